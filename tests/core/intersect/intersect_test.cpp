// The entry point (intersect.hpp): a curve handled as a point, and a point curve under every
// method. The expected answers are Intersection's contract and the exact roots.

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

// A curve smaller than about 2^-44 of the other is handled
// as a point, its parameter interval is [0, 1] (or a half of it), and the intersection is
// still flagged `resolved`. Here f is the segment y = 2x of length ~2^-48 through the
// origin and g the segment y = x / 2 through it: one transversal crossing, at t = s = 1/2.
TEST(Intersect, TinyCurveIsNotReportedResolvedWithItsWholeInterval) {
  const Curve f({{-0x1p-50, -0x1p-49}, {0.0, 0.0}, {0x1p-50, 0x1p-49}});
  const Curve g({{-1.0, -0.5}, {1.0, 0.5}});
  IntersectOptions options;
  options.tolerance = 1e-9;
  const IntersectionResult r = intersect(f, g, options);
  ASSERT_EQ(r.status, IntersectStatus::ok);
  ASSERT_EQ(r.intersections.size(), 1u);
  EXPECT_TRUE(covered(r, 0.5, 0.5));
  expect_intersection_contract(r, options.tolerance);
}

// Bézier
// clipping with a degree-0 curve called fat_curve_operator(0, 0), whose assertion k >= 1
// aborts (release builds, these tests', skip the assertion; the fuzz build checks it). The
// point (0, 0) is the end f(1) of the segment f(t) = (1 - t, 0), so t = 1 exactly, and g's
// parameter is free: one contact, s in [0, 1].
TEST(Intersect, BezierClippingAcceptsAPointCurve) {
  const Curve f({{1.0, 0.0}, {0.0, 0.0}});
  const Curve g(std::vector<Point2>{{0.0, 0.0}});
  IntersectOptions options;
  options.method = IntersectMethod::bezier_clipping;
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f, options) : intersect(f, g, options);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    ASSERT_EQ(r.intersections.size(), 1u);
    const Intersection& x = r.intersections[0];
    const ParamInterval on_f = swapped ? x.s_interval : x.t_interval;
    const ParamInterval on_g = swapped ? x.t_interval : x.s_interval;
    EXPECT_TRUE(on_f.contains(1.0));
    EXPECT_LT(on_f.width(), options.tolerance);
    EXPECT_EQ(on_g, (ParamInterval{0.0, 1.0}));
    EXPECT_EQ(x.kind, IntersectionKind::degenerate);
    EXPECT_FALSE(x.resolved);
    expect_intersection_contract(r, options.tolerance);
  }
}

}  // namespace
}  // namespace bezier::core
