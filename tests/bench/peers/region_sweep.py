#!/usr/bin/env python3
"""Checks /boolean and /contains of a running bezier-service on region cases, independently.

Cases: JSON lines files (tests/bench/peers/region_cases/*.jsonl), one case a line:
  {"name": ..., "a": {"path": SVG path data, "fill_rule": "nonzero"|"evenodd"}, "b": {...}}
("b" may be absent: only simplify of a is checked). The geometry comes from other libraries'
public test suites (Paper.js, Skia PathOps, lib2geom, flo_curves), transcribed as data by the
make_*.py scripts beside them, and hand-made adversarial cases; plus generated cases
(--generate N: random small-integer shapes, or --family cubics | loops | quads, the families
Skia's threaded PathOps tests enumerate, sampled, or --family coincident, shapes with moved,
mirrored, turned or reversed copies of themselves). --transform s,tx,ty sends every operand as
a `curves` operand moved by x -> s x + t (scale and translation invariance).

For every case and op (union, intersection, difference a-b and b-a, xor, simplify of each
operand) it checks, without using the service's winding code:
  membership  at random points and points placed around every vertex and segment of the
              operands and of the result (only those farther than MARGIN x scale from both
              operands' boundaries; scale here is the operands' size, and the margin is never
              below 4e-9 of the largest coordinate), the result's winding, by ray casting on a
              flattening of the result's segments within FLAT x scale (control polygon within the chord's
              tolerance), is 1 where op(in a, in b) holds and 0 elsewhere; in a / in b from
              the same ray casting on the operands with their fill rules;
  clean       contours closed with exact joins, no zero-length segment, each contour's
              orientation matching the sign of its area (own Gauss-Legendre Green's
              integral), nonzero area;
  status      200 (no 500, no 422 work-cap on these small inputs);
  identities  area(a u b) + area(a n b) = area(a) + area(b), xor = union - intersection,
              a - b = union - area(b), with the simplified operands' areas;
  /contains   the exact winding at the sample points equals the ray-cast winding.
The operands' segments are read with /segments (the path-data parser is not under test).

  python3 tests/bench/peers/region_sweep.py --port 18200 tests/bench/peers/region_cases/*.jsonl
  python3 tests/bench/peers/region_sweep.py --port 18200 --generate 2000
  python3 tests/bench/peers/region_sweep.py --port 18200 --family cubics --generate 2000
  python3 tests/bench/peers/region_sweep.py --port 18200 --transform 9.5367431640625e-07,3,-5 FILES...
A case that fails prints its operands and the first failures of each op; the last line counts
cases, operations and failed cases (exit status 1 when any failed).
"""

import argparse
import http.client
import json
import math
import random
import signal
import sys

FLAT = 2e-7     # flattening tolerance, fraction of scale
MARGIN = 2e-6   # sample points farther than this (fraction of scale) from operand boundaries
OPS = ["union", "intersection", "difference", "rdifference", "xor", "simplify_a", "simplify_b"]


class Service:
    def __init__(self, port):
        self.port = port
        self.conn = http.client.HTTPConnection("127.0.0.1", port, timeout=120)

    def post(self, route, body):
        data = json.dumps(body)
        for attempt in range(2):
            try:
                self.conn.request("POST", route, data, {"Content-Type": "application/json"})
                r = self.conn.getresponse()
                return r.status, json.loads(r.read() or b"null")
            except (http.client.HTTPException, ConnectionError, OSError):
                self.conn.close()
                self.conn = http.client.HTTPConnection("127.0.0.1", self.port, timeout=120)
                if attempt:
                    return 0, None
        return 0, None


# ---------- geometry of Bezier segments (control point lists) ----------

def split(ctrl, t=0.5):
    left, right, pts = [ctrl[0]], [ctrl[-1]], ctrl
    while len(pts) > 1:
        pts = [((1 - t) * p[0] + t * q[0], (1 - t) * p[1] + t * q[1]) for p, q in zip(pts, pts[1:])]
        left.append(pts[0])
        right.append(pts[-1])
    return left, right[::-1]


def seg_dist(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    wx, wy = p[0] - a[0], p[1] - a[1]
    l2 = dx * dx + dy * dy
    t = 0.0 if l2 == 0 else max(0.0, min(1.0, (wx * dx + wy * dy) / l2))
    return math.hypot(wx - t * dx, wy - t * dy)


def flatten(ctrl, tol, out, depth=0):
    """Appends points after ctrl[0] of a polyline within tol of the curve (hull property)."""
    if len(ctrl) == 2 or depth > 40 or all(seg_dist(q, ctrl[0], ctrl[-1]) <= tol for q in ctrl[1:-1]):
        out.append(ctrl[-1])
        return
    l, r = split(ctrl)
    flatten(l, tol, out, depth + 1)
    flatten(r, tol, out, depth + 1)


def evaluate(ctrl, t):
    pts = ctrl
    while len(pts) > 1:
        pts = [((1 - t) * p[0] + t * q[0], (1 - t) * p[1] + t * q[1]) for p, q in zip(pts, pts[1:])]
    return pts[0]


def derivative(ctrl, t):
    n = len(ctrl) - 1
    d = [(n * (q[0] - p[0]), n * (q[1] - p[1])) for p, q in zip(ctrl, ctrl[1:])]
    return evaluate(d, t)


GL_X = [-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
        0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363]
GL_W = [0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
        0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763]


def green_area(ctrl, origin=(0.0, 0.0)):
    """(1/2) integral of x dy - y dx over the curve, x and y measured from `origin` (the sum
    over a closed contour does not depend on it; the contour's own first point keeps the
    products small where the coordinates are large); exact for degree <= 8 (8-point rule)."""
    local = [(q[0] - origin[0], q[1] - origin[1]) for q in ctrl]
    s = 0.0
    for x, w in zip(GL_X, GL_W):
        t = 0.5 * (x + 1)
        p, d = evaluate(local, t), derivative(local, t)
        s += w * 0.5 * (p[0] * d[1] - p[1] * d[0])
    return 0.5 * s


class Polygon:
    """Closed polylines with a grid index for ray casting and distance queries."""

    def __init__(self, loops, box, cells=64):
        self.edges = []
        for loop in loops:
            for i in range(len(loop)):
                # Zero-length edges too: a boundary that is a single point still has a distance.
                self.edges.append((loop[i], loop[(i + 1) % len(loop)]))
        self.x0, self.y0, x1, y1 = box
        self.n = cells
        self.cw = max(x1 - self.x0, 1e-300) / cells
        self.ch = max(y1 - self.y0, 1e-300) / cells
        self.rows = [[] for _ in range(cells)]   # edges by y row (ray casting to +x)
        self.grid = {}                          # edges by cell (distance)
        for e in self.edges:
            (ax, ay), (bx, by) = e
            r0, r1 = self._row(min(ay, by)), self._row(max(ay, by))
            for r in range(r0, r1 + 1):
                self.rows[r].append(e)
            c0, c1 = self._col(min(ax, bx)), self._col(max(ax, bx))
            for r in range(r0, r1 + 1):
                for c in range(c0, c1 + 1):
                    self.grid.setdefault((r, c), []).append(e)

    def _row(self, y):
        return min(self.n - 1, max(0, int((y - self.y0) / self.ch)))

    def _col(self, x):
        return min(self.n - 1, max(0, int((x - self.x0) / self.cw)))

    def winding(self, p):
        x, y = p
        w = 0
        for (ax, ay), (bx, by) in self.rows[self._row(y)]:
            if (ay <= y) != (by <= y):
                xi = ax + (y - ay) * (bx - ax) / (by - ay)
                if xi > x:
                    w += 1 if by > ay else -1
        return w

    def near(self, p, d):
        """True when p is within d of an edge."""
        r, c = self._row(p[1]), self._col(p[0])
        kr, kc = 1 + int(d / self.ch), 1 + int(d / self.cw)
        if kr * kc > 16:
            return any(seg_dist(p, a, b) <= d for a, b in self.edges)
        for dr in range(-kr, kr + 1):
            for dc in range(-kc, kc + 1):
                for a, b in self.grid.get((r + dr, c + dc), ()):
                    if seg_dist(p, a, b) <= d:
                        return True
        return False


def filled(w, rule):
    return w != 0 if rule == "nonzero" else (w % 2) != 0


def op_value(op, ia, ib):
    return {"union": ia or ib, "intersection": ia and ib, "difference": ia and not ib,
            "rdifference": ib and not ia, "xor": ia != ib, "simplify_a": ia, "simplify_b": ib}[op]


def operand_loops(segments_answer, tol):
    """Closed polylines of an operand from /segments (open subpaths closed by a line)."""
    loops = []
    segs = segments_answer["segments"]
    ctrls = []
    for sp in segments_answer["subpaths"]:
        loop = []
        first = sp["first_segment"]
        for k in range(first, first + sp["segment_count"]):
            ctrl = [tuple(p) for p in segs[k]["points"]]
            ctrls.append(ctrl)
            if not loop:
                loop.append(ctrl[0])
            flatten(ctrl, tol, loop)
        if loop:
            if loop[-1] != loop[0]:
                ctrls.append([loop[-1], loop[0]])
            loops.append(loop)
    return loops, ctrls


def check_case(svc, case, rng, nrandom, report, transform=None):
    """Returns the list of failure strings of one case."""
    fails = []
    ops_checked = 0
    names = ["a"] + (["b"] if "b" in case else [])
    seg = {}
    for k in names:
        st, ans = svc.post("/segments", {"path": case[k]["path"]})
        if st != 200:
            return [f"/segments {k} status {st} {ans}"], 0
        seg[k] = ans
    if transform is not None:
        # The operands moved: x -> s x + t (each coordinate), sent as curves operands (the
        # chains of the subpaths, an open one closed by its line).
        sc, tx, ty = transform
        case = dict(case)
        for k in names:
            curves, subpaths = [], []
            for sp in seg[k]["subpaths"]:
                first = sp["first_segment"]
                chain = [[[sc * x + tx, sc * y + ty] for x, y in seg[k]["segments"][j]["points"]]
                         for j in range(first, first + sp["segment_count"])]
                if chain and chain[-1][-1] != chain[0][0]:
                    chain.append([chain[-1][-1], chain[0][0]])
                subpaths.append({"first_segment": len(curves), "segment_count": len(chain)})
                curves += chain
            seg[k] = {"segments": [{"points": c} for c in curves], "subpaths": subpaths}
            case[k] = {"curves": curves, "fill_rule": case[k].get("fill_rule", "nonzero")}
    pts_all = [tuple(p) for k in names for s in seg[k]["segments"] for p in s["points"]]
    if not pts_all:
        return [], 0
    xs, ys = [p[0] for p in pts_all], [p[1] for p in pts_all]
    scale = max(max(abs(v) for v in xs), max(abs(v) for v in ys), 1e-300)
    # The largest coordinate of one operand: the scale of its simplify (whose result the other
    # operand's coordinates do not bound).
    operand_scale = {k: max([abs(v) for s in seg[k]["segments"] for p in s["points"] for v in p]
                            + [1e-300]) for k in names}
    size = max(max(xs) - min(xs), max(ys) - min(ys), 1e-12 * scale)
    pad = 0.05 * size
    box = (min(xs) - pad, min(ys) - pad, max(xs) + pad, max(ys) + pad)
    # Distances relative to the operands' size (the flattening's cost follows it), and never
    # below the contract's margin, 1e-9 of the largest coordinate.
    tol = FLAT * size
    margin = max(MARGIN * size, 4e-9 * scale)
    poly, ctrls, rule = {}, {}, {}
    for k in names:
        loops, ctrls[k] = operand_loops(seg[k], tol)
        poly[k] = Polygon(loops, box)
        rule[k] = case[k].get("fill_rule", "nonzero")

    # Sample points: random in the box, and around the operands' control/end points and
    # segment samples at several distances.
    samples = [(rng.uniform(box[0], box[2]), rng.uniform(box[1], box[3])) for _ in range(nrandom)]

    def around(p, out, count):
        for r in (3 * margin, 1e-4 * size, 3e-3 * size, 3e-2 * size):
            for _ in range(count):
                a = rng.uniform(0, 2 * math.pi)
                out.append((p[0] + r * math.cos(a), p[1] + r * math.sin(a)))

    for k in names:
        for c in ctrls[k]:
            around(c[0], samples, 2)
            around(evaluate(c, rng.random()), samples, 1)

    clear_cache = {}

    def clear(p):
        v = clear_cache.get(p)
        if v is None:
            v = clear_cache[p] = all(not poly[k].near(p, margin) for k in names)
        return v

    # Results of every op.
    results = {}
    for op in OPS:
        if op in ("simplify_b",) and "b" not in case:
            continue
        if op not in ("simplify_a", "simplify_b") and "b" not in case:
            continue
        if op == "simplify_a":
            body = {"op": "simplify", "a": case["a"]}
        elif op == "simplify_b":
            body = {"op": "simplify", "a": case["b"]}
        elif op == "rdifference":
            body = {"op": "difference", "a": case["b"], "b": case["a"]}
        else:
            body = {"op": op, "a": case["a"], "b": case["b"]}
        st, ans = svc.post("/boolean", body)
        ops_checked += 1
        if st != 200:
            fails.append(f"{op}: status {st} {json.dumps(ans)[:200]}")
            continue
        results[op] = ans
        # Clean contours.
        rsegs = ans["segments"]
        op_scale = operand_scale[op[-1]] if op.startswith("simplify") else scale
        loops = []
        total = 0.0
        for ci, c in enumerate(ans["contours"]):
            first, end = c["segments"]
            loop = []
            area = 0.0
            for j in range(first, end):
                ctrl = [tuple(p) for p in rsegs[j]["points"]]
                nxt = [tuple(p) for p in rsegs[first if j + 1 == end else j + 1]["points"]]
                if ctrl[-1] != nxt[0]:
                    fails.append(f"{op}: contour {ci} segment {j} does not meet the next exactly")
                if all(q == ctrl[0] for q in ctrl):
                    fails.append(f"{op}: contour {ci} segment {j} has zero length")
                if not loop:
                    loop.append(ctrl[0])
                flatten(ctrl, tol, loop)
                area += green_area(ctrl, loop[0])
            loops.append(loop[:-1] if len(loop) > 1 and loop[-1] == loop[0] else loop)
            if abs(area) <= 2.0 ** -80 * op_scale * op_scale or c["area"] == 0:
                fails.append(f"{op}: contour {ci} has zero area ({area!r})")
            if (area > 0) != (c["orientation"] == "ccw"):
                fails.append(f"{op}: contour {ci} orientation {c['orientation']} with area {area:.6g}")
            total += area
        if abs(total - ans["area"]) > 1e-9 * abs(total) + 1e-12 * op_scale * op_scale:
            fails.append(f"{op}: area {ans['area']} but contours enclose {total}")
        rpoly = Polygon(loops, box)
        bad = 0
        first_bad = None
        rs = list(samples)
        for c in rsegs:
            around(tuple(c["points"][0]), rs, 1)
        for p in rs:
            if not clear(p) or rpoly.near(p, 4 * tol):
                continue
            ia = filled(poly["a"].winding(p), rule["a"])
            ib = filled(poly["b"].winding(p), rule["b"]) if "b" in poly else False
            want = 1 if op_value(op, ia, ib) else 0
            got = rpoly.winding(p)
            if got != want:
                bad += 1
                if first_bad is None:
                    first_bad = (p, got, want, ia, ib)
        if bad:
            p, got, want, ia, ib = first_bad
            fails.append(f"{op}: {bad} points wrong, e.g. ({p[0]!r}, {p[1]!r}) winding {got} "
                         f"want {want} (in a {ia}, in b {ib})")

    # Area identities.
    if "b" in case and all(o in results for o in OPS):
        ar = {o: results[o]["area"] for o in OPS}
        eps = 1e-9 * (ar["simplify_a"] + ar["simplify_b"]) + 1e-12 * scale * scale
        checks = [("u+i=a+b", ar["union"] + ar["intersection"], ar["simplify_a"] + ar["simplify_b"]),
                  ("xor=u-i", ar["xor"], ar["union"] - ar["intersection"]),
                  ("a-b=u-b", ar["difference"], ar["union"] - ar["simplify_b"]),
                  ("b-a=u-a", ar["rdifference"], ar["union"] - ar["simplify_a"])]
        for name, x, y in checks:
            if abs(x - y) > eps:
                fails.append(f"identity {name}: {x!r} vs {y!r}")

    # /contains against the ray-cast windings.
    for k in names:
        targets = [p for p in samples[:nrandom] + samples[nrandom::7] if clear(p)][:400]
        if not targets:
            continue
        body = {kk: v for kk, v in case[k].items() if kk != "fill_rule"}
        body.update({"fill_rule": rule[k], "targets": [list(p) for p in targets]})
        st, ans = svc.post("/contains", body)
        if st != 200:
            fails.append(f"/contains {k}: status {st}")
            continue
        wrong = [(p, r["winding"], poly[k].winding(p)) for p, r in zip(targets, ans["results"])
                 if r["boundary"] or r["winding"] != poly[k].winding(p)]
        if wrong:
            p, got, want = wrong[0]
            fails.append(f"/contains {k}: {len(wrong)} wrong, e.g. {p} winding {got} want {want}")
    return fails, ops_checked


# ---------- generated families (small integer coordinates, as Skia's threaded op tests) ----------

def generated_cases(count, seed):
    rng = random.Random(seed)
    out = []
    for i in range(count):
        kind = i % 4

        def contour():
            n = rng.choice([1, 2, 3]) if kind else 1
            x0, y0 = rng.randint(0, 6), rng.randint(0, 6)
            d = f"M{x0} {y0}"
            for _ in range(n):
                t = rng.choice("LQC") if kind == 3 else "LQC"[kind % 3]
                k = {"L": 1, "Q": 2, "C": 3}[t]
                d += " " + t + " ".join(f"{rng.randint(0, 6)} {rng.randint(0, 6)}" for _ in range(k))
            return d + " Z"

        a = " ".join(contour() for _ in range(rng.choice([1, 1, 2])))
        b = " ".join(contour() for _ in range(rng.choice([1, 1, 2])))
        out.append({"name": f"gen{seed}-{i}",
                    "a": {"path": a, "fill_rule": rng.choice(["nonzero", "evenodd"])},
                    "b": {"path": b, "fill_rule": rng.choice(["nonzero", "evenodd"])}})
    return out


def family_cases(family, count, seed):
    """Random members of the small-integer families Skia's threaded PathOps tests enumerate
    (PathOpsOpCubicThreadedTest, PathOpsOpLoopThreadedTest, PathOpsSimplifyQuadThreadedTest):
    the same construction of the operands from integer indices, sampled instead of
    enumerated, each with its fill rules."""
    rng = random.Random(seed)
    rules = ["nonzero", "evenodd"]
    out = []

    def pair():
        a = rng.randrange(0, 6)
        return a, rng.randrange(a + 1, 7)

    def num(v):
        return repr(float(v))

    for i in range(count):
        name = f"{family}{seed}-{i}"
        if family == "cubics":
            (A, B), (C, D), (a, b), (c, d) = pair(), pair(), pair(), pair()
            pa = f"M{A} {B} C{C} {D} {b} {a} {d} {c} Z"
            pb = f"M{a} {b} C{c} {d} {B} {A} {D} {C} Z"
            out.append({"name": name, "a": {"path": pa, "fill_rule": rng.choice(rules)},
                        "b": {"path": pb, "fill_rule": rng.choice(rules)}})
        elif family == "loops":
            (A, B), (C, D), (a, b), (c, d) = pair(), pair(), pair(), pair()
            vx, vy = a - c, b - d
            mid_a = ((a * A + c * (6 - A)) / 6, (b * A + d * (6 - A)) / 6)
            mid_b = ((a * B + c * (6 - B)) / 6, (b * B + d * (6 - B)) / 6)
            end_c = (mid_a[0] + vy * C / 3, mid_a[1] + vx * C / 3)
            end_d = (mid_b[0] - vy * D / 3, mid_b[1] + vx * D / 3)
            pa = f"M{a} {b} C{c} {d} {num(end_c[0])} {num(end_c[1])} {num(end_d[0])} {num(end_d[1])} Z"
            pb = f"M{c} {d} C{num(end_c[0])} {num(end_c[1])} {num(end_d[0])} {num(end_d[1])} {a} {b} Z"
            out.append({"name": name, "a": {"path": pa, "fill_rule": "nonzero"},
                        "b": {"path": pb, "fill_rule": "nonzero"}})
        elif family == "quads":
            idx = sorted(rng.randrange(16) for _ in range(4))
            idx2 = sorted(rng.randrange(16) for _ in range(4))
            xy = [(v & 3, v >> 2) for v in idx + idx2]
            (ax, ay), (bx, by), (cx, cy), (dx, dy), (ex, ey), (fx, fy), (gx, gy), (hx, hy) = xy
            pa = (f"M{ax} {ay} Q{bx} {by} {cx} {cy} L{dx} {dy} Z "
                  f"M{ex} {ey} L{fx} {fy} Q{gx} {gy} {hx} {hy} Z")
            out.append({"name": name, "a": {"path": pa, "fill_rule": rng.choice(rules)}})
        elif family == "coincident":
            # A random closed shape of lines, quadratics and cubics on a small grid, and b a
            # copy of it moved by a grid step, mirrored, turned a quarter or reversed, so that
            # pieces of boundary coincide (in the same or opposite direction), touch at
            # vertices and cross at grid points.
            n = rng.randint(2, 5)
            pts = [(rng.randint(0, 4), rng.randint(0, 4)) for _ in range(n)]
            d = f"M{pts[0][0]} {pts[0][1]}"
            segs = []
            for k in range(n):
                q = pts[(k + 1) % n]
                kind = rng.choice("LLQC")
                ctrl = [(rng.randint(0, 4), rng.randint(0, 4)) for _ in range({"L": 0, "Q": 1, "C": 2}[kind])]
                segs.append((kind, ctrl + [q]))
            for kind, cps in segs:
                d += " " + kind + " ".join(f"{x} {y}" for x, y in cps)
            d += " Z"
            t = rng.choice(["move", "mirror", "turn", "reverse", "same"])
            dx, dy = rng.randint(-2, 2), rng.randint(-2, 2)

            def tf(p):
                x, y = p
                if t == "move":
                    return x + dx, y + dy
                if t == "mirror":
                    return 4 - x, y
                if t == "turn":
                    return 4 - y, x
                return x, y

            if t == "reverse":
                rev = [pts[0]]
                chain = []
                start = pts[0]
                cur = start
                for kind, cps in segs:
                    chain.append((kind, [cur] + cps))
                    cur = cps[-1]
                e = f"M{start[0]} {start[1]}"
                for kind, full in reversed(chain):
                    back = list(reversed(full))
                    e += " " + kind + " ".join(f"{x} {y}" for x, y in back[1:])
                e += " Z"
            else:
                e = f"M{tf(pts[0])[0]} {tf(pts[0])[1]}"
                for kind, cps in segs:
                    e += " " + kind + " ".join(f"{tf(c)[0]} {tf(c)[1]}" for c in cps)
                e += " Z"
            out.append({"name": name + "-" + t, "a": {"path": d, "fill_rule": rng.choice(rules)},
                        "b": {"path": e, "fill_rule": rng.choice(rules)}})
        else:
            raise SystemExit(f"unknown family {family}")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("files", nargs="*")
    ap.add_argument("--port", type=int, default=18200)
    ap.add_argument("--generate", type=int, default=0)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--family", default=None, help="cubics, loops, quads or coincident: --generate samples it")
    ap.add_argument("--points", type=int, default=300, help="random points per case")
    ap.add_argument("--only", default=None, help="substring of case names to run")
    ap.add_argument("--case-seconds", type=int, default=300,
                    help="a case whose checks take longer is reported as failed")
    ap.add_argument("--transform", default=None,
                    help="s,tx,ty: send the operands as curves moved by x -> s x + t")
    args = ap.parse_args()
    cases = []
    for f in args.files:
        with open(f) as fh:
            for line in fh:
                line = line.strip()
                if line and not line.startswith("//"):
                    cases.append(json.loads(line))
    if args.family:
        cases += family_cases(args.family, args.generate, args.seed)
    else:
        cases += generated_cases(args.generate, args.seed)
    if args.only:
        cases = [c for c in cases if args.only in c["name"]]
    transform = tuple(float(v) for v in args.transform.split(",")) if args.transform else None
    svc = Service(args.port)
    rng = random.Random(args.seed)
    failed = 0
    ops = 0
    def too_long(signum, frame):
        raise TimeoutError

    signal.signal(signal.SIGALRM, too_long)
    for case in cases:
        signal.alarm(args.case_seconds)
        try:
            fails, n = check_case(svc, case, rng, args.points, None, transform)
        except TimeoutError:
            fails, n = [f"the check took more than {args.case_seconds} s (checker or service)"], 0
        signal.alarm(0)
        ops += n
        if fails:
            failed += 1
            print(f"FAIL {case['name']}: a={json.dumps(case['a'])} b={json.dumps(case.get('b'))}")
            for f in fails[:6]:
                print("   ", f)
            sys.stdout.flush()
    print(f"{len(cases)} cases, {ops} operations checked, {failed} cases failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
