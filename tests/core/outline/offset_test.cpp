// Tests of core/outline/offset.hpp: cubics within a tolerance of the parallel curve.
//
// Independent checks: every exact offset point O(t) = B(t) + d N(t) (N from the derivative,
// computed here) is within the tolerance of the answer (nearest-point kernel on each cubic);
// every answer point is within the tolerance of the exact offset curve (the least distance
// to O over a dense set of t, refined by golden-section search around the best); cusps of O
// are ends of cubics; a line's offset is a line.

#include "core/outline/offset.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <limits>
#include <vector>

#include "core/curve/derivative.hpp"
#include "core/curve/evaluate.hpp"
#include "core/measure/nearest.hpp"
#include "core/outline/offset_cusps.hpp"
#include "core/outline/tangent_limits.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::outline {
namespace {

using core::Curve;
using core::Point2;

/// O(t) with the one-sided limit of the normal where B' = 0 (side +1 from the right): the
/// first derivative longer than `least` gives the direction.
Point2 exact_offset(const Curve& curve, double d, double t, double side, double least = 1e-9) {
  const auto k = core::derivatives_at(curve, t, curve.degree());
  for (std::size_t i = 0; i < k.size(); ++i) {
    const double len = core::length(k[i]);
    if (len > least) {
      const double sign = (i % 2 == 1 && side < 0) ? -1.0 : 1.0;  // ε^i / i! B^(i+1)
      const Point2 tangent = (sign / len) * k[i];
      return core::evaluate(curve, t) + d * Point2{-tangent.y, tangent.x};
    }
  }
  return core::evaluate(curve, t);
}

double distance_to_answer(const CurveOffset& offset, Point2 p) {
  double best = std::numeric_limits<double>::infinity();
  for (const OffsetCubic& c : offset.cubics) {
    const Curve cubic(std::vector<Point2>(c.points.begin(), c.points.end()));
    best = std::min(best, core::nearest(cubic, p, 0, 1).distance);
  }
  return best;
}

/// min over t in [t0, t1] of |O(t) - p|: dense samples, then golden-section search around the
/// best sample.
double distance_to_exact(const Curve& curve, double d, double t0, double t1, Point2 p,
                         double least = 1e-9) {
  const int samples = 400;
  double best = std::numeric_limits<double>::infinity();
  int best_j = 0;
  for (int j = 0; j <= samples; ++j) {
    const double t = t0 + (t1 - t0) * j / samples;
    const double dist =
        core::length(exact_offset(curve, d, t, j == samples ? -1.0 : 1.0, least) - p);
    if (dist < best) best = dist, best_j = j;
  }
  double lo = t0 + (t1 - t0) * std::max(0, best_j - 1) / samples;
  double hi = t0 + (t1 - t0) * std::min(samples, best_j + 1) / samples;
  const double phi = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 80; ++i) {
    const double m1 = hi - phi * (hi - lo), m2 = lo + phi * (hi - lo);
    const double f1 = core::length(exact_offset(curve, d, m1, 1.0, least) - p);
    const double f2 = core::length(exact_offset(curve, d, m2, 1.0, least) - p);
    best = std::min({best, f1, f2});
    (f1 < f2 ? hi : lo) = f1 < f2 ? m2 : m1;
  }
  return best;
}

CurveOffset unbounded_offset(const Curve& curve, double d, double tolerance) {
  core::WorkBudget budget;
  return offset_curve(curve, d, tolerance, budget);
}

void expect_within(const Curve& curve, double d, double tolerance, const CurveOffset& offset,
                   double least = 1e-9) {
  ASSERT_FALSE(offset.cubics.empty());
  const double allowed = tolerance * (1 + 1e-6);
  // Exact offset points near the answer, from both sides of every cut.
  for (const OffsetCubic& c : offset.cubics) {
    EXPECT_LE(c.error_bound, tolerance);
    for (int j = 0; j <= 20; ++j) {
      const double t = c.t0 + (c.t1 - c.t0) * j / 20;
      const Point2 o = exact_offset(curve, d, t, j == 20 ? -1.0 : 1.0, least);
      EXPECT_LE(distance_to_answer(offset, o), allowed) << "t " << t << " d " << d;
    }
    // Answer points near the exact offset of their piece.
    const Curve cubic(std::vector<Point2>(c.points.begin(), c.points.end()));
    for (int j = 0; j <= 8; ++j) {
      const Point2 p = core::evaluate(cubic, j / 8.0);
      EXPECT_LE(distance_to_exact(curve, d, c.t0, c.t1, p, least), allowed)
          << "piece " << c.t0 << " d " << d;
    }
  }
  // The pieces cover [0, 1] in order.
  EXPECT_EQ(offset.cubics.front().t0, 0.0);
  EXPECT_EQ(offset.cubics.back().t1, 1.0);
  for (std::size_t i = 1; i < offset.cubics.size(); ++i)
    EXPECT_EQ(offset.cubics[i].t0, offset.cubics[i - 1].t1);
}

TEST(Offset, LineOffsetIsTheParallelLine) {
  const Curve line({{0, 0}, {3, 0}});
  const CurveOffset o = unbounded_offset(line, 1.0, 1e-6);
  ASSERT_EQ(o.cubics.size(), 1u);
  EXPECT_EQ(o.cubics[0].points[0], (Point2{0, 1}));
  EXPECT_EQ(o.cubics[0].points[3], (Point2{3, 1}));
  expect_within(line, 1.0, 1e-6, o);
}

TEST(Offset, ParabolaBothSides) {
  const Curve parabola({{-1, 1}, {0, -1}, {1, 1}});
  for (const double d : {0.3, -0.3, -1.0}) {
    expect_within(parabola, d, 1e-3, unbounded_offset(parabola, d, 1e-3));
  }
}

TEST(Offset, CuspsAreEndsOfCubics) {
  const Curve parabola({{-1, 1}, {0, -1}, {1, 1}});
  const double d = std::sqrt(2.0);  // cusps at t = 1/4 and 3/4 (offset_cusps_test.cpp)
  const CurveOffset o = unbounded_offset(parabola, d, 1e-3);
  expect_within(parabola, d, 1e-3, o);
  for (const double cusp : offset_cusps(parabola, d)) {
    bool is_end = false;
    for (const OffsetCubic& c : o.cubics) is_end = is_end || c.t1 == cusp;
    EXPECT_TRUE(is_end) << cusp;
  }
}

TEST(Offset, RandomCubicsAndQuintics) {
  test::Mulberry32 rng(3131);
  for (int trial = 0; trial < 12; ++trial) {
    const int n = trial % 3 == 2 ? 5 : 3;
    std::vector<Point2> p;
    for (int k = 0; k <= n; ++k) p.push_back({rng.uniform(-1, 1), rng.uniform(-1, 1)});
    const Curve curve(p);
    const double d = rng.uniform(-0.3, 0.3);
    expect_within(curve, d, 1e-3, unbounded_offset(curve, d, 1e-3));
  }
}

// Each cubic's certified bound (error_bound) against its measured distance to O on its
// piece, both ways: the bound's sampled part and its remainder (the interpolation error with
// offset.hpp's bound of |d N''|) must hold wherever O turns fast and slowly, on pieces kept
// with few samples and on ones cut because their first bound failed.
TEST(Offset, EachBoundHoldsAgainstTheMeasuredDistance) {
  test::Mulberry32 rng(4242);
  int cut = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const int n = trial % 4 == 3 ? 5 : 3;
    std::vector<Point2> p;
    for (int k = 0; k <= n; ++k) p.push_back({rng.uniform(-1, 1), rng.uniform(-1, 1)});
    const Curve curve(p);
    const double d = rng.uniform(-0.2, 0.2);
    const double tolerance = trial % 2 == 0 ? 1e-3 : 1e-5;
    const CurveOffset offset = unbounded_offset(curve, d, tolerance);
    ASSERT_FALSE(offset.cubics.empty());
    for (const OffsetCubic& c : offset.cubics) {
      if (c.t0 > 0.0 && c.t0 != offset.cubics.front().t0) ++cut;
      const Curve cubic(std::vector<Point2>(c.points.begin(), c.points.end()));
      // The distance measures (nearest points, golden sections) are accurate to far below
      // the bounds compared.
      const double allowed = c.error_bound * (1 + 1e-6) + 1e-12;
      for (int j = 0; j <= 64; ++j) {
        const double t = c.t0 + (c.t1 - c.t0) * j / 64;
        const Point2 o = exact_offset(curve, d, t, j == 64 ? -1.0 : 1.0);
        EXPECT_LE(core::nearest(cubic, o, 0, 1).distance, allowed) << trial << " t " << t;
      }
      for (int j = 0; j <= 16; ++j) {
        const Point2 q = core::evaluate(cubic, j / 16.0);
        EXPECT_LE(distance_to_exact(curve, d, c.t0, c.t1, q), allowed) << trial << " " << c.t0;
      }
    }
  }
  EXPECT_GT(cut, 0);  // curves of more than one cubic (cusps of O, and pieces split after a bound failed)
}

TEST(Offset, ZeroDerivativeAtAnEndAndInside) {
  const Curve handle({{0, 0}, {0, 0}, {1, 1}, {2, 0}});  // B'(0) = 0
  expect_within(handle, 0.2, 1e-3, unbounded_offset(handle, 0.2, 1e-3));
  const Curve cusped({{0, 0}, {2, 2}, {-1, 2}, {1, 0}});  // B'(1/2) = 0
  const CurveOffset o = unbounded_offset(cusped, 0.1, 1e-3);
  expect_within(cusped, 0.1, 1e-3, o);
  bool cut = false;
  for (const OffsetCubic& c : o.cubics) cut = cut || std::fabs(c.t1 - 0.5) < 1e-9;
  EXPECT_TRUE(cut);
}

TEST(Offset, NextToACuspOfTheCurveAtTightTolerances) {
  // B'(1/2) = 0: next to it the curvature grows without bound, so O has a cusp of its own
  // within a few 1e-6 of t = 1/2, and the pieces between the two cusps are short against
  // the curve's size (their own control points differ by little more than rounding).
  const Curve cusped({{0, 0}, {10, 10}, {0, 10}, {10, 0}});
  for (const double tolerance : {1e-5, 1e-6}) {
    for (const double d : {1.0, -1.0, 0.25}) {
      expect_within(cusped, d, tolerance, unbounded_offset(cusped, d, tolerance));
    }
  }
}

TEST(Offset, TheChecksTellAnotherDistanceApart) {
  // The independent check is sharp enough to see a parallel curve 0.01 away.
  const Curve parabola({{-1, 1}, {0, -1}, {1, 1}});
  const CurveOffset o = unbounded_offset(parabola, 0.3, 1e-3);
  double worst = 0.0;
  for (int j = 0; j <= 20; ++j)
    worst = std::max(worst, distance_to_answer(o, exact_offset(parabola, 0.31, j / 20.0, 1.0)));
  EXPECT_GT(worst, 5e-3);
}

TEST(Offset, BothSidesTogetherAreEachSideAlone) {
  // offset_interval_sides at ±d gives, bit for bit, the cubics and the work of
  // offset_interval at d and at -d, on intervals with no cusp of either side and no zero of
  // B' inside (lines, conics, cubics and quintics, loose and nearly tight sides, tight
  // tolerances where the first fit of a side fails and it is split on its own).
  test::Mulberry32 rng(3132);
  std::vector<Curve> curves{Curve({{0, 0}, {3, 1}}), Curve({{-1, 1}, {0, -1}, {1, 1}})};
  for (int trial = 0; trial < 24; ++trial) {
    const int n = trial % 3 == 2 ? 5 : 3;
    std::vector<Point2> p;
    for (int k = 0; k <= n; ++k) p.push_back({rng.uniform(-1, 1), rng.uniform(-1, 1)});
    curves.emplace_back(p);
  }
  int compared = 0;
  for (const Curve& curve : curves) {
    for (const double d : {0.02, 0.3}) {
      for (const double tolerance : {1e-3, 1e-7}) {
        std::vector<double> cuts{0.0, 1.0};
        for (const double t : offset_cusps(curve, d)) cuts.push_back(t);
        for (const double t : offset_cusps(curve, -d)) cuts.push_back(t);
        for (const double t : stationary_points(curve)) cuts.push_back(t);
        std::sort(cuts.begin(), cuts.end());
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
          const double a = cuts[k], b = cuts[k + 1];
          if (!(b > a)) continue;
          core::WorkBudget alone_budget(std::numeric_limits<std::int64_t>::max() / 4);
          core::WorkBudget together_budget(std::numeric_limits<std::int64_t>::max() / 4);
          std::vector<OffsetCubic> plus, minus, plus_alone, minus_alone;
          ASSERT_TRUE(offset_interval(curve, a, b, d, tolerance, alone_budget, plus_alone));
          ASSERT_TRUE(offset_interval(curve, a, b, -d, tolerance, alone_budget, minus_alone));
          ASSERT_TRUE(
              offset_interval_sides(curve, a, b, d, tolerance, together_budget, plus, minus));
          EXPECT_EQ(alone_budget.spent(), together_budget.spent());
          for (const auto& [together, alone] : {std::pair{&plus, &plus_alone},
                                                std::pair{&minus, &minus_alone}}) {
            ASSERT_EQ(together->size(), alone->size());
            for (std::size_t i = 0; i < alone->size(); ++i) {
              EXPECT_EQ((*together)[i].t0, (*alone)[i].t0);
              EXPECT_EQ((*together)[i].t1, (*alone)[i].t1);
              EXPECT_EQ((*together)[i].error_bound, (*alone)[i].error_bound);
              for (std::size_t j = 0; j < 4; ++j)
                EXPECT_EQ((*together)[i].points[j], (*alone)[i].points[j]);
            }
          }
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, 100);
}

/// The offset within the service's default work cap per request (api/limits.hpp's max_work):
/// these inputs must be answered, not refused.
CurveOffset capped_offset(const Curve& curve, double d, double tolerance) {
  core::WorkBudget budget(22000000);
  CurveOffset o = offset_curve(curve, d, tolerance, budget);
  EXPECT_FALSE(budget.exhausted()) << "work cap reached";
  return o;
}

/// The expected answer for a curve on the x-axis, in closed form: between consecutive zeros
/// of x' (given, with 0 and 1) the curve runs one way along the axis, so its parallel curve
/// is the segment [x(t_k), x(t_{k+1})] moved by d to the left of that way, y = ±d. The cubics
/// of each run (it may be cut where it passes another turn of the curve) must lie on that
/// line within the run's segment, straight (handles on it), chained end to end in the run's
/// direction from x(t_k) to x(t_{k+1}).
void expect_moved_segments(const Curve& curve, double d, double tolerance,
                           const std::vector<double>& zeros, const CurveOffset& o) {
  std::vector<double> cuts{0.0};
  cuts.insert(cuts.end(), zeros.begin(), zeros.end());
  cuts.push_back(1.0);
  const double rounding = 1e-12 * (core::scale(curve) + std::fabs(d));
  std::size_t next = 0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double x0 = core::evaluate(curve, cuts[k]).x, x1 = core::evaluate(curve, cuts[k + 1]).x;
    const double side = x1 > x0 ? d : -d;  // left of +x is +y, left of -x is -y
    ASSERT_LT(next, o.cubics.size());
    EXPECT_NEAR(o.cubics[next].t0, cuts[k], 1e-12);
    EXPECT_NEAR(o.cubics[next].points[0].x, x0, rounding);
    double at = x0;
    for (; next < o.cubics.size() && o.cubics[next].t1 <= cuts[k + 1] + 1e-12; ++next) {
      const OffsetCubic& c = o.cubics[next];
      EXPECT_NEAR(c.points[0].x, at, rounding);
      at = c.points[3].x;
      EXPECT_TRUE(x1 > x0 ? c.points[3].x >= c.points[0].x : c.points[3].x <= c.points[0].x);
      for (const Point2 p : c.points) {
        EXPECT_NEAR(p.y, side, rounding);
        EXPECT_GE(p.x, std::min(x0, x1) - rounding);
        EXPECT_LE(p.x, std::max(x0, x1) + rounding);
      }
      EXPECT_LE(c.error_bound, tolerance);
    }
    EXPECT_NEAR(o.cubics[next - 1].t1, cuts[k + 1], 1e-12);
    EXPECT_NEAR(at, x1, rounding);
  }
  EXPECT_EQ(next, o.cubics.size());
}

TEST(Offset, CollinearCurvesThatTurnBackAreTheirRunsMovedAlongTheNormal) {
  // B' = 0 where the curve reverses along its line: the quadratic's x' = 200 (1 - t) - 100 t
  // vanishes at 2/3; the cubics' x' / 3 = 100 (1 - t)^2 + 2 c1 t (1 - t) + c2 t^2 with
  // (c1, c2) = (-200, 100): 600 t^2 - 600 t + 100 = 0, t = 1/2 ± sqrt(3)/6; (0, -50):
  // 100 (1 - t)^2 = 50 t^2, t = sqrt(2) / (1 + sqrt(2)); (-200, 150): 650 t^2 - 600 t + 100,
  // t = (6 ± sqrt(10)) / 13.
  const double r3 = std::sqrt(3.0), r2 = std::sqrt(2.0), r10 = std::sqrt(10.0);
  const std::vector<std::pair<Curve, std::vector<double>>> cases{
      {Curve({{0, 0}, {100, 0}, {50, 0}}), {2.0 / 3.0}},
      {Curve({{0, 0}, {100, 0}, {-100, 0}, {0, 0}}), {0.5 - r3 / 6, 0.5 + r3 / 6}},
      {Curve({{0, 0}, {100, 0}, {100, 0}, {50, 0}}), {r2 / (1 + r2)}},
      {Curve({{0, 0}, {100, 0}, {-100, 0}, {50, 0}}), {(6 - r10) / 13, (6 + r10) / 13}},
  };
  for (const auto& [curve, zeros] : cases) {
    for (const double d : {2.0, -2.0, 0.5}) {
      for (const double tolerance : {1e-3, 1.5e-7}) {
        SCOPED_TRACE(testing::Message() << "degree " << curve.degree() << " d " << d
                                        << " tolerance " << tolerance);
        const CurveOffset o = capped_offset(curve, d, tolerance);
        expect_moved_segments(curve, d, tolerance, zeros, o);
        expect_within(curve, d, tolerance, o);
      }
    }
  }
}

TEST(Offset, CollinearCurvesOffTheAxesAndOfHighDegree) {
  // On the line through (0, 0) along (3, 4), turning back at t = 1/2 (x' ∝ (1 - 2t)): each
  // run's parallel curve is one straight cubic; and a curve of degree 20 whose last 20
  // control points coincide (B' = 20 (1 - t)^19 (P1 - P0): a zero of order 19 at t = 1).
  const Curve slanted({{0, 0}, {30, 40}, {0, 0}});
  for (const double d : {1.0, -3.0}) {
    const CurveOffset o = capped_offset(slanted, d, 1e-7);
    ASSERT_EQ(o.cubics.size(), 2u);
    expect_within(slanted, d, 1e-7, o);
  }
  std::vector<Point2> p{{0, 0}};
  for (int k = 0; k < 20; ++k) p.push_back({4, 0});
  const Curve flat(p);
  // (expect_within's exact_offset takes B' below 1e-9 for zero, as it is here from t = 0.7
  // on: the closed form alone judges.)
  expect_moved_segments(flat, 1.0, 1e-3, {}, capped_offset(flat, 1.0, 1e-3));
  expect_moved_segments(flat, -1.0, 1e-9 * 4, {}, capped_offset(flat, -1.0, 1e-9 * 4));
}

TEST(Offset, ZigzagOfDegreeNineteenAlongALine) {
  // Control points alternating between (0, 0) and (10, 0): B runs back and forth along the
  // axis, turning where x' vanishes. Every cubic lies on y = ±d inside [0, 10] (the closed
  // form of each run's parallel curve), and every point of O (from B' where it is not near
  // a zero, the normal then being unambiguous) is within the tolerance of the answer.
  std::vector<Point2> p;
  for (int k = 0; k < 10; ++k) {
    p.push_back({0, 0});
    p.push_back({10, 0});
  }
  const Curve zigzag(p);
  const double d = 1.5, tolerance = 1e-6;
  const CurveOffset o = capped_offset(zigzag, d, tolerance);
  ASSERT_FALSE(o.cubics.empty());
  for (const OffsetCubic& c : o.cubics) {
    EXPECT_LE(c.error_bound, tolerance);
    for (const Point2 q : c.points) {
      EXPECT_NEAR(std::fabs(q.y), d, 1e-12);
      EXPECT_GE(q.x, -1e-12);
      EXPECT_LE(q.x, 10 + 1e-12);
    }
  }
  for (int j = 0; j <= 2000; ++j) {
    const double t = j / 2000.0;
    const Point2 v = core::derivatives_at(zigzag, t, 1)[0];
    if (std::fabs(v.x) < 1e-3) continue;
    const Point2 exact = core::evaluate(zigzag, t) + Point2{0, v.x > 0 ? d : -d};
    EXPECT_LE(distance_to_answer(o, exact), tolerance) << "t " << t;
  }
}

TEST(Offset, TrueCuspOfTheCurveAtTheSmallestAcceptedTolerances) {
  // B'(1/2) = 0 exactly; tolerances down to 1e-9 of the scale (10) are accepted (offset.hpp).
  const Curve cusped({{0, 0}, {10, 10}, {0, 10}, {10, 0}});
  for (const double tolerance : {1e-7, 1e-8}) {
    for (const double d : {1.0, -1.0}) {
      SCOPED_TRACE(testing::Message() << "d " << d << " tolerance " << tolerance);
      expect_within(cusped, d, tolerance, capped_offset(cusped, d, tolerance));
    }
  }
  // Degree 5 with repeated control points: B' vanishes at both ends to the third order.
  const Curve repeated({{0, 0}, {0, 0}, {0, 0}, {5, 5}, {5, 5}, {10, 0}});
  expect_within(repeated, 1.0, 1e-6, capped_offset(repeated, 1.0, 1e-6));
}

TEST(Offset, HairpinWhoseTurnSpansATrillionthOfTheParameter) {
  // x' = 200 (1 - t) - 100 t vanishes at 2/3, where y' = 2e-9 (1 - 3t) is -6.7e-10: B turns
  // back by a half turn within about 1e-11 of t, and O goes round a half circle of radius |d|
  // there; the parts shrink towards it for about 40 levels before they reach the turn. B'
  // is nowhere zero (|B'| >= 6.7e-10), so the check takes the normal from B' itself.
  const Curve hairpin({{0, 0}, {100, 1e-9}, {50, 0}});
  for (const double d : {2.0, -0.5}) {
    SCOPED_TRACE(testing::Message() << "d " << d);
    expect_within(hairpin, d, 1e-3, capped_offset(hairpin, d, 1e-3), 0.0);
  }
}

TEST(Offset, CuspRoundedOffItsZeroIsTheCuspsOffset) {
  // P2 moved by 1e-12 off the cusp of {0,0},{10,10},{0,10},{10,0}: x' has no real root left,
  // |B'(1/2)| = 7.5e-13, below end_tangent's threshold; stationary_points reports the
  // minimum of |B'| there and the answer is the cusped curve's parallel curve (the curves
  // differ by 1e-12 in position), judged against the exact cusp's.
  const Curve rounded({{0, 0}, {10, 10}, {1e-12, 10}, {10, 0}});
  const std::vector<double> zeros = stationary_points(rounded);
  ASSERT_EQ(zeros.size(), 1u);
  EXPECT_NEAR(zeros[0], 0.5, 1e-6);
  const Curve cusped({{0, 0}, {10, 10}, {0, 10}, {10, 0}});
  for (const double d : {1.0, -1.0}) {
    SCOPED_TRACE(testing::Message() << "d " << d);
    expect_within(cusped, d, 1e-6 + 1e-9, capped_offset(rounded, d, 1e-6));
  }
}

TEST(Offset, CurveThatIsOnePointIsOnePointAsALineOfZeroLength) {
  // No direction: end_tangent's convention (1, 0), as the line from a point to itself.
  const CurveOffset line = capped_offset(Curve({{2, 3}, {2, 3}}), 1.5, 1e-6);
  const CurveOffset cubic = capped_offset(Curve({{2, 3}, {2, 3}, {2, 3}, {2, 3}}), 1.5, 1e-6);
  ASSERT_EQ(line.cubics.size(), 1u);
  ASSERT_EQ(cubic.cubics.size(), 1u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(line.cubics[0].points[i], (Point2{2, 4.5}));
    EXPECT_EQ(cubic.cubics[0].points[i], (Point2{2, 4.5}));
  }
}

TEST(Offset, WorkCapIsReported) {
  const Curve curve({{0, 0}, {1, 2}, {2, -2}, {3, 0}});
  core::WorkBudget budget(1000);
  const CurveOffset o = offset_curve(curve, 0.1, 1e-6, budget);
  EXPECT_TRUE(budget.exhausted());
  EXPECT_TRUE(o.cubics.empty());
}

}  // namespace
}  // namespace bezier::outline
