// Tests of core/measure/bounds.hpp: the tight box of a curve piece.
//
// Closed forms: a quadratic's and a cubic's extremes from the roots of B' (solved by hand
// or by the quadratic formula in long double); properties on random curves: the box holds
// every sampled point, and each face is within 2 ulps of a value attained at an end or at a
// reported critical parameter.

#include "core/measure/bounds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/curve/evaluate.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

/// lo <= exact and exact - lo within 2 ulps of exact (a lower face); mirrored for upper.
/// `slack` is the compensated evaluation's second-order bound (bounds.hpp), which decides
/// only where the extreme is near zero against the control points.
void expect_lower_face(double face, long double exact, double slack = 0.0) {
  EXPECT_LE(static_cast<long double>(face), exact);
  const double e = static_cast<double>(exact) - slack;
  EXPECT_GE(face, std::nextafter(std::nextafter(e, -INFINITY), -INFINITY)) << "exact " << e;
}
void expect_upper_face(double face, long double exact, double slack = 0.0) {
  EXPECT_GE(static_cast<long double>(face), exact);
  const double e = static_cast<double>(exact) + slack;
  EXPECT_LE(face, std::nextafter(std::nextafter(e, INFINITY), INFINITY)) << "exact " << e;
}

TEST(Bounds, QuadraticArch) {
  // x = 2t, y = 4t(1 - t): top 1 at t = 1/2, the ends on y = 0.
  const auto box = bounds(Curve({{0, 0}, {1, 2}, {2, 0}}), 0, 1);
  EXPECT_EQ(box.min, (Point2{0, 0}));
  EXPECT_EQ(box.max.x, 2.0);
  expect_upper_face(box.max.y, 1.0L);
  EXPECT_TRUE(box.critical[0].empty());
  ASSERT_EQ(box.critical[1].size(), 1u);
  EXPECT_EQ(box.critical[1][0], 0.5);
  // Not the control polygon's box (which reaches y = 2).
  EXPECT_LT(box.max.y, 1.5);
}

TEST(Bounds, CubicExtremesFromQuadraticFormula) {
  const Curve cubic({{0, 0}, {3, 5}, {-2, 4}, {1, -1}});
  const auto box = bounds(cubic, 0, 1);
  // Each coordinate of B' = 3 [(1-t)^2 d0 + 2t(1-t) d1 + t^2 d2], d_i = P_{i+1} - P_i:
  // a t^2 + b t + c with a = d0 - 2 d1 + d2, b = 2 (d1 - d0), c = d0.
  const auto extremes = [&](auto coord) {
    const long double d0 = coord(cubic[1]) - coord(cubic[0]), d1 = coord(cubic[2]) - coord(cubic[1]),
                      d2 = coord(cubic[3]) - coord(cubic[2]);
    const long double a = d0 - 2 * d1 + d2, b = 2 * (d1 - d0), c = d0;
    const long double disc = std::sqrt(b * b - 4 * a * c);
    std::vector<long double> ts;
    for (const long double t : {(-b - disc) / (2 * a), (-b + disc) / (2 * a)}) {
      if (0 < t && t < 1) ts.push_back(t);
    }
    std::sort(ts.begin(), ts.end());
    long double lo = std::min<long double>(coord(cubic[0]), coord(cubic[3])), hi = std::max<long double>(coord(cubic[0]), coord(cubic[3]));
    for (const long double t : ts) {
      const long double s = 1 - t;
      const long double v = s * s * s * coord(cubic[0]) + 3 * s * s * t * coord(cubic[1]) +
                            3 * s * t * t * coord(cubic[2]) + t * t * t * coord(cubic[3]);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    return std::tuple{lo, hi, ts};
  };
  const auto [xlo, xhi, xts] = extremes([](Point2 p) { return p.x; });
  const auto [ylo, yhi, yts] = extremes([](Point2 p) { return p.y; });
  // x(3/4) = 0 exactly, by cancellation of control points up to 3: the slack decides there.
  const double u = 0x1p-53;
  expect_lower_face(box.min.x, xlo, 2 * 16 * u * u * 3);
  expect_upper_face(box.max.x, xhi);
  expect_lower_face(box.min.y, ylo);
  expect_upper_face(box.max.y, yhi);
  ASSERT_EQ(box.critical[0].size(), xts.size());
  ASSERT_EQ(box.critical[1].size(), yts.size());
  for (std::size_t i = 0; i < xts.size(); ++i) EXPECT_NEAR(box.critical[0][i], static_cast<double>(xts[i]), 1e-15);
  for (std::size_t i = 0; i < yts.size(); ++i) EXPECT_NEAR(box.critical[1][i], static_cast<double>(yts[i]), 1e-15);
}

TEST(Bounds, DoubleRootReportedOnce) {
  // x = (t - 1/2)^3 / ... : x' = 3 (t - 1/2)^2 has a double root at 1/2 (no extreme there).
  const auto box = bounds(Curve({{-0.125, 0}, {0.125, 1}, {-0.125, 2}, {0.125, 3}}), 0, 1);
  ASSERT_EQ(box.critical[0].size(), 1u);
  EXPECT_NEAR(box.critical[0][0], 0.5, 1e-5);
  EXPECT_EQ(box.min.x, -0.125);
  EXPECT_EQ(box.max.x, 0.125);
}

TEST(Bounds, SubIntervalAndPoint) {
  const Curve arch({{0, 0}, {1, 2}, {2, 0}});
  // On [0, 1/4] the arch rises: y from 0 to 3/4, x from 0 to 1/2 (exact in doubles).
  const auto piece = bounds(arch, 0, 0.25);
  EXPECT_EQ(piece.min, (Point2{0, 0}));
  expect_upper_face(piece.max.x, 0.5L);
  expect_upper_face(piece.max.y, 0.75L);
  EXPECT_TRUE(piece.critical[1].empty());
  const auto point = bounds(arch, 0.5, 0.5);
  expect_lower_face(point.min.x, 1.0L);
  expect_upper_face(point.max.x, 1.0L);
  expect_upper_face(point.max.y, 1.0L);
}

TEST(Bounds, DoubleRootAtTheIntervalsEndIsTheEnd) {
  // x = (2t - 1)^3 (control x -1, 1, -1, 1): x' = 6 (2t - 1)^2 vanishes twice at t = 1/2, the
  // start of [1/2, 1], where x = 0 exactly; x rises to 1 at t = 1. No critical t in (1/2, 1).
  const Curve curve({{-1, -2}, {1, 6}, {-1, 3}, {1, 2}});
  const auto box = bounds(curve, 0.5, 1);
  EXPECT_TRUE(box.critical[0].empty());
  EXPECT_EQ(box.min.x, 0.0);
  EXPECT_EQ(box.max.x, 1.0);
  // Mirrored: x = (1 - 2t)^3 on [0, 1/2] ends at its double root.
  const Curve reversed({{1, 2}, {-1, 3}, {1, 6}, {-1, -2}});
  const auto mirrored = bounds(reversed, 0, 0.5);
  EXPECT_TRUE(mirrored.critical[0].empty());
  EXPECT_EQ(mirrored.min.x, 0.0);
  EXPECT_EQ(mirrored.max.x, 1.0);
}

TEST(Bounds, SlopeZeroAtAnEndOfTheCurve) {
  // y = 6t^2 - 2t^3 (control y 0, 0, 2, 4): y' = 6t (2 - t) vanishes at t = 0 only; x with
  // control 2, 5, 6, 6 has x' = 3 (1 - t)(3 - t), zero at t = 1 only. The box is the end
  // points' box exactly, with no critical parameter.
  const auto box = bounds(Curve({{2, 0}, {5, 0}, {6, 2}, {6, 4}}), 0, 1);
  EXPECT_TRUE(box.critical[0].empty());
  EXPECT_TRUE(box.critical[1].empty());
  EXPECT_EQ(box.min, (Point2{2, 0}));
  EXPECT_EQ(box.max, (Point2{6, 4}));
}

TEST(Bounds, InteriorEndsAreExactWhenTheValueIsADouble) {
  // x = t^2 on [1/4, 3/4] (control x 0, 0, 1): 1/16 and 9/16 are doubles, so the faces are
  // those values themselves.
  const auto box = bounds(Curve({{0, 0}, {0, 1}, {1, 1}}), 0.25, 0.75);
  EXPECT_EQ(box.min.x, 0.0625);
  EXPECT_EQ(box.max.x, 0.5625);
  // y = 2t - t^2: at 1/3 the exact value 5/9 is no double; the faces bracket it tightly.
  const double third = 1.0 / 3.0;
  const auto piece = bounds(Curve({{0, 0}, {0, 1}, {1, 1}}), third, 0.75);
  const long double y = 2.0L * third - static_cast<long double>(third) * third;
  EXPECT_LE(static_cast<long double>(piece.min.y), y);
  EXPECT_GE(piece.min.y, std::nextafter(static_cast<double>(y), -INFINITY));
}

template <class P>
void check_random(int dimension) {
  test::Mulberry32 rng(static_cast<std::uint32_t>(31 + dimension));
  for (int i = 0; i < 40; ++i) {
    const int degree = 1 + i % 10;
    std::vector<P> pts;
    for (int k = 0; k <= degree; ++k) {
      P p;
      double* c = &p.x;
      for (int j = 0; j < dimension; ++j) c[j] = rng.uniform(-100, 100);
      pts.push_back(p);
    }
    const BasicCurve<P> curve(pts);
    const double a = rng.next() * 0.5, b = 0.5 + rng.next() * 0.5;
    const auto box = bounds(curve, a, b);
    const double* lo = &box.min.x;
    const double* hi = &box.max.x;
    for (int s = 0; s <= 2000; ++s) {
      const P q = evaluate(curve, a + (b - a) * s / 2000.0);
      const double* c = &q.x;
      for (int j = 0; j < dimension; ++j) {
        ASSERT_LE(lo[j], c[j]) << "curve " << i << " axis " << j;
        ASSERT_GE(hi[j], c[j]) << "curve " << i << " axis " << j;
      }
    }
    // Each face is attained (within 2 ulps) at an end or a critical parameter.
    for (int j = 0; j < dimension; ++j) {
      std::vector<double> ts = {a, b};
      ts.insert(ts.end(), box.critical[static_cast<std::size_t>(j)].begin(), box.critical[static_cast<std::size_t>(j)].end());
      double attained_lo = INFINITY, attained_hi = -INFINITY;
      for (const double t : ts) {
        ASSERT_TRUE(a <= t && t <= b);
        const P q = evaluate(curve, t);
        attained_lo = std::min(attained_lo, (&q.x)[j]);
        attained_hi = std::max(attained_hi, (&q.x)[j]);
      }
      EXPECT_GE(lo[j], std::nextafter(std::nextafter(attained_lo, -INFINITY), -INFINITY));
      EXPECT_LE(hi[j], std::nextafter(std::nextafter(attained_hi, INFINITY), INFINITY));
      EXPECT_TRUE(std::is_sorted(box.critical[static_cast<std::size_t>(j)].begin(), box.critical[static_cast<std::size_t>(j)].end()));
    }
  }
}

TEST(Bounds, RandomCurvesContainSamplesAndAttainFaces2D) { check_random<Point2>(2); }
TEST(Bounds, RandomCurvesContainSamplesAndAttainFaces3D) { check_random<Point3>(3); }

TEST(Bounds, CoordinatesNearTheDoubleRange) {
  // x = 1e308 (2t - 3t^2), y = -x: extremes ±1e308/3 at t = 1/3, although the hodograph's
  // points (2e308, ...) overflow doubles.
  const auto box = bounds(Curve({{0, 0}, {1e308, -1e308}, {-1e308, 1e308}}), 0, 1);
  expect_upper_face(box.max.x, 1e308L / 3);
  expect_lower_face(box.min.y, -1e308L / 3, 2 * 9 * 0x1p-106 * 1e308);
  ASSERT_EQ(box.critical[0].size(), 1u);
  EXPECT_NEAR(box.critical[0][0], 1.0 / 3, 1e-15);
}

TEST(Bounds, InvariantUnderReversal) {
  const Curve cubic({{0, 0}, {3, 5}, {-2, 4}, {1, -1}});
  const auto forward = bounds(cubic, 0, 1), backward = bounds(reversed(cubic), 0, 1);
  EXPECT_EQ(forward.min, backward.min);
  EXPECT_EQ(forward.max, backward.max);
  for (std::size_t k = 0; k < 2; ++k) {
    ASSERT_EQ(forward.critical[k].size(), backward.critical[k].size());
    for (std::size_t i = 0; i < forward.critical[k].size(); ++i)
      EXPECT_NEAR(forward.critical[k][i], 1 - backward.critical[k][forward.critical[k].size() - 1 - i], 1e-15);
  }
}

}  // namespace
}  // namespace bezier::core
