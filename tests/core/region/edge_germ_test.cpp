#include "core/region/edge_germ.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "core/base/curve.hpp"
#include "core/curve/evaluate.hpp"
#include "core/region/boolean_tuning.hpp"

namespace bezier::region {
namespace {

using core::Point2;

/// Whether ccw_angle puts `to` just counter-clockwise of `from` (a tie-zone answer in
/// (0, kTangentTieAngle)) or just clockwise (in (2 pi - kTangentTieAngle, 2 pi)).
bool just_counter_clockwise(const EdgeGerm& from, const EdgeGerm& to) {
  const double a = ccw_angle(from, to);
  EXPECT_NE(a, 0.0);
  EXPECT_TRUE(a < kTangentTieAngle || a > 2.0 * std::numbers::pi - kTangentTieAngle) << a;
  return a < kTangentTieAngle;
}

TEST(EdgeGerm, ShortPieceLeavingAtATinyAngleIsOrderedByWhereItLies) {
  // A line from the origin along -x, and a short quadratic leaving the origin 5e-7 radians
  // clockwise of it (heading -x, rising) and bending back to the left (its curvature is
  // positive): y(t) = 5e-13 (2t - t^2) > 0 on (0, 1], so the quadratic lies above the line
  // (clockwise of it, seen heading -x) all the way to its end, where it stops.
  const core::Curve line({{0, 0}, {-1, 0}});
  const core::Curve piece({{0, 0}, {-1e-6, 5e-13}, {-2e-6, 5e-13}});
  for (const double t : {0.25, 0.5, 1.0}) ASSERT_GT(core::evaluate(piece, t).y, 0.0);
  const EdgeGerm g_line = germ_at_start(line), g_piece = germ_at_start(piece);
  ASSERT_GT(g_piece.turn, 0.0);  // it bends left of its tangent
  EXPECT_FALSE(just_counter_clockwise(g_line, g_piece));
  EXPECT_TRUE(just_counter_clockwise(g_piece, g_line));
}

TEST(EdgeGerm, CurvesThatTouchAreOrderedByCurvature) {
  // Two arcs leaving the origin along +x with tangents 1e-8 radians apart (the error of a
  // located tangency) and curvatures 1 and 2: the more curved one bends left of the other at
  // every distance their reaches allow beyond 2e-8, so it lies counter-clockwise, whatever
  // the tiny angle says.
  const double tilt = 1e-8;
  // Quadratics with B'(0) = 2 P1 and curvature cross(B', B'') / |B'|^3, B'' = 2 (P2 - 2 P1).
  const core::Curve flatter({{0, 0}, {0.5, 0.5 * tilt}, {1, 0.5}});  // curvature about 1
  const core::Curve rounder({{0, 0}, {0.5, 0}, {1, 1}});             // curvature about 2
  const EdgeGerm g_flat = germ_at_start(flatter), g_round = germ_at_start(rounder);
  ASSERT_GT(g_flat.angle, g_round.angle);
  ASSERT_GT(g_round.turn, g_flat.turn);
  EXPECT_TRUE(just_counter_clockwise(g_flat, g_round));
  EXPECT_FALSE(just_counter_clockwise(g_round, g_flat));
}

TEST(EdgeGerm, EqualGermsTie) {
  const core::Curve c({{0, 0}, {1, 1}, {2, 0}});
  EXPECT_EQ(ccw_angle(germ_at_start(c), germ_at_start(c)), 0.0);
}

}  // namespace
}  // namespace bezier::region
