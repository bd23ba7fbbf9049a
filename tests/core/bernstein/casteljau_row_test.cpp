// Tests of core/bernstein/casteljau_row.hpp against de Casteljau's triangle in exact
// rationals (tests/support/exact_bezier.hpp). The contract checked, per coordinate, is the
// compensated one: |value + error - exact| <= u |exact| + c S with c = O(n^2 u^2)
// (test::compensated_coefficient) and S the triangle run on |P_i| (the condition scale).

#include "core/bernstein/casteljau_row.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <vector>

#include "core/base/curve.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::Rational;

template <class P>
auto exact_of(const TwoTerm<P>& e) {
  return test::exact(e.hi) + test::exact(e.lo);
}

TEST(CasteljauRow, StartsWithTheExactControlPoints) {
  const std::vector<Point2> pts{{1, 2}, {0.1, -3}, {5e10, 7e-10}};
  const CasteljauRow<Point2> row{std::span<const Point2>(pts)};
  ASSERT_EQ(row.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(row.point(i), pts[i]);
    EXPECT_EQ(row.entry(i).lo, Point2{});
  }
}

// Every intermediate row, and the last entry B(t), against the exact triangle; the row of
// values alone is the plain algorithm (lerp) bit for bit.
template <class P>
void check_rows(std::uint32_t seed, int max_degree, double lo, double hi) {
  test::Mulberry32 rng(seed);
  for (int n = 1; n <= max_degree; ++n) {
    for (int draw = 0; draw < 4; ++draw) {
      const auto curve = test::random_curve<P>(rng, n, lo, hi);
      const double t = draw == 0 ? 0.5 : rng.next();
      SCOPED_TRACE(test::case_name(seed, n, t));
      const auto exact_pts = test::exact_points(curve);
      const std::vector<P> plain_start(curve.points().begin(), curve.points().end());
      std::vector<P> plain = plain_start;
      CasteljauRow<P> row{curve.points()};
      std::vector<Rational> ts;
      const double c = test::compensated_coefficient(n);
      for (int k = 1; k <= n; ++k) {
        row.casteljau_step(t);
        ts.push_back(Rational(t));
        for (std::size_t i = 0; i + 1 < plain.size(); ++i)
          plain[i] = lerp(plain[i], plain[i + 1], t);
        plain.pop_back();
        ASSERT_EQ(row.size(), plain.size());
        const auto exact_row = test::exact_polar(exact_pts, ts);
        const auto scale_row = test::exact_abs_polar(exact_pts, ts);
        for (std::size_t i = 0; i < row.size(); ++i) {
          EXPECT_EQ(row.entry(i).hi, plain[i]) << "round " << k << " entry " << i;
          EXPECT_EQ(test::accuracy_violation(row.point(i), exact_row[i], scale_row[i], c), "")
              << "round " << k << " entry " << i;
        }
      }
    }
  }
}

TEST(CasteljauRow, RowsMatchTheExactTriangle2D) {
  check_rows<Point2>(101, 30, -1.0, 1.0);  // up to degree 30: rows beyond kInline too
}

TEST(CasteljauRow, RowsMatchTheExactTriangle3DWithCancellation) {
  check_rows<Point3>(102, 12, 1e5, 1e5 + 1.0);  // near-equal points: the steps cancel
}

TEST(CasteljauRow, CompensatedValueNearARootOfHighMultiplicity) {
  // x(t) = (2t - 1)^n has Bernstein coefficients (-1)^(n-i); at t = 1/2 + 2^-20 it is
  // 2^-19n, far below the rounding of plain de Casteljau (u Σ|x_i| b_i = u), while the
  // compensated error is O(n^2 u^2), so the value is good to far better than 2^-40.
  for (int n = 2; n <= 5; ++n) {
    std::vector<Point2> pts;
    for (int i = 0; i <= n; ++i) pts.push_back({(n - i) % 2 == 0 ? 1.0 : -1.0, 0.0});
    const double t = 0.5 + 0x1p-20;
    CasteljauRow<Point2> row{std::span<const Point2>(pts)};
    for (int k = 0; k < n; ++k) row.casteljau_step(t);
    const Rational exact = test::exact_evaluate(test::exact_points(Curve(pts)), Rational(t)).x;
    Rational expected(1);
    for (int k = 0; k < n; ++k) expected *= Rational(0x1p-19);
    ASSERT_EQ(exact, expected);
    EXPECT_LE((Rational(row.point(0).x) - exact).abs(), Rational(0x1p-40) * exact.abs()) << n;
  }
}

TEST(CasteljauRow, HodographStepIsTheScaledDifferences) {
  test::Mulberry32 rng(103);
  for (int n = 1; n <= 26; ++n) {
    // Close points: the differences cancel, and are split exactly.
    const auto curve = test::random_curve<Point2>(rng, n, 1e3, 1e3 + 1e-3);
    const auto exact_pts = test::exact_points(curve);
    const auto expected = test::exact_hodograph(exact_pts);
    CasteljauRow<Point2> row{curve.points()};
    row.hodograph_step();
    ASSERT_EQ(row.size(), static_cast<std::size_t>(n));
    const double u2 = 0x1p-106;
    for (std::size_t i = 0; i < row.size(); ++i) {
      EXPECT_EQ(test::accuracy_violation(row.point(i), expected[i], test::abs(expected[i]), 4 * u2),
                "")
          << "degree " << n << " entry " << i;
    }
  }
}

TEST(CasteljauRow, DerivativeByHodographThenCasteljau) {
  test::Mulberry32 rng(104);
  for (int n = 1; n <= 12; ++n) {
    const auto curve = test::random_curve<Point2>(rng, n, -1.0, 1.0);
    const double t = rng.next();
    SCOPED_TRACE(test::case_name(104, n, t));
    const auto exact_pts = test::exact_points(curve);
    const auto h = test::exact_hodograph(exact_pts);
    // Scale of the hodograph as computed: n (|P_{i+1}| + |P_i|).
    std::vector<test::RPoint2> scales;
    for (std::size_t i = 0; i + 1 < exact_pts.size(); ++i)
      scales.push_back(Rational(n) * (test::abs(exact_pts[i + 1]) + test::abs(exact_pts[i])));
    CasteljauRow<Point2> row{curve.points()};
    row.hodograph_step();
    for (int k = 1; k < n; ++k) row.casteljau_step(t);
    const std::vector<Rational> ts(static_cast<std::size_t>(n - 1), Rational(t));
    EXPECT_EQ(test::accuracy_violation(row.point(0), test::exact_polar(h, ts).front(),
                                       test::exact_abs_polar(scales, ts).front(),
                                       test::compensated_coefficient(n)),
              "");
  }
}

TEST(CasteljauRow, HodographOfASinglePointIsZero) {
  const std::vector<Point3> pts{{4, 5, 6}};
  CasteljauRow<Point3> row{std::span<const Point3>(pts)};
  row.hodograph_step();
  ASSERT_EQ(row.size(), 1u);
  EXPECT_EQ(row.point(0), Point3{});
}

}  // namespace
}  // namespace bezier::core
