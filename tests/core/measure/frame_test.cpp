// Tests of core/measure/frame.hpp: unit tangent, normal and curvature.
//
// Closed forms: the parabola B(t) = (t, t^2) (control points (0,0), (1/2,0), (1,1)) has
// tangent (1, 2t)/sqrt(1 + 4t^2) and signed curvature 2 / (1 + 4t^2)^(3/2); the twisted cubic
// (3t, 3t^2, 3t^3) has |B' x B''| / |B'|^3 from its derivatives by hand; a cusp has no frame.

#include "core/measure/frame.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bezier::core {
namespace {

constexpr double kUlps = 8 * 0x1p-53;

TEST(Frame, ParabolaVertexHasCurvatureTwo) {
  const Curve parabola({{0, 0}, {0.5, 0}, {1, 1}});
  const auto f = frame(parabola, 0.0);
  ASSERT_TRUE(f.has_value());
  EXPECT_EQ(f->tangent, (Point2{1, 0}));
  ASSERT_TRUE(f->normal.has_value());
  EXPECT_EQ(*f->normal, (Point2{0, 1}));
  EXPECT_NEAR(f->curvature, 2.0, 2 * kUlps);
}

TEST(Frame, ParabolaClosedFormAlongTheCurve) {
  const Curve parabola({{0, 0}, {0.5, 0}, {1, 1}});
  for (int k = 0; k <= 8; ++k) {
    const long double t = k / 8.0L;
    const long double speed = std::sqrt(1 + 4 * t * t);
    const auto f = frame(parabola, static_cast<double>(t));
    ASSERT_TRUE(f.has_value());
    EXPECT_NEAR(f->tangent.x, static_cast<double>(1 / speed), kUlps);
    EXPECT_NEAR(f->tangent.y, static_cast<double>(2 * t / speed), kUlps);
    EXPECT_NEAR(f->normal->x, static_cast<double>(-2 * t / speed), kUlps);
    EXPECT_NEAR(f->normal->y, static_cast<double>(1 / speed), kUlps);
    const long double curvature = 2 / (speed * speed * speed);
    EXPECT_NEAR(f->curvature, static_cast<double>(curvature), kUlps * static_cast<double>(curvature));
  }
}

TEST(Frame, CurvatureIsSignedAndFollowsReversalAndScale) {
  const Curve parabola({{0, 0}, {0.5, 0}, {1, 1}});
  const auto backwards = frame(reversed(parabola), 1.0);
  ASSERT_TRUE(backwards.has_value());
  EXPECT_EQ(backwards->tangent, (Point2{-1, 0}));
  EXPECT_EQ(*backwards->normal, (Point2{0, -1}));
  EXPECT_NEAR(backwards->curvature, -2.0, 2 * kUlps);
  // Scaled by 2^10 and moved: curvature / 2^10, the same tangent.
  const double s = 0x1p10;
  const auto scaled = frame(Curve({{5, 7}, {5 + 0.5 * s, 7}, {5 + s, 7 + s}}), 0.0);
  ASSERT_TRUE(scaled.has_value());
  EXPECT_EQ(scaled->tangent, (Point2{1, 0}));
  EXPECT_NEAR(scaled->curvature, 2.0 / s, 2 * kUlps / s);
}

TEST(Frame, NoFrameWhereTheDerivativeVanishes) {
  // The cusp cubic: B' = 3 (1 - 2t) ((1 - 2t), 1) is zero at t = 1/2.
  const Curve cusp({{0, 0}, {1, 1}, {0, 1}, {1, 0}});
  EXPECT_FALSE(frame(cusp, 0.5).has_value());
  EXPECT_TRUE(frame(cusp, 0.5 + 1e-6).has_value());
  // A doubled first control point: B'(0) = 0.
  EXPECT_FALSE(frame(Curve({{0, 0}, {0, 0}, {1, 1}}), 0.0).has_value());
  // A curve that is one point.
  EXPECT_FALSE(frame(Curve({{2, 3}, {2, 3}, {2, 3}}), 0.25).has_value());
  // The same cusp at another scale.
  const Curve big({{0, 0}, {1e8, 1e8}, {0, 1e8}, {1e8, 0}});
  EXPECT_FALSE(frame(big, 0.5).has_value());
  EXPECT_FALSE(frame(Curve3({{0, 0, 0}, {1, 1, 1}, {0, 1, 1}, {1, 0, 0}}), 0.5).has_value());
}

TEST(Frame, CoordinatesNearTheDoubleRange) {
  // The parabola scaled by 2^1020: curvature 2 / 2^1020 at the vertex, though |B'|^3
  // overflows doubles.
  const double s = 0x1p1020;
  const auto f = frame(Curve({{0, 0}, {0.5 * s, 0}, {s, s}}), 0.0);
  ASSERT_TRUE(f.has_value());
  EXPECT_EQ(f->tangent, (Point2{1, 0}));
  EXPECT_NEAR(f->curvature * s, 2.0, 2 * kUlps);
}

TEST(Frame, TwistedCubic) {
  // B = (3t, 3t^2, 3t^3): control points by the power-to-Bernstein map.
  const Curve3 twisted({{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 3, 3}});
  for (int k = 0; k <= 4; ++k) {
    const long double t = k / 4.0L;
    const long double d1[3] = {3, 6 * t, 9 * t * t}, d2[3] = {0, 6, 18 * t};
    const long double c[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                              d1[0] * d2[1] - d1[1] * d2[0]};
    const long double speed = std::sqrt(d1[0] * d1[0] + d1[1] * d1[1] + d1[2] * d1[2]);
    const long double bend = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    // (B' x B'') x B'
    const long double nv[3] = {c[1] * d1[2] - c[2] * d1[1], c[2] * d1[0] - c[0] * d1[2],
                               c[0] * d1[1] - c[1] * d1[0]};
    const long double nl = std::sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
    const auto f = frame(twisted, static_cast<double>(t));
    ASSERT_TRUE(f.has_value());
    const long double curvature = bend / (speed * speed * speed);
    EXPECT_NEAR(f->curvature, static_cast<double>(curvature), kUlps * static_cast<double>(curvature));
    EXPECT_NEAR(f->tangent.x, static_cast<double>(d1[0] / speed), kUlps);
    EXPECT_NEAR(f->tangent.y, static_cast<double>(d1[1] / speed), kUlps);
    EXPECT_NEAR(f->tangent.z, static_cast<double>(d1[2] / speed), kUlps);
    ASSERT_TRUE(f->normal.has_value());
    EXPECT_NEAR(f->normal->x, static_cast<double>(nv[0] / nl), kUlps);
    EXPECT_NEAR(f->normal->y, static_cast<double>(nv[1] / nl), kUlps);
    EXPECT_NEAR(f->normal->z, static_cast<double>(nv[2] / nl), kUlps);
  }
}

TEST(Frame, SpaceParabolaAndStraightLine) {
  // (5t, 3t^2, 4t^2) = 5 (t, t^2 (3/5, 4/5)): a parabola of curvature 2/5 at its vertex.
  const auto f = frame(Curve3({{0, 0, 0}, {2.5, 0, 0}, {5, 3, 4}}), 0.0);
  ASSERT_TRUE(f.has_value());
  EXPECT_EQ(f->tangent, (Point3{1, 0, 0}));
  ASSERT_TRUE(f->normal.has_value());
  EXPECT_NEAR(f->normal->x, 0.0, kUlps);
  EXPECT_NEAR(f->normal->y, 0.6, kUlps);
  EXPECT_NEAR(f->normal->z, 0.8, kUlps);
  EXPECT_NEAR(f->curvature, 0.4, kUlps);
  // A straight line in space: curvature 0 and no principal normal.
  const auto line = frame(Curve3({{0, 0, 0}, {1, 2, 2}, {2, 4, 4}}), 0.3);
  ASSERT_TRUE(line.has_value());
  EXPECT_EQ(line->curvature, 0.0);
  EXPECT_FALSE(line->normal.has_value());
  EXPECT_NEAR(line->tangent.y, 2.0 / 3.0, kUlps);
}

}  // namespace
}  // namespace bezier::core
