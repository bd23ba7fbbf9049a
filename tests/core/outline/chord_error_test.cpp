// Tests of core/outline/chord_error.hpp: the bracket of a curve piece's distance to its chord.
//
// Closed forms: a parabola's chord over [a, b] is parallel to the tangent at the middle and
// stands off by |cross(B'', u)| (b - a)^2 / 8 (u the chord's unit direction), reached at the
// middle; a collinear curve that runs past its end, x(t) = 4t - 3t^2 on [0, 1], goes out to
// 4/3 while its chord ends at 1, so its distance is 1/3; a curve crossing its chord.

#include "core/outline/chord_error.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/base/curve.hpp"
#include "core/outline/tuning.hpp"

namespace bezier::outline {
namespace {

using core::Curve;
using core::Point2;

TEST(ChordError, ParabolaBracketHoldsTheClosedForm) {
  // B(t) = (2t - 1, (2t - 1)^2): B'' = (0, 8).
  const Curve parabola({{-1, 1}, {0, -1}, {1, 1}});
  for (const auto& [a, b] : {std::pair{0.0, 1.0}, std::pair{0.25, 0.5}, std::pair{0.1, 0.9}}) {
    const double x0 = 2 * a - 1, x1 = 2 * b - 1;
    const Point2 chord{x1 - x0, x1 * x1 - x0 * x0};
    const double exact =
        std::fabs(core::cross(Point2{0, 8}, chord)) / core::length(chord) * (b - a) * (b - a) / 8;
    const double tolerance = 2 * exact;
    const ChordCheck check = check_chord(parabola.points(), a, b, tolerance, 0.0);
    EXPECT_TRUE(check.within);
    EXPECT_LE(check.lower, exact * (1 + 1e-12));
    EXPECT_GE(check.upper, exact * (1 - 1e-12));
    EXPECT_LE(check.upper - check.lower, outline_tuning::kChordResolution * tolerance * (1 + 1e-9));
    // Just below the distance: not within.
    EXPECT_FALSE(check_chord(parabola.points(), a, b, exact * (1 - 1e-2), 0.0).within);
  }
}

TEST(ChordError, CurveRunningPastTheChordsEnd) {
  const Curve fold({{0, 0}, {2, 0}, {1, 0}});
  const ChordCheck check = check_chord(fold.points(), 0.0, 1.0, 0.5, 0.0);
  EXPECT_TRUE(check.within);
  EXPECT_LE(check.lower, 1.0 / 3 + 1e-15);
  EXPECT_GE(check.upper, 1.0 / 3 - 1e-15);
  EXPECT_FALSE(check_chord(fold.points(), 0.0, 1.0, 0.33, 0.0).within);
}

TEST(ChordError, ZeroLengthChordIsTheDistanceToItsPoint) {
  // A closed quadratic: B(0) = B(1) = (0, 0), farthest at t = 1/2: (0, 1) (the control point
  // (0, 2) halfway).
  const Curve loop({{0, 0}, {0, 2}, {0, 0}});
  const ChordCheck check = check_chord(loop.points(), 0.0, 1.0, 1.5, 0.0);
  EXPECT_TRUE(check.within);
  EXPECT_LE(check.lower, 1.0);
  EXPECT_GE(check.upper, 1.0);
  EXPECT_FALSE(check_chord(loop.points(), 0.0, 1.0, 0.99, 0.0).within);
}

TEST(ChordError, MarginIsTakenFromTheTolerance) {
  const Curve parabola({{-1, 1}, {0, -1}, {1, 1}});
  // Distance 1 over [0, 1] (the chord y = 1, the vertex (0, 0)).
  EXPECT_TRUE(check_chord(parabola.points(), 0.0, 1.0, 1.01, 0.0).within);
  EXPECT_FALSE(check_chord(parabola.points(), 0.0, 1.0, 1.01, 0.02).within);
}

TEST(ChordError, WorkGrowsWithTheHalvings) {
  const Curve cubic({{0, 0}, {1, 2}, {2, -2}, {3, 0}});
  const ChordCheck coarse = check_chord(cubic.points(), 0.0, 1.0, 10.0, 0.0);
  const ChordCheck tight = check_chord(cubic.points(), 0.2, 0.3, 1e-3, 0.0);
  EXPECT_GT(coarse.work, 0);
  EXPECT_GT(tight.work, coarse.work);
}

}  // namespace
}  // namespace bezier::outline
