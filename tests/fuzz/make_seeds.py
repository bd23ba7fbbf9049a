#!/usr/bin/env python3
"""Writes the hand-made seed inputs of the kernel fuzz targets into tests/fuzz/corpus/.

The targets decode their input with libFuzzer's FuzzedDataProvider, which takes integers
from the END of the input, most significant byte first. So a seed is the list of values
the target will consume, each encoded as the provider reads it, and the whole list
reversed. The decoders are in fuzz_support.hpp (NumberSource) and in each *_fuzzer.cpp;
keep this file in step with them.

Run from anywhere: python3 tests/fuzz/make_seeds.py   (it rewrites only its own files,
named seed_*; files libFuzzer adds to a corpus have SHA-1 names).
"""

import os
import struct
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))


class Seed:
    """The values a target consumes, in order."""

    def __init__(self):
        self.consumed = []  # bytes in consumption order

    def byte(self, b):
        self.consumed.append(b & 0xFF)
        return self

    def int_in_range(self, value, lo, hi):
        """ConsumeIntegralInRange(lo, hi) returning `value` (ranges below 256: one byte)."""
        assert lo <= value <= hi and hi - lo < 256
        return self.byte(value - lo)

    def int16(self, value):
        """ConsumeIntegral<int16_t>: two bytes, value = -32768 + (hi << 8 | lo)."""
        raw = value + 32768
        return self.byte(raw >> 8).byte(raw & 0xFF)

    def number(self, x):
        """A NumberSource double: a small integer (selector 1) or k / 2^j (selector 2); any
        other value (a rational such as 1/3) as its nearest double (selector 0)."""
        x = Fraction(x)
        if x.denominator == 1 and -8 <= x <= 8:
            return self.byte(1).int_in_range(int(x), -8, 8)
        j = 0
        while (x * 2**j).denominator != 1 and j <= 20:
            j += 1
        k = x * 2**j
        if k.denominator != 1 or not -32768 <= k <= 32767:
            return self.raw_double(float(x))
        assert k.denominator == 1 and -32768 <= k <= 32767 and j <= 20, x
        return self.byte(2).int16(int(k)).int_in_range(j, 0, 20)

    def raw_double(self, x):
        """A NumberSource double from its IEEE bits (selector 0)."""
        bits = struct.unpack(">Q", struct.pack(">d", x))[0]
        self.byte(0)
        for shift in range(56, -1, -8):
            self.byte(bits >> shift)
        return self

    def points(self, pts):
        for x, y in pts:
            self.number(x).number(y)
        return self

    def data(self):
        return bytes(reversed(self.consumed))


def write(target, name, seed):
    folder = os.path.join(HERE, "corpus", target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "seed_" + name), "wb") as f:
        f.write(seed.data())


# intersect_fuzzer: config (method = c % 3, fat curve 3 if c & 4, tolerance index
# (c >> 3) % 8, 0 = 1e-12), flags (1 symmetry, 2 scaling, 4 tame), scale exponent,
# degree of f, degree of g (b % 5 for b < 224), then the points of f and of g.
def intersect_seed(name, f, g, method=0, fat3=False, tolerance_index=0, flags=7, scale=3):
    config = next(c for c in range(256)
                  if c % 3 == method and bool(c & 4) == fat3 and (c >> 3) % 8 == tolerance_index)
    seed = Seed().byte(config).byte(flags).int_in_range(scale, -60, 60)
    seed.byte(degree_byte(len(f) - 1)).byte(degree_byte(len(g) - 1)).points(f).points(g)
    write("intersect_fuzzer", name, seed)


def degree_byte(n):
    """The byte pick_degree reads as degree n: b % 5 below 224, b % 21 from 224 on."""
    return n if n < 5 else next(b for b in range(224, 256) if b % 21 == n)


def compose(h, q):
    """The control points of h(q(s)) (h's control points, q in Bernstein form, exact
    rationals): de Casteljau's algorithm on polynomials in Bernstein form."""
    from math import comb

    def multiply(a, b):
        m, n = len(a) - 1, len(b) - 1
        return [sum(Fraction(comb(m, j) * comb(n, i - j), comb(m + n, i)) * a[j] * b[i - j]
                    for j in range(max(0, i - n), min(m, i) + 1)) for i in range(m + n + 1)]

    q = [Fraction(v) for v in q]
    one_minus_q = [1 - v for v in q]
    rows = [[[Fraction(x)], [Fraction(y)]] for x, y in h]
    for level in range(len(h) - 1, 0, -1):
        for i in range(level):
            rows[i] = [[a + b for a, b in zip(multiply(one_minus_q, rows[i][c]),
                                               multiply(q, rows[i + 1][c]))] for c in (0, 1)]
    return list(zip(rows[0][0], rows[0][1]))


S_CURVE = [(0, 0), (1, 4), (3, -4), (4, 0)]
for method, label in [(0, "hybrid"), (1, "clipping"), (2, "subdivision")]:
    intersect_seed("lines_" + label, [(0, 0), (4, 4)], [(0, 4), (4, 0)], method)
    intersect_seed("s_curve_line_" + label, S_CURVE, [(-1, 0), (5, 0)], method)
intersect_seed("tangent_parabola", [(0, 0), (2, 4), (4, 0)], [(0, 2), (4, 2)], fat3=True)
intersect_seed("overlap_identical", S_CURVE, S_CURVE)
intersect_seed("overlap_reversed_piece", S_CURVE, list(reversed(S_CURVE)), method=1)
intersect_seed("closed_lens", [(0, 0), (1, 2), (3, 2), (4, 0)], [(4, 0), (3, -2), (1, -2), (0, 0)])
intersect_seed("point_on_line", [(2, 1)], [(0, 0), (4, 2)])
intersect_seed("collinear_segments", [(0, 0), (4, 0)], [(2, 0), (6, 0)], method=2)
intersect_seed("quartics_dyadic", [(0, 0), (0.5, 3), (1.25, -3), (2.75, 3), (4, 0)],
               [(0, 1), (1.5, -2.5), (2, 3.5), (3.5, -1), (4, 1.125)], fat3=True, tolerance_index=2)
intersect_seed("wild_far_apart", [(0, 0), (1, 1)], [(2, 2), (3, 0)], flags=3)
# Curves tracing one arc at different speeds (core/intersect/common_arc.hpp).
PARABOLA = [(0, 0), (1, 2), (3, 0)]
intersect_seed("arc_square", PARABOLA, compose(PARABOLA, [0, 0, 1]))
intersect_seed("arc_retraced", PARABOLA, compose(PARABOLA, [0, 2, 0]), method=2)
intersect_seed("arc_both_turn", compose(PARABOLA, [1, Fraction(-1, 5), 1]),
               compose(PARABOLA, [0, Fraction(6, 5), 0]), fat3=True)
intersect_seed("arc_cubic_square", S_CURVE, compose(S_CURVE, [0, 0, 1]), method=1)

# self_intersection_fuzzer: flags (1 general method instead of the cubic closed form,
# 2 scaling, 4 compare methods, 8 tame), scale exponent, degree byte (1 + b % 5 for
# b < 224), then the points.
def self_seed(name, pts, flags=0b1110, scale=-5):
    seed = Seed().byte(flags).int_in_range(scale, -60, 60).byte(self_degree_byte(len(pts) - 1))
    seed.points(pts)
    write("self_intersection_fuzzer", name, seed)


def self_degree_byte(n):
    """The byte the target reads as degree n: 1 + b % 5 below 224, 1 + b % 20 from 224 on."""
    return n - 1 if n <= 5 else next(b for b in range(224, 256) if 1 + b % 20 == n)


self_seed("cubic_loop", [(0, 0), (2, 2), (-1, 2), (1, 0)])
self_seed("cubic_loop_general", [(0, 0), (2, 2), (-1, 2), (1, 0)], flags=0b1111)
self_seed("cubic_cusp", [(0, 0), (1, 1), (0, 1), (1, 0)])
self_seed("cubic_loop_at_start", [(0, 0), (0, 1), (1, 1), (-3, -6)])
self_seed("quartic_closed", [(0, 0), (4, 4), (-2, 4), (2, -2), (0, 0)])
self_seed("quintic_two_loops", [(0, 0), (4, 4), (-2, 4), (6, -4), (0, -4), (4, 0)])
self_seed("collinear_retracing", [(0, 0), (2, 0), (-1, 0), (1, 0)])
self_seed("point", [(1, 1), (1, 1), (1, 1)])
self_seed("line", [(0, 0), (3, 1)])
# Improper curves that turn back on themselves (core/self_intersect/self_intersection.cpp's improper branch).
self_seed("fold", compose(PARABOLA, [Fraction(1, 16), Fraction(-3, 16), Fraction(9, 16)]))
self_seed("folded_loop", compose([(-9, 0), (13, 16), (-13, 16), (9, 0)],
                                 [Fraction(1, 4), Fraction(-1, 2), Fraction(1)]), scale=-10)

# classify_fuzzer: scale exponent (-40..40), then the four points.
def classify_seed(name, pts, scale=7):
    write("classify_fuzzer", name, Seed().int_in_range(scale, -40, 40).points(pts))


START = [(0, 0), (0, 1), (1, 1)]  # the canonical frame: P3 is the canonical point
classify_seed("arch", START + [(1, 0)])
classify_seed("cusp", [(0, 0), (1, 1), (0, 1), (1, 0)])
classify_seed("loop", START + [(-1, Fraction(-1, 2))])
classify_seed("loop_at_start", START + [(-3, -6)])
classify_seed("loop_at_end", [(-3, -6), (1, 1), (0, 1), (0, 0)])
classify_seed("single_inflection", START + [(0, 2)])
classify_seed("double_inflection", START + [(0, Fraction(7, 8))])
classify_seed("quadratic", START + [(3, 0)])
classify_seed("line", [(0, 0), (1, 1), (3, 3), (2, 2)])
classify_seed("point", [(5, 5)] * 4)
classify_seed("closed", [(0, 0), (2, 2), (-1, 2), (0, 0)])
classify_seed("collinear_start", [(0, 0), (1, 0), (2, 0), (1, 3)])


# work_bound_fuzzer: budget index (22e6 / 10^i), route (0 two curves, 1 one curve,
# 2 loop area), method (0 hybrid, 1 hybrid with fat curves of degree 2, 2 Bézier clipping,
# 3 subdivision), then per curve a degree byte (1 + b % 4 below 192, 1 + b % 20 from 192 on)
# and its coordinates, each a HostileNumbers selector and its payload.
def hostile_number(seed, x):
    """0 (selector 0), a small integer (1), m 10^e (2, from a string "me"), k / 2^j (4)."""
    if isinstance(x, str):
        m, e = x.split("e")
        seed.byte(2).int16(int(m))
        k = int(e) + 300  # ConsumeIntegralInRange(-300, 300): two bytes, high first
        return seed.byte(k >> 8).byte(k & 0xFF)
    x = Fraction(x)
    if x == 0:
        return seed.byte(0)
    if x.denominator == 1 and -8 <= x <= 8:
        return seed.byte(1).int_in_range(int(x), -8, 8)
    j = 0
    while (x * 2**j).denominator != 1:
        j += 1
    return seed.byte(4).int16(int(x * 2**j)).int_in_range(j, 0, 20)


def work_bound_degree_byte(n):
    return n - 1 if n <= 4 else next(b for b in range(192, 256) if 1 + b % 20 == n)


def work_bound_seed(name, curves, route=0, method=0, budget_index=0):
    seed = Seed().int_in_range(budget_index, 0, 3).int_in_range(route, 0, 2)
    seed.int_in_range(method, 0, 3)
    for pts in curves:
        seed.byte(work_bound_degree_byte(len(pts) - 1))
        for x, y in pts:
            hostile_number(seed, x)
            hostile_number(seed, y)
    write("work_bound_fuzzer", name, seed)


# Two requests that once ran for seconds at the default budget, by every method.
STEEP_PARABOLA = [(2, -2), (-1, "1e14"), (-1, -1)]
STEEP_LINE = [(Fraction(-1, 2), 0), (-2, "1e6")]
WIDE_CUBIC = [(0, 1), ("1e9", 1), (0, "-1e9"), (0, -2)]
DIAGONAL = [(0, 0), (1, 1)]
for method, label in [(0, "hybrid"), (1, "hybrid2"), (2, "clipping"), (3, "subdivision")]:
    work_bound_seed("steep_parabola_" + label, [STEEP_PARABOLA, STEEP_LINE], method=method)
    work_bound_seed("wide_cubic_" + label, [WIDE_CUBIC, DIAGONAL], method=method)
work_bound_seed("wide_quartic_self", [[(1, Fraction(1, 2)), (Fraction(1, 2), "-69e13"),
                                       ("69e13", "-69e13"), (Fraction(-19615, 2), "-61e-2"),
                                       ("-74e-17", "-61e-2")]], route=1, method=3)
work_bound_seed("wide_quartic_loop_area", [[(1, Fraction(1, 2)), (Fraction(1, 2), "-69e13"),
                                            ("69e13", "-69e13"), (Fraction(-19615, 2), "-61e-2"),
                                            ("-74e-17", "-61e-2")]], route=2, budget_index=1)
work_bound_seed("tiny_and_huge", [[("1e-300", "1e300"), ("-1e300", "1e-300"), (1, 1)],
                                  [("1e300", "1e300"), ("-1e-300", "-1e300")]], budget_index=2)


# request_cost_fuzzer: byte 0 the route (0 /batch, k the k-th compute route of
# api/route_table.hpp), byte 1 the work cap index (22e6 / 10^i), then the body as it is
# (read from the front, not through FuzzedDataProvider).
COST_ROUTES = ["/batch", "/evaluate", "/polar", "/classify", "/loop-area", "/intersections", "/length",
               "/bounds", "/nearest", "/contains", "/boolean", "/flatten", "/offset", "/segments"]


def request_cost_seed(name, path, body, budget_index=0):
    folder = os.path.join(HERE, "corpus", "request_cost_fuzzer")
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "seed_" + name), "wb") as f:
        f.write(bytes([COST_ROUTES.index(path), budget_index]) + body.encode())


EXTREME_PAIR = ('{"curves":[{"points":[[-3e-300,2e-300],[8.5e+307,1e-310],[-3e-300,1.7e+308],[8.5e+307,1e-300]]},'
                '{"points":[[1e-310,1e-300],[1e-310,-1e-300],[1.7e+308,1e-300],[-3e-300,-1e-300]]}],'
                '"method":"subdivision"}')
SPACE_CURVE_20 = "[" + ",".join("[%d,1,-1]" % i for i in range(21)) + "]"
request_cost_seed("extreme_subdivision", "/intersections", EXTREME_PAIR)
request_cost_seed("extreme_subdivision_batch", "/batch",
                  '{"requests":[' + ",".join(['{"path":"/intersections","body":' + EXTREME_PAIR + "}"] * 10) + "]}",
                  budget_index=2)
request_cost_seed("zero_length_path", "/intersections", '{"curves":[{"path":"M0 0' + "-0-0" * 1200 + '"}]}',
                  budget_index=1)
request_cost_seed("evaluate_samples", "/evaluate", '{"points":' + SPACE_CURVE_20 + ',"samples":10000}')
request_cost_seed("evaluate_batch", "/batch",
                  '{"requests":[' + ",".join(['{"path":"/evaluate","body":{"points":' + SPACE_CURVE_20 +
                                              ',"samples":500,"derivatives":19,"frame":true}}'] * 12) + "]}")
request_cost_seed("polar_samples", "/polar", '{"points":' + SPACE_CURVE_20 + ',"t0":[0.1,0.2,0.3],"samples":10000}')
request_cost_seed("classify", "/classify", '{"points":[[0,0],[1e-310,1e308],[0,1],[1,0]]}')
request_cost_seed("bounds_path", "/bounds",
                  '{"path":"M0 0' + "".join(" C%d 1 %d -1 %d 0" % (3 * i + 1, 3 * i + 2, 3 * i + 3) for i in range(500)) +
                  '"}')
request_cost_seed("segments_arcs", "/segments", '{"path":"M0 0 A1e300 1e300 0 0 1 1 0","arc_tolerance":1e-300}')
