#!/usr/bin/env python3
"""Writes skia.jsonl and skia_optest.jsonl: operands of Skia's PathOps tests
(tests/PathOpsOpTest.cpp, google/skia), transcribed as data: a first set here, the rest of
the file's transcribable tests in skia_optest.tsv. Each operand is path data in a small
notation: M/L/Q/C/Z with numbers that are float32 (SkScalar; `h` + 8 hex digits is
SkBits2Float of those bits), R x0 y0 x1 y1 for addRect (clockwise in Skia's y-down sense, as
addRect's default kCW draws it; `r` for kCCW), and the fill type (w winding -> nonzero, e
even-odd). Coordinates are y-down in Skia; the regions are the same point sets. Inverse fill
types and conics have no counterpart here and are left out."""
import json
import re
import os
import struct


def f32(v):
    return struct.unpack("<f", struct.pack("<f", float(v)))[0]


def num(tok):
    if tok.startswith("h"):
        return struct.unpack(">f", bytes.fromhex(tok[1:]))[0]
    return f32(tok)


def svg(src):
    out = []
    toks = re.findall(r"h[0-9a-fA-F]{8}|[MLQCZRr]|[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?", src)
    i = 0
    while i < len(toks):
        t = toks[i]
        if t in ("R", "r"):
            x0, y0, x1, y1 = (num(v) for v in toks[i + 1:i + 5])
            if t == "R":  # kCW in y-down: (x0,y0) (x1,y0) (x1,y1) (x0,y1)
                pts = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
            else:
                pts = [(x0, y0), (x0, y1), (x1, y1), (x1, y0)]
            out.append("M%r %r L%r %r L%r %r L%r %r Z" % tuple(v for p in pts for v in p))
            i += 5
        elif t in "MLQC":
            k = {"M": 2, "L": 2, "Q": 4, "C": 6}[t]
            out.append(t + " ".join(repr(num(v)) for v in toks[i + 1:i + 1 + k]))
            i += 1 + k
        elif t == "Z":
            out.append("Z")
            i += 1
        else:
            raise ValueError(t)
    return " ".join(out)


RULE = {"w": "nonzero", "e": "evenodd"}
CASES = [
    # name, fill a, path a, fill b, path b (b "" for a simplify test of a alone)
    ("xOp3i", "w", "M1 4 C0 5 4 1 3 1 Z", "w", "M1 4 C1 3 4 1 5 0 Z"),
    ("findFirst1", "w", "M0 1 C1 6 5 0 2 1 Z", "w", "M0 5 C1 2 1 0 6 1 Z"),
    ("cubicOp112", "w", "M2 4 C2 3 6 4 1 0 Z", "w", "M4 6 C0 1 4 2 3 2 Z"),
    ("cubicOp113", "w", "M2 4 C3 5 2.33333325 4.33333349 3.83333325 3.83333349 Z", "w", "M3 5 C2.33333325 4.33333349 3.83333325 3.83333349 2 4 Z"),
    ("cubicOp114", "w", "M0 1 C1 3 -1 2 3.5 1.33333337 Z", "w", "M1 3 C-1 2 3.5 1.33333337 0 1 Z"),
    ("quadOp10i", "w", "M0 0 Q1 8 3 5 L8 1 Z", "w", "M0 0 Q8 1 4 8 Z"),
    ("kari1", "w", "M39.9375 -5.8359375 L40.625 -5.7890625 L37.7109375 1.3515625 L37.203125 0.9609375 Z", "w",
     "M37.52734375 -1.44140625 C37.8736991882324 -1.69921875 38.1640625 -2.140625 38.3984375 -2.765625 L38.640625 -2.609375 "
     "C38.53125 -1.89583337306976 38.0664443969727 -0.154893040657043 38.0664443969727 -0.154893040657043 "
     "C38.0664443969727 -0.154893040657043 37.1809883117676 -1.18359375 37.52734375 -1.44140625 Z"),
    ("issue2504", "w", "M34.2421875 -5.976562976837158203125 L35.453121185302734375 0 L31.9375 0 Z", "w",
     "M36.71843719482421875 0.8886508941650390625 C36.71843719482421875 0.8886508941650390625 35.123386383056640625 0.554015457630157470703125 34.511409759521484375 -0.1152553558349609375 "
     "C33.899425506591796875 -0.7845261096954345703125 34.53484344482421875 -5.6777553558349609375 34.53484344482421875 -5.6777553558349609375 Z"),
    ("issue2540", "w",
     "M26.5054988861083984375 85.73960113525390625 C84.19739532470703125 17.77140045166015625 16.93920135498046875 101.86199951171875 12.631000518798828125 105.24700164794921875 "
     "C11.08199977874755859375 106.46399688720703125 11.52600002288818359375 104.464996337890625 11.52600002288818359375 104.464996337890625 "
     "L23.1654987335205078125 89.72879791259765625 C23.1654987335205078125 89.72879791259765625 -10.1713008880615234375 119.9160003662109375 -17.1620006561279296875 120.8249969482421875 "
     "C-19.1149997711181640625 121.07900238037109375 -18.0380001068115234375 119.79299163818359375 -18.0380001068115234375 119.79299163818359375 "
     "C-18.0380001068115234375 119.79299163818359375 14.22100067138671875 90.60700225830078125 26.5054988861083984375 85.73960113525390625 Z", "w",
     "M-25.077999114990234375 124.9120025634765625 C-25.077999114990234375 124.9120025634765625 -25.9509983062744140625 125.95400238037109375 -24.368999481201171875 125.7480010986328125 "
     "C-16.06999969482421875 124.66899871826171875 1.26800000667572021484375 91.23999786376953125 37.264003753662109375 95.35400390625 "
     "C37.264003753662109375 95.35400390625 11.3710002899169921875 83.7339935302734375 -25.077999114990234375 124.9120025634765625 Z"),
    ("rects1", "e", "M0 0 L1 0 L1 1 L0 1 Z M0 0 L6 0 L6 6 L0 6 Z", "e", "M0 0 L1 0 L1 1 L0 1 Z M0 0 L2 0 L2 2 L0 2 Z"),
    ("rects2", "e", "M0 0 L4 0 L4 4 L0 4 Z M3 3 L4 3 L4 4 L3 4 Z", "w", "M3 3 L6 3 L6 6 L3 6 Z M3 3 L4 3 L4 4 L3 4 Z"),
    ("rects3", "e", "R 0 0 1 1 R 0 0 4 4", "w", "R 0 0 2 2 R 0 0 2 2"),
    ("rects4", "e", "R 0 0 1 1 R 0 0 2 2", "w", "R 0 0 2 2 R 0 0 3 3"),
    ("issue2753", "w", "M142.701 110.568 L142.957 100 L153.835 100 L154.592 108.188 C154.592 108.188 153.173 108.483 152.83 109.412 C152.83 109.412 142.701 110.568 142.701 110.568 Z", "w",
     "M39 124.001 C39 124.001 50.6 117.001 50.6 117.001 C50.6 117.001 164.601 85.2 188.201 117.601 C188.201 117.601 174.801 93 39 124.001 Z"),
    ("issue2808", "w",
     "M509.20300293 385.601989746 Q509.20300293 415.68838501 487.928710938 436.96270752 Q466.654388428 458.236999512 436.567993164 458.236999512 "
     "Q406.4815979 458.236999512 385.207275391 436.96270752 Q363.932983398 415.68838501 363.932983398 385.601989746 "
     "Q363.932983398 355.515594482 385.207275391 334.241271973 Q406.4815979 312.96697998 436.567993164 312.96697998 "
     "Q466.654388428 312.96697998 487.928710938 334.241271973 Q509.20300293 355.515594482 509.20300293 385.601989746 Z", "w",
     "M449.033996582 290.87298584 Q449.033996582 301.028259277 441.853149414 308.209106445 Q434.672271729 315.389984131 424.516998291 315.389984131 "
     "Q414.361724854 315.389984131 407.180847168 308.209106445 Q400 301.028259277 400 290.87298584 Q400 280.717712402 407.180847168 273.536865234 "
     "Q414.361724854 266.355987549 424.516998291 266.355987549 Q434.672271729 266.355987549 441.853149414 273.536865234 Q449.033996582 280.717712402 449.033996582 290.87298584 Z"),
    ("cubicOp115", "w", "M0 1 C3 4 2 1 5 3 Z", "w", "M1 2 C3 5 1 0 4 3 Z"),
    ("testRect1", "w", "r 0 0 60 60 r 30 20 50 50 r 24 20 36 30", "w", ""),
    ("testRect2", "w", "R 0 0 1 1 R 4 4 5 5", "e", "R 0 0 2 2 R 0 0 6 6"),
    ("cubicOp116", "w", "M0 1 C4 6 2 0 2 0 Z", "w", "M0 2 C0 2 1 0 6 4 Z"),
    ("cubicOp117", "w", "M0 1 C4 5 6 0 1 0 Z", "w", "M0 6 C0 1 1 0 5 4 Z"),
    ("cubicOp118", "w", "M0 1 C4 6 5 1 6 2 Z", "w", "M1 5 C2 6 1 0 6 4 Z"),
    ("loop1", "w", "M0 1 C1 5 -5.66666651 3.33333349 8.83333302 2.33333349 Z", "w", "M1 5 C-5.66666651 3.33333349 8.83333302 2.33333349 0 1 Z"),
    # tests/PathOpsOpTest.cpp, first cases
    ("cubicOp1d", "w", "M0 1 C0 2 1 0 1 0 Z", "w", "M0 1 C0 1 1 0 2 0 Z"),
    ("cubicOp2d", "w", "M0 2 C0 1 1 0 1 0 Z", "w", "M0 1 C0 1 2 0 1 0 Z"),
    ("cubicOp3d", "w", "M0 1 C2 3 1 0 1 0 Z", "w", "M0 1 C0 1 1 0 3 2 Z"),
    ("cubicOp5d", "w", "M0 1 C0 2 1 0 2 0 Z", "w", "M0 1 C0 2 1 0 2 0 Z"),
    ("cubicOp6d", "w", "M0 1 C0 6 1 0 3 0 Z", "w", "M0 1 C0 3 1 0 6 0 Z"),
    ("cubicOp7d", "w", "M0 1 C3 4 1 0 3 0 Z", "w", "M0 1 C0 3 1 0 4 3 Z"),
    ("cubicOp8d", "w", "M0 1 C0 5 1 0 4 0 Z", "w", "M0 1 C0 4 1 0 5 0 Z"),
    ("cubicOp9d", "w", "M0 1 C1 6 1 0 2 1 Z", "w", "M0 1 C1 2 1 0 6 1 Z"),
    ("quadOp9d", "w", "M0 1 Q1 6 1.5 1 Q1.5 0.5 2 1 Z", "w", "M0 1 Q1 2 1.4 1 Q3 0.4 6 1 Z"),
    ("lineOp9d", "w", "M0 1 L1 6 L1.5 1 L1.8 0.8 L2 1 Z", "w", "M0 1 L1 2 L1.4 1 L3 0.4 L6 1 Z"),
    ("cubicOp1i", "w", "M0 1 C1 2 1 0 2 1 Z", "w", "M0 1 C1 2 1 0 2 1 Z"),
    ("cubicOp10d", "w", "M0 1 C1 3 1 0 4 1 Z", "w", "M0 1 C1 4 1 0 3 1 Z"),
    ("cubicOp11d", "w", "M0 1 C3 4 1 0 5 1 Z", "w", "M0 1 C1 5 1 0 4 3 Z"),
    ("cubicOp12d", "w", "M0 1 C1 6 1 0 1 0 Z", "w", "M0 1 C0 1 1 0 6 1 Z"),
    ("cubicOp13d", "w", "M0 1 C4 5 1 0 5 3 Z", "w", "M0 1 C3 5 1 0 5 4 Z"),
    ("cubicOp14d", "w", "M0 1 C0 2 2 0 2 1 Z", "w", "M0 2 C1 2 1 0 2 0 Z"),
    ("cubicOp15d", "w", "M0 1 C3 6 2 0 2 1 Z", "w", "M0 2 C1 2 1 0 6 3 Z"),
    ("cubicOp16d", "w", "M0 2 C0 1 3 0 1 0 Z", "w", "M0 3 C0 1 2 0 1 0 Z"),
    ("cubicOp17d", "w", "M0 2 C0 2 4 0 2 1 Z", "w", "M0 4 C1 2 2 0 2 0 Z"),
    ("cubicOp18d", "w", "M0 1 C3 5 2 0 2 1 Z", "w", "M0 2 C1 2 1 0 5 3 Z"),
    ("cubicOp19i", "w", "M0 2 C0 1 2 1 6 2 Z", "w", "M1 2 C2 6 2 0 1 0 Z"),
    ("cubicOp20d", "w", "M0 1 C0 1 6 0 2 1 Z", "w", "M0 6 C1 2 1 0 1 0 Z"),
    ("cubicOp21d", "w", "M0 1 C0 1 2 1 6 5 Z", "w", "M1 2 C5 6 1 0 1 0 Z"),
    ("cubicOp22d", "w", "M0 1 C2 3 3 0 2 1 Z", "w", "M0 3 C1 2 1 0 3 2 Z"),
    ("cubicOp23d", "w", "M0 1 C1 2 4 0 2 1 Z", "w", "M0 4 C1 2 1 0 2 1 Z"),
    ("cubicOp24d", "w", "M0 1 C1 2 2 0 3 2 Z", "w", "M0 2 C2 3 1 0 2 1 Z"),
    ("testIntersect1", "w", "R 0 0 6 6", "w", "R 3 3 9 9"),
    ("testIntersect2", "w", "R 0 0 6 6", "w", "R 0 3 9 9"),
    ("testOp1d", "w", "R 0 0 1 1 R 0 0 2 2", "w", "R 0 0 1 1 R 0 0 1 1"),
    ("testOp2d", "w", "R 0 0 1 1 R 0 0 2 2", "e", "R 0 0 1 1 R 0 0 1 1"),
    ("testOp3d", "w", "R 0 0 1 1 R 1 1 2 2", "w", "R 0 0 1 1 R 0 0 1 1"),
    ("testOp1u", "w", "R 0 0 1 1 R 0 0 3 3", "w", "R 0 0 1 1 R 0 0 1 1"),
    ("xOp2i", "e", "M1 5 C0 4 3 2 6 1 Z", "e", "M2 3 C1 6 5 1 4 0 Z"),
]

LOOPS = [
    ('loops34i', '3 4', '0 4', '2.5 4', '3 9'),
    ('loops35i', '3 4', '0 4', '2.5 4', '3 10'),
    ('loops36i', '3 4', '1 4', '2.66666675 4', '3 8'),
    ('loops37i', '2 4', '1 4', '1.83333337 4', '2 5.33333349'),
    ('loops38i', '3 4', '2 4', '2.83333325 4', '3 6'),
    ('loops39i', '3 5', '0 5', '2.5 5', '3 10'),
    ('loops40i', '3 5', '0 5', '2.5 5', '3 11'),
    ('loops44i', '1 5', '0 1', '7.33333302 5.33333349', '-7 7'),
    ('loops45i', '1 6', '0 2', '7.33333302 6.33333302', '-7 8'),
    ('loops46i', '2 6', '1 2', '8.33333302 6.33333302', '-6 8'),
    ('loops47i', '2 4', '0 1', '6 5.83333302', '-4 8'),
    ('loops48i', '2 6', '0 1', '9.33333302 6.83333302', '-8.33333302 9.16666603'),
    ('loops49i', '0 2', '1 4', '-0.166666687 2.66666675', '1.66666675 2'),
    ('loops50i', '0 3', '1 5', '-0.166666687 3.66666675', '1.66666675 3'),
    ('loops51i', '1 2', '2 4', '0.833333313 2.66666675', '2.66666675 2'),
    ('loops52i', '1 3', '2 5', '0.833333313 3.66666675', '2.66666675 3'),
    ('loops53i', '2 3', '3 5', '1.83333325 3.66666675', '3.66666651 3'),
    ('loops54i', '0 2', '1 4', '0 3', '1.66666675 2'),
    ('loops55i', '0 3', '1 5', '0 4', '1.66666675 3'),
    ('loops56i', '1 2', '2 4', '0.99999994 3', '2.66666675 2'),
    ('loops57i', '1 3', '2 5', '0.99999994 4', '2.66666675 3'),
    ('loops58i', '2 3', '3 5', '2 4', '3.66666651 3'),
    ('loops59i', '0 6', '1 2', '7.33333302 1.66666663', '-7.5 2'),
    ('loops61i', '0 1', '1 5', '-6.33333302 0.666666627', '8 -1'),
    ('loops62i', '0 2', '1 6', '-6.33333302 1.66666663', '8 0'),
    ('loops63i', '0 1', '2 4', '-4 -0.833333254', '6 -3'),
    ('loops33i', '2 6', '1 2', '7.16666698 6.66666698', '-4.66666651 7.66666651'),
]
# loopsNNi: path M p0 C p1 p2 p3 Z and pathB M p1 C p2 p3 p0 Z, winding fills.
CASES += [(n, "w", f"M{p0} C{p1} {p2} {p3} Z", "w", f"M{p1} C{p2} {p3} {p0} Z") for n, p0, p1, p2, p3 in LOOPS]
CASES += [
    ("cubics41d", "w", "M0 1 C1 4 3 0 3 1 Z", "w", "M0 3 C1 3 1 0 4 1 Z"),
    ("cubics44d", "w", "M3 4 C2 5 3 1 6 2 Z", "w", "M1 3 C2 6 4 3 5 2 Z"),
    ("cubics45u", "w", "M1 3 C2 6 4 3 5 2 Z", "w", "M3 4 C2 5 3 1 6 2 Z"),
    ("fuzz763_1c", "w", "M0 0 C h1931204a h2ba1a14a h4a4a08ff h4a4a08ff h4a4a4a34 h4a4a4a4a "
     "M h000010a1 h19312000 C h4a4a4a4a h4a4a4a4a ha14a4a4a h08ff2ba1 h08ff4a4a h4a344a4a "
     "C h4a4a4a4a h4a4a4a4a h2ba1a14a h4e4a08ff h4a4a4a4a ha1a181ff", "w", ""),
]

cases = []
for name, fa, pa, fb, pb in CASES:
    c = {"name": "skia-" + name, "a": {"path": svg(pa), "fill_rule": RULE[fa]}}
    if pb:
        c["b"] = {"path": svg(pb), "fill_rule": RULE[fb]}
    cases.append(c)
here = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(here, "skia.jsonl"), "w") as f:
    for c in cases:
        f.write(json.dumps(c) + "\n")
print(len(cases), "cases")

# The rest of PathOpsOpTest.cpp (skia_optest.tsv, its header says what it holds) to
# skia_optest.jsonl: the tests not in CASES, each operand as above (an empty first path is an
# empty operand, an empty second one is left out). Operands with infinite or NaN coordinates
# (SkBits2Float of such bits) are left out: SVG path data has no such numbers, and the
# service refuses them at the parser.
known = {name for name, *_ in CASES}
more = []
with open(os.path.join(here, "skia_optest.tsv")) as f:
    for line in f:
        if line.startswith("#") or not line.strip():
            continue
        name, fa, pa, fb, pb, _op = line.rstrip("\n").split("\t")
        if name in known:
            continue
        a, b = svg(pa), svg(pb)
        if any(w in a + " " + b for w in ("inf", "nan")):
            continue
        c = {"name": "skia-" + name, "a": {"path": a, "fill_rule": RULE[fa]}}
        if b:
            c["b"] = {"path": b, "fill_rule": RULE[fb]}
        more.append(c)
with open(os.path.join(here, "skia_optest.jsonl"), "w") as f:
    for c in more:
        f.write(json.dumps(c) + "\n")
print(len(more), "more cases")
