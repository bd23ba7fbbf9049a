// Tests of core/measure/nearest.hpp: the global minimum of |B(t) - q| on [a, b].
//
// Closed forms: the parabola B(t) = (2t - 1, (2t - 1)^2) seen from (0, h) has its nearest
// points at x = ±sqrt(h - 1/2) (two tied minima, distance sqrt(h - 1/4)) when h > 1/2; the
// symmetric cubic (0,0),(2,1),(-1,1),(1,0) crosses itself at t = 1/2 ± sqrt(15)/10, point
// (1/2, 3/10). Properties: the distance is no larger than the distance to any of 10 000
// sampled points, and the answer is the sampled best's basin (a local minimum would not be).

#include "core/measure/nearest.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/curve/evaluate.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

constexpr double kU = 0x1p-53;

TEST(Nearest, SymmetricTargetTiesTwoMinima) {
  const Curve parabola({{-1, 1}, {0, -1}, {1, 1}});
  for (const double h : {1.0, 0.75, 1.25}) {
    const double x = std::sqrt(h - 0.5);
    const auto got = nearest(parabola, Point2{0, h}, 0, 1);
    EXPECT_NEAR(got.distance, std::sqrt(h - 0.25), 4 * kU * std::sqrt(h));
    EXPECT_NEAR(got.t, (1 - x) / 2, 1e-10);
    ASSERT_EQ(got.ties.size(), 1u) << "h " << h;
    EXPECT_NEAR(got.ties[0], (1 + x) / 2, 1e-10);
  }
  // Below h = 1/2 the vertex is the only minimum.
  const auto vertex = nearest(parabola, Point2{0, 0.25}, 0, 1);
  EXPECT_NEAR(vertex.t, 0.5, 1e-10);
  EXPECT_NEAR(vertex.distance, 0.25, 4 * kU);
  EXPECT_TRUE(vertex.ties.empty());
}

TEST(Nearest, GlobalNotLocal) {
  // Off the axis the two minima differ: the global one is on the target's side.
  const Curve parabola({{-1, 1}, {0, -1}, {1, 1}});
  const auto got = nearest(parabola, Point2{0.05, 1.0}, 0, 1);
  EXPECT_GT(got.t, 0.5);
  EXPECT_TRUE(got.ties.empty());
  // From the other side, the mirror answer.
  const auto mirror = nearest(parabola, Point2{-0.05, 1.0}, 0, 1);
  EXPECT_NEAR(mirror.t, 1 - got.t, 1e-12);
  EXPECT_NEAR(mirror.distance, got.distance, 4 * kU);
}

TEST(Nearest, TargetOnASelfIntersectionTiesBothParameters) {
  const Curve loop({{0, 0}, {2, 1}, {-1, 1}, {1, 0}});
  const double t0 = 0.5 - std::sqrt(15.0) / 10;
  const auto got = nearest(loop, Point2{0.5, 0.3}, 0, 1);
  EXPECT_LE(got.distance, 8 * kU * 2);
  EXPECT_NEAR(got.t, t0, 1e-10);
  ASSERT_EQ(got.ties.size(), 1u);
  EXPECT_NEAR(got.ties[0], 1 - t0, 1e-10);
}

TEST(Nearest, TargetsOnTheCurve) {
  const Curve cubic({{0, 0}, {3, 5}, {-2, 4}, {1, -1}});
  for (const double t : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
    const Point2 q = evaluate(cubic, t);
    const auto got = nearest(cubic, q, 0, 1);
    EXPECT_LE(got.distance, 8 * kU * 5) << "t " << t;
    EXPECT_NEAR(got.t, t, 1e-10);
  }
}

TEST(Nearest, EndsAndIntervals) {
  const Curve parabola({{-1, 1}, {0, -1}, {1, 1}});
  // Beyond the end of the curve: the end point.
  const auto end = nearest(parabola, Point2{3, 2}, 0, 1);
  EXPECT_EQ(end.t, 1.0);
  EXPECT_EQ(end.point, (Point2{1, 1}));
  EXPECT_DOUBLE_EQ(end.distance, std::sqrt(5.0));
  // The vertex excluded by the interval: the nearer end of [0, 1/4] (x in [-1, -1/2]).
  const auto piece = nearest(parabola, Point2{0, 0}, 0, 0.25);
  EXPECT_EQ(piece.t, 0.25);
  EXPECT_NEAR(piece.distance, std::hypot(0.5, 0.25), 4 * kU);
}

template <class P>
void check_against_samples(int dimension) {
  test::Mulberry32 rng(static_cast<std::uint32_t>(40 + dimension));
  for (int i = 0; i < 30; ++i) {
    const int degree = 2 + i % 8;
    std::vector<P> pts;
    for (int k = 0; k <= degree; ++k) {
      P p;
      for (int j = 0; j < dimension; ++j) (&p.x)[j] = rng.uniform(-1, 1);
      pts.push_back(p);
    }
    const BasicCurve<P> curve(pts);
    P q;
    for (int j = 0; j < dimension; ++j) (&q.x)[j] = rng.uniform(-1.5, 1.5);
    const auto got = nearest(curve, q, 0, 1);
    double best = INFINITY, best_t = 0;
    constexpr int kSamples = 10000;
    for (int s = 0; s <= kSamples; ++s) {
      const double t = static_cast<double>(s) / kSamples;
      const double d = length(evaluate(curve, t) - q);
      if (d < best) {
        best = d;
        best_t = t;
      }
    }
    ASSERT_LE(got.distance, best * (1 + 1e-13)) << "curve " << i;
    // Refine the best sample by golden-section search on its neighbourhood: the true
    // minimum near it cannot be below the answer.
    double lo = std::max(0.0, best_t - 1.0 / kSamples), hi = std::min(1.0, best_t + 1.0 / kSamples);
    for (int k = 0; k < 200; ++k) {
      const double m1 = lo + (hi - lo) * 0.381966, m2 = hi - (hi - lo) * 0.381966;
      if (length(evaluate(curve, m1) - q) < length(evaluate(curve, m2) - q)) {
        hi = m2;
      } else {
        lo = m1;
      }
    }
    const double refined = length(evaluate(curve, lo) - q);
    EXPECT_LE(got.distance, refined + 1e-13 * refined + 8 * kU) << "curve " << i;
    EXPECT_NEAR(got.distance, length(got.point - q), 1e-12 * got.distance + 8 * kU);
  }
}

TEST(Nearest, NoSampleIsCloser2D) { check_against_samples<Point2>(2); }
TEST(Nearest, NoSampleIsCloser3D) { check_against_samples<Point3>(3); }

TEST(Nearest, InvariantUnderReversalTranslationAndScale) {
  const Curve cubic({{0, 0}, {3, 5}, {-2, 4}, {1, -1}});
  const Point2 q{0.3, 1.7};
  const auto got = nearest(cubic, q, 0, 1);
  const auto back = nearest(reversed(cubic), q, 0, 1);
  EXPECT_NEAR(back.t, 1 - got.t, 1e-12);
  EXPECT_NEAR(back.distance, got.distance, 1e-13 * got.distance);
  std::vector<Point2> moved;
  for (const Point2 p : cubic.points()) moved.push_back(0x1p12 * p + Point2{64, -32});
  const auto far = nearest(Curve(moved), 0x1p12 * q + Point2{64, -32}, 0, 1);
  EXPECT_NEAR(far.t, got.t, 1e-12);
  EXPECT_NEAR(far.distance, 0x1p12 * got.distance, 1e-13 * 0x1p12 * got.distance);
}

TEST(Nearest, CoordinatesNearTheDoubleRange) {
  // The parabola scaled by 2^1020 (its products (B - q) . B' overflow doubles): the tie
  // and the distance scale exactly.
  const double s = 0x1p1020;
  const Curve parabola({{-s, s}, {0, -s}, {s, s}});
  const auto got = nearest(parabola, Point2{0, s}, 0, 1);
  EXPECT_NEAR(got.distance / s, std::sqrt(0.75), 4 * kU);
  EXPECT_NEAR(got.t, (1 - std::sqrt(0.5)) / 2, 1e-10);
  ASSERT_EQ(got.ties.size(), 1u);
}

TEST(Nearest, PointCurve) {
  const auto got = nearest(Curve({{1, 1}, {1, 1}, {1, 1}}), Point2{4, 5}, 0.25, 0.75);
  EXPECT_EQ(got.t, 0.25);
  EXPECT_EQ(got.distance, 5.0);
  EXPECT_TRUE(got.ties.empty());
}

TEST(Nearest, SpaceCurve) {
  // (5t, 3t^2, 4t^2) is the parabola (5t, 5t^2) placed in the plane spanned by (1, 0, 0)
  // and (0, 3/5, 4/5): targets in that plane have the planar curve's answers.
  const Curve3 space({{0, 0, 0}, {2.5, 0, 0}, {5, 3, 4}});
  const Curve plane({{0, 0}, {2.5, 0}, {5, 5}});
  for (const double h : {0.5, 2.0, 4.0}) {
    const auto a = nearest(space, Point3{1, 0.6 * h, 0.8 * h}, 0, 1);
    const auto b = nearest(plane, Point2{1, h}, 0, 1);
    EXPECT_NEAR(a.t, b.t, 1e-12);
    EXPECT_NEAR(a.distance, b.distance, 1e-13 * b.distance + 8 * kU * 5);
  }
}

}  // namespace
}  // namespace bezier::core
