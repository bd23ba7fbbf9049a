#!/usr/bin/env python3
"""Accuracy of the reported intersection points of the benchmark's cubic pairs.

Reads dumps written by bezier_intersection_dump (tests/bench/intersection_dump.cpp), draws
the same 20000 pairs (BENCHMARKS.md, "Benchmark input": mulberry32, seed 1, control points
in [0, 1)^2), and for every crossing of the default method ("cubic/hybrid3") compares the reported point with
(f(t) + g(s)) / 2 evaluated exactly in rationals at the reported t and s. Prints, per dump,
the mean and largest error in ulps of the exact value (the larger coordinate's), how many
points are off by more than 1 ulp, and the same restricted to points whose coordinates are
both at least 1/4 (where the working frame's origin costs no relative accuracy).

    build/tests/bezier_intersection_dump > after.txt
    tests/bench/point_accuracy.py before.txt after.txt
"""
import math
import re
import statistics
import sys
from fractions import Fraction

MASK = 0xFFFFFFFF


class Mulberry32:
    def __init__(self, seed):
        self.state = seed & MASK

    def next(self):
        self.state = (self.state + 0x6D2B79F5) & MASK
        t = ((self.state ^ (self.state >> 15)) * (self.state | 1)) & MASK
        t = ((t + (((t ^ (t >> 7)) * (t | 61)) & MASK)) & MASK) ^ t
        return (t ^ (t >> 14)) / 4294967296.0


def cubic_pairs(count=20000):
    rng = Mulberry32(1)
    pairs = []
    for _ in range(count):
        f = [(rng.next(), rng.next()) for _ in range(4)]
        g = [(rng.next(), rng.next()) for _ in range(4)]
        pairs.append((f, g))
    return pairs


def evaluate(points, t):
    t = Fraction(t)
    row = [(Fraction(x), Fraction(y)) for x, y in points]
    while len(row) > 1:
        row = [((1 - t) * a[0] + t * b[0], (1 - t) * a[1] + t * b[1]) for a, b in zip(row, row[1:])]
    return row[0]


def crossings(path):
    """{pair index: [(t, s, x, y)]} for the default method's answers."""
    out, index = {}, None
    for line in open(path):
        if line.startswith("cubic/"):
            index = int(line.split()[1]) if line.startswith("cubic/hybrid3 ") else None
            if index is not None:
                out[index] = []
        elif index is not None and "kind" in line:
            fields = line.split()
            point = re.search(r"\((\S+) (\S+)\)", line)
            out[index].append(tuple(float.fromhex(v) for v in
                                    (fields[0], fields[1], point.group(1), point.group(2))))
    return out


def ulps(value, exact):
    return float(abs(Fraction(value) - exact) / Fraction(math.ulp(float(exact))))


def main(paths):
    pairs = cubic_pairs()
    for path in paths:
        errors, inner = [], []
        for index, found in crossings(path).items():
            f, g = pairs[index]
            for t, s, x, y in found:
                a, b = evaluate(f, t), evaluate(g, s)
                mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
                error = max(ulps(x, mid[0]), ulps(y, mid[1]))
                errors.append(error)
                if abs(mid[0]) >= Fraction(1, 4) and abs(mid[1]) >= Fraction(1, 4):
                    inner.append(error)
        print(f"{path}: {len(errors)} points, mean {statistics.mean(errors):.3f} ulp, "
              f"max {max(errors):.3f}, > 1 ulp: {sum(e > 1 for e in errors)}; "
              f"coordinates >= 1/4: {len(inner)} points, max {max(inner):.3f}, "
              f"> 1 ulp: {sum(e > 1 for e in inner)}")


if __name__ == "__main__":
    main(sys.argv[1:])
