// Every intersection and overlap of the benchmark pairs, written bit for bit, so that a change
// meant to leave results alone (a faster clipping step, a compiler option) can be checked by
// comparing two runs:
//
//   build/tests/bezier_intersection_dump > before.txt    # on the old tree
//   build/tests/bezier_intersection_dump > after.txt     # on the new one
//   cmp before.txt after.txt
//
// The pairs: the 20000 random cubic pairs of the shared benchmark input (mulberry32 seed 1;
// BENCHMARKS.md) by hybrid with fat curves of degree 3 and 2, Bézier clipping and subdivision; 1000
// degree-7 pairs (seed 7) by hybrid and Bézier clipping; 200 degree-10 pairs (seed 10); 2000
// cubic-line (seed 5) and 2000 cubic-quadratic pairs (seed 6). Per pair: a header line (set, index,
// status, counts), then each intersection (estimates, both intervals, point, kind, resolved) and
// each overlap, every number as %a.

#include <cstdint>
#include <cstdio>
#include <utility>
#include <vector>

#include "core/intersect/intersect.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/mulberry32.hpp"

namespace {

using bezier::core::Curve;
using bezier::core::IntersectMethod;
using bezier::core::Point2;

using Pairs = std::vector<std::pair<Curve, Curve>>;

/// Control points uniform in [0, 1)^2 (mulberry32's draws themselves, x then y), f's then g's.
Pairs random_pairs(std::uint32_t seed, int f_degree, int g_degree, int count) {
  bezier::test::Mulberry32 rng(seed);
  Pairs pairs;
  for (int i = 0; i < count; ++i) {
    Curve f = bezier::test::random_curve<Point2>(rng, f_degree, 0.0, 1.0);
    Curve g = bezier::test::random_curve<Point2>(rng, g_degree, 0.0, 1.0);
    pairs.emplace_back(std::move(f), std::move(g));
  }
  return pairs;
}

void dump(const char* set, const Pairs& pairs, IntersectMethod method, int fat_curve_degree) {
  bezier::core::IntersectOptions options;
  options.method = method;
  options.fat_curve_degree = fat_curve_degree;
  int index = 0;
  for (const auto& [f, g] : pairs) {
    const auto r = bezier::core::intersect(f, g, options);
    std::printf("%s %d status %d intersections %zu overlaps %zu\n", set, index++,
                static_cast<int>(r.status), r.intersections.size(), r.overlaps.size());
    for (const auto& x : r.intersections) {
      std::printf(" %a %a [%a %a] [%a %a] (%a %a) kind %d resolved %d\n", x.t, x.s, x.t_interval.lo,
                  x.t_interval.hi, x.s_interval.lo, x.s_interval.hi, x.point.x, x.point.y,
                  static_cast<int>(x.kind), static_cast<int>(x.resolved));
    }
    for (const auto& o : r.overlaps) {
      std::printf(" overlap [%a %a] [%a %a] reversed %d\n", o.t_interval.lo, o.t_interval.hi,
                  o.s_interval.lo, o.s_interval.hi, static_cast<int>(o.reversed));
    }
  }
}

}  // namespace

int main() {
  const Pairs cubic = random_pairs(1, 3, 3, 20000);
  dump("cubic/hybrid3", cubic, IntersectMethod::hybrid, 3);
  dump("cubic/hybrid2", cubic, IntersectMethod::hybrid, 2);
  dump("cubic/bezier-clipping", cubic, IntersectMethod::bezier_clipping, 3);
  dump("cubic/subdivision", cubic, IntersectMethod::subdivision, 3);
  const Pairs degree7 = random_pairs(7, 7, 7, 1000);
  dump("degree7/hybrid3", degree7, IntersectMethod::hybrid, 3);
  dump("degree7/bezier-clipping", degree7, IntersectMethod::bezier_clipping, 3);
  dump("degree10/hybrid3", random_pairs(10, 10, 10, 200), IntersectMethod::hybrid, 3);
  dump("cubic-line/hybrid3", random_pairs(5, 3, 1, 2000), IntersectMethod::hybrid, 3);
  dump("cubic-quadratic/hybrid3", random_pairs(6, 3, 2, 2000), IntersectMethod::hybrid, 3);
  return 0;
}
