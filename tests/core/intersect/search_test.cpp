// The search (search.hpp): boxes next to the curves' ends, where rounding of the fast pieces
// decides, and crossings next to a shared end point. Crossings are proved in exact
// rationals, absences by sign arguments on the control points.

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

TEST(Search, ACurveEndingBesideAnotherDoesNotMeetItThere) {
  // f ends at (0, 0x1.4cp-30) coming straight down; g starts at (-0x1.009cfc7c7p-23, 0) and
  // crosses x = 0 at y of about -1.2e-7 (slope -1), 5e-15 of the curves' size 2^24 below
  // f's end: the curves' extensions meet a few ulps of t beyond f's end. The curves do not
  // meet with s < 1e-3: every control point of f has x <= 0 and y >= 0, and y_f = 0 only
  // at t = 0 (the origin). For s in [0, 1e-3], x_g <= 0 only up to s of about 1.7e-15 (g
  // starts 1.2e-7 left of the axis with x_g' about 7e7), and there y_g <= 0 (the term
  // 3 s (1 - s)^2 y_1 with y_1 = -0x1.6a0a00009cfc7p+24 dominates). So a common point
  // would have y = 0: f at the origin, g at its first point, which is not the origin. The
  // fast pieces' rounding (1e-15 of the working scale) hid that gap, and one order
  // reported a box at (1, 2^-49).
  const Curve f({{0x0p+0, 0x0p+0},
                 {-0x1p+24, 0x1p+24},
                 {-0x1.a7a7a7a8p-28, 0x1.307p+24},
                 {0x0p+0, 0x1.4cp-30}});
  const Curve g({{-0x1.009cfc7c7p-23, 0x0p+0},
                 {0x1.6a0a00009cfc7p+24, -0x1.6a0a00009cfc7p+24},
                 {0x1.fffffefep+10, 0x1.fffffefep+9},
                 {-0x1.fbd8p+13, 0x1.001206a8a802p+10}});
  for (const IntersectMethod method :
       {IntersectMethod::hybrid, IntersectMethod::bezier_clipping, IntersectMethod::subdivision}) {
    IntersectOptions options;
    options.method = method;
    options.tolerance = 0x1.0c6f7a0b5ed8dp-20;
    const IntersectionResult a = intersect(f, g, options), b = intersect(g, f, options);
    EXPECT_EQ(a.intersections.size(), b.intersections.size())
        << "method " << static_cast<int>(method);
    for (const Intersection& x : a.intersections) {
      EXPECT_FALSE(x.t > 1 - 1e-3 && x.s < 1e-3) << "method " << static_cast<int>(method);
    }
    for (const Intersection& x : b.intersections) {
      EXPECT_FALSE(x.s > 1 - 1e-3 && x.t < 1e-3) << "method " << static_cast<int>(method);
    }
  }
}

// f(t) = (4t - (4 + 2^19) t^2, -8 t^2) starts where the
// parabola g ends, f(0) = g(1) = (0, 0), and crosses g once more right next to it. With g
// first, hybrid clipping dropped that crossing: the piece of f on s in [0, 2^-17] is closed
// to within its rounding, so its fat line runs along its farthest control point instead of
// its chord, and the band for degree 2 assumed a line through both end points. The second
// crossing is proved here without the kernel: g lies on the parabola h(X) = A1^2 - 4 A0 A2 =
// 0 (Ai the signed area of the triangle X P_j P_k, {i, j, k} = {0, 1, 2}: barycentric
// coordinates, tau_1^2 = 4 tau_0 tau_2 on a quadratic), and h(f(t)) changes sign, in exact
// rationals, between t = 7.6e-6 and 2^-17, where f is within 1e-9 of g(1).
TEST(Search, CrossingNextToASharedEndPointIsFound) {
  const Curve f({{0.0, 0.0}, {2.0, 0.0}, {-0x1p19, -8.0}});
  const Curve g({{376.5, 0.043}, {0.043, -1.0}, {0.0, 0.0}});
  const auto h_of_f = [&](double t) { return on_parabola(g, exact_point(f, t)); };
  const double t_lo = 7.6e-6, t_hi = 0x1p-17;
  ASSERT_LT(h_of_f(t_lo).sign() * h_of_f(t_hi).sign(), 0);
  for (const IntersectMethod method :
       {IntersectMethod::hybrid, IntersectMethod::bezier_clipping, IntersectMethod::subdivision}) {
    IntersectOptions options;
    options.method = method;
    for (const bool swapped : {false, true}) {
      const IntersectionResult r = swapped ? intersect(g, f, options) : intersect(f, g, options);
      ASSERT_EQ(r.status, IntersectStatus::ok);
      ASSERT_EQ(r.intersections.size(), 2u)
          << "method " << static_cast<int>(method) << " swapped " << swapped;
      EXPECT_TRUE(swapped ? covered(r, 1.0, 0.0) : covered(r, 0.0, 1.0));
      bool crossing = false;
      for (const Intersection& x : r.intersections) {
        const double t = swapped ? x.s : x.t, s = swapped ? x.t : x.s;
        crossing = crossing || (t_lo <= t && t <= t_hi && 1 - 1e-9 < s && s < 1);
      }
      EXPECT_TRUE(crossing) << "method " << static_cast<int>(method) << " swapped " << swapped;
      expect_intersection_contract(r, options.tolerance);
    }
  }
}

}  // namespace
}  // namespace bezier::core
