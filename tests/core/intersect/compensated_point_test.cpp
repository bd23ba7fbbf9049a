// evaluate_compensated (core/intersect/compensated_point.hpp): the point must be exact to
// double-double accuracy, checked against de Casteljau in exact rationals on the exact
// working curve hi + lo, and the tangent must be the plain de Casteljau's, bit for bit.

#include <gtest/gtest.h>

#include <vector>

#include "core/intersect/compensated_point.hpp"
#include "core/intersect/working_curve.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::Rational;
using test::RPoint2;

TEST(CompensatedPoint, MatchesExactEvaluationToDoubleDoubleAccuracy) {
  test::Mulberry32 rng(11);
  for (const int degree : {1, 2, 3, 5, 7}) {
    for (int trial = 0; trial < 40; ++trial) {
      std::vector<Point2> pts(static_cast<std::size_t>(degree) + 1);
      // Coordinates far from the frame's grid, so the lo parts are nonzero.
      for (Point2& p : pts) p = {rng.uniform(-3, 5) + 1e-9 * rng.next(), rng.uniform(-2, 7)};
      const Curve curve(pts);
      const WorkingCurve w = to_working(curve, working_frame(curve, curve));
      std::vector<RPoint2> exact;
      for (std::size_t i = 0; i < pts.size(); ++i)
        exact.push_back({Rational(w.x[i]) + Rational(w.x_lo[i]), Rational(w.y[i]) + Rational(w.y_lo[i])});
      const double t = rng.next();
      const RPoint2 want = test::exact_evaluate(exact, Rational(t));
      const CompensatedPoint got = evaluate_compensated(w, t);
      // Double-double level: n^2 u^2 times the magnitude, with room (a plain double
      // evaluation is off by about n u).
      const double u = 0x1p-53;
      const Rational bound(64.0 * degree * degree * u * u * (w.magnitude + w.frame_error));
      EXPECT_LE(abs(Rational(got.x.hi) + Rational(got.x.lo) - want.x), bound) << degree << " " << t;
      EXPECT_LE(abs(Rational(got.y.hi) + Rational(got.y.lo) - want.y), bound) << degree << " " << t;
      const Point2 plain = evaluate_with_tangent(w, t).tangent;
      EXPECT_EQ(got.tangent.x, plain.x);
      EXPECT_EQ(got.tangent.y, plain.y);
    }
  }
}

}  // namespace
}  // namespace bezier::core
