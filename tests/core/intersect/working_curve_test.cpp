// The working frame (working_curve.hpp) at the ends of the double range: subnormal
// coordinates, coordinates next to the largest double, tiny curves far from the origin.
// Through intersect(), whose answers must be finite and hold the exact roots.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "core/base/curve.hpp"
#include "core/curve/evaluate.hpp"
#include "core/intersect/intersect.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/intersection_checks.hpp"

namespace bezier::core {
namespace {

using test::covered;
using test::exact_point;
using test::expect_intersection_contract;
using test::expect_no_common_point;
using test::expect_one_exact_end_root;
using test::for_every_option;
using test::on_parabola;
using test::RationalPoint;

// Subnormal coordinates. Two segments 1e-310 long meeting
// at the origin, f(1) = g(0) = (0, 0): the kernel answered (1, 1) with a NaN point (the
// working frame's power-of-two scale overflowed).
TEST(WorkingCurve, SubnormalCoordinatesGiveFinitePointsAndTheRightRoot) {
  const Curve f({{1e-310, 0.0}, {0.0, 0.0}});
  const Curve g({{0.0, 0.0}, {0.0, 1e-310}});
  const IntersectionResult r = intersect(f, g);
  ASSERT_EQ(r.status, IntersectStatus::ok);
  EXPECT_TRUE(covered(r, 1.0, 0.0));
  expect_intersection_contract(r, IntersectOptions{}.tolerance);
}

// Coordinates a few subnormal steps
// from zero. A point (a degree-1 curve with equal points) at the origin and the segment
// g(s) = (-4 (1 - s) 2^-1074, 0) ending there: the working frame's grid (a sixteenth of the
// extent) underflowed to 0 and its origin became NaN, so the search spent the whole work
// budget and reported NaN points. The answer: s = 1 exactly, t free, the point the origin.
TEST(WorkingCurve, SegmentFourSubnormalStepsLong) {
  const Curve f({{0.0, 0.0}, {0.0, 0.0}});
  const Curve g({{-0x0.0000000000004p-1022, 0.0}, {0.0, 0.0}});
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    ASSERT_EQ(r.intersections.size(), 1u);
    EXPECT_TRUE(swapped ? covered(r, 1.0, 0.5) : covered(r, 0.5, 1.0));
    const Intersection& x = r.intersections[0];
    EXPECT_LT((swapped ? x.t_interval : x.s_interval).width(), IntersectOptions{}.tolerance);
    EXPECT_EQ(swapped ? x.s_interval : x.t_interval, (ParamInterval{0.0, 1.0}));
    // Within a subnormal step of the origin (the mean of f(t) and g(s), rounded).
    EXPECT_LE(std::fabs(x.point.x), 0x1p-1074);
    EXPECT_EQ(x.point.y, 0.0);
    expect_intersection_contract(r, IntersectOptions{}.tolerance);
  }
}

// Coordinates next to the largest double. The working
// frame's origin, rounded to its grid, must stay within the double range, or the offsets are
// infinite and `std::ilogb(m) + 1` overflows an int. The answer: f(t) = (1.79e308 t, -1.79e308) ends where g (a point) is, t = 1,
// s free.
TEST(WorkingCurve, CoordinatesNextToTheLargestDouble) {
  const Curve f({{0.0, -1.79e308}, {1.79e308, -1.79e308}});
  const Curve g({{1.79e308, -1.79e308}, {1.79e308, -1.79e308}});
  const IntersectionResult r = intersect(f, g);
  ASSERT_EQ(r.status, IntersectStatus::ok);
  ASSERT_EQ(r.intersections.size(), 1u);
  EXPECT_TRUE(covered(r, 1.0, 0.5));
  const Intersection& x = r.intersections[0];
  EXPECT_LT(x.t_interval.width(), IntersectOptions{}.tolerance);
  EXPECT_EQ(x.s_interval, (ParamInterval{0.0, 1.0}));
  EXPECT_NEAR(x.point.x, 1.79e308, 1.79e308 * 1e-15);
  EXPECT_EQ(x.point.y, -1.79e308);
  expect_intersection_contract(r, IntersectOptions{}.tolerance);
}

TEST(WorkingCurve, ATinyCurveFarFromTheOriginHasAFiniteFrame) {
  // Two vertical segments at x = -7, about 2^-1030 long near y = 2^-1007: the working frame's
  // grid (a sixteenth of the extent) is so fine that -7 / grid overflowed, the origin came
  // out infinite and the frame's exponent overflowed an int (UBSan). They lie on one
  // line and overlap where their y ranges do: f from t = 0 to where it reaches g's end, g
  // from where it reaches f's start to s = 1 (the fractions computed here in rationals).
  using bezier::test::Rational;
  const double y1 = 0x1.9010901270001p-1007, y2 = 0x1.9010c01012701p-1007;
  const double y3 = 0x1.901090126fffep-1007, y4 = 0x1.9010c0101004p-1007;
  const Curve f({{-7.0, y1}, {-7.0, y2}});
  const Curve g({{-7.0, y3}, {-7.0, y4}});
  const double t_hi = ((Rational(y4) - Rational(y1)) / (Rational(y2) - Rational(y1))).to_double();
  const double s_lo = ((Rational(y1) - Rational(y3)) / (Rational(y4) - Rational(y3))).to_double();
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.intersections.empty());
    ASSERT_EQ(r.overlaps.size(), 1u);
    const ParamInterval t = swapped ? r.overlaps[0].s_interval : r.overlaps[0].t_interval;
    const ParamInterval s = swapped ? r.overlaps[0].t_interval : r.overlaps[0].s_interval;
    EXPECT_EQ(t.lo, 0.0);
    EXPECT_NEAR(t.hi, t_hi, 1e-15);
    EXPECT_NEAR(s.lo, s_lo, 1e-15);
    EXPECT_EQ(s.hi, 1.0);
  }
}

}  // namespace
}  // namespace bezier::core
