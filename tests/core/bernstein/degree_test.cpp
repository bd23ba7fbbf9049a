// core/bernstein/degree.hpp: elevation and L2-best reduction, against exact rational computations
// of the same definitions (Gram systems solved in rationals).

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/numeric/binomial.hpp"
#include "core/bernstein/degree.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::Rational;

Rational rbinomial(int n, int k) {
  return Rational(static_cast<long long>(binomial(n, k)));
}

/// The L2 reduction matrix in exact rationals: G_k R = M, Gaussian elimination without
/// pivoting (G_k is positive definite).
std::vector<std::vector<Rational>> exact_reduction(int n, int k) {
  std::vector<std::vector<Rational>> a(static_cast<std::size_t>(k + 1)),
      b(static_cast<std::size_t>(k + 1));
  for (int i = 0; i <= k; ++i) {
    for (int j = 0; j <= k; ++j) {
      a[i].push_back(rbinomial(k, i) * rbinomial(k, j) /
                     (Rational(2 * k + 1) * rbinomial(2 * k, i + j)));
    }
    for (int j = 0; j <= n; ++j) {
      b[i].push_back(rbinomial(k, i) * rbinomial(n, j) /
                     (Rational(k + n + 1) * rbinomial(k + n, i + j)));
    }
  }
  for (int c = 0; c <= k; ++c) {
    for (int r = c + 1; r <= k; ++r) {
      const Rational factor = a[r][c] / a[c][c];
      for (int j = c; j <= k; ++j) a[r][j] -= factor * a[c][j];
      for (int j = 0; j <= n; ++j) b[r][j] -= factor * b[c][j];
    }
  }
  std::vector<std::vector<Rational>> x(
      static_cast<std::size_t>(k + 1),
      std::vector<Rational>(static_cast<std::size_t>(n + 1), Rational(0)));
  for (int r = k; r >= 0; --r) {
    for (int j = 0; j <= n; ++j) {
      Rational sum = b[r][j];
      for (int c = r + 1; c <= k; ++c) sum -= a[r][c] * x[c][j];
      x[r][j] = sum / a[r][r];
    }
  }
  return x;
}

TEST(DegreeReduction, MatricesMatchTheExactGramSolution) {
  // Degrees covered by the compile-time table (<= 20) and beyond it (computed at run time).
  for (const int k : {1, 2, 3, 4}) {
    for (const int n : {k + 1, k + 2, 7, 10, 20, 21}) {
      SCOPED_TRACE("n = " + std::to_string(n) + ", k = " + std::to_string(k));
      const BernsteinMatrix m = l2_reduction_matrix(n, k);
      const auto exact = exact_reduction(n, k);
      ASSERT_EQ(m.rows, k + 1);
      ASSERT_EQ(m.cols, n + 1);
      for (int i = 0; i <= k; ++i) {
        for (int j = 0; j <= n; ++j) {
          const double e = exact[i][j].to_double();
          EXPECT_NEAR(m(i, j), e, 1e-13 * std::fmax(1.0, std::fabs(e)));
        }
      }
    }
  }
}

TEST(DegreeReduction, TablesAgreeWithTheMatrices) {
  for (const int k : {2, 3}) {
    for (int n = k + 1; n <= 20; ++n) {
      const double* table = l2_reduction_table(n, k);
      ASSERT_NE(table, nullptr);
      const BernsteinMatrix m = l2_reduction_matrix(n, k);
      for (int i = 0; i < m.rows * m.cols; ++i)
        EXPECT_EQ(table[i], m.entries[static_cast<std::size_t>(i)]);
    }
  }
  EXPECT_EQ(l2_reduction_table(21, 2), nullptr);
  EXPECT_EQ(elevation_table(4, 5), nullptr);
  for (int from = 1; from <= 3; ++from) {
    for (int to = from; to <= 20; ++to) {
      const BernsteinMatrix m = elevation_matrix(from, to);
      const double* table = elevation_table(from, to);
      for (int i = 0; i < m.rows * m.cols; ++i)
        EXPECT_EQ(table[i], m.entries[static_cast<std::size_t>(i)]);
    }
  }
}

TEST(DegreeReduction, ReductionOfAnElevatedPolynomialGivesItBack) {
  // A polynomial of degree k is its own best approximation of degree k.
  test::Mulberry32 rng(31);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<double> p(3);
    for (double& v : p) v = rng.uniform(-1, 1);
    const std::vector<double> up = elevate_degree(std::span<const double>(p), 9);
    const std::vector<double> back = reduce_degree(std::span<const double>(up), 2);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(back[static_cast<std::size_t>(i)], p[static_cast<std::size_t>(i)], 1e-14);
  }
}

TEST(DegreeReduction, ElevationKeepsTheCurveExactly) {
  // A dyadic cubic elevated to degree 4 has coefficients i/4 P_{i-1} + (1 - i/4) P_i: exact,
  // and the same point at every t (compared in rationals).
  const Curve c({{0.0, 0.0}, {0.25, 1.0}, {0.75, -0.5}, {1.0, 0.5}});
  const Curve e = elevate_degree(c, 4);
  ASSERT_EQ(e.degree(), 4);
  const std::vector<test::RPoint2> expected = {
      test::exact(c[0]),
      Rational(1, 4) * test::exact(c[0]) + Rational(3, 4) * test::exact(c[1]),
      Rational(2, 4) * test::exact(c[1]) + Rational(2, 4) * test::exact(c[2]),
      Rational(3, 4) * test::exact(c[2]) + Rational(1, 4) * test::exact(c[3]),
      test::exact(c[3]),
  };
  for (int i = 0; i <= 4; ++i) EXPECT_EQ(test::exact(e[i]), expected[static_cast<std::size_t>(i)]);
}

TEST(DegreeReduction, ResidualIsOrthogonalToTheLowDegreePolynomials) {
  // The L2 projection's residual D - p is orthogonal to every degree-k polynomial:
  // ∫ (D - p) B_j^k = 0 for j = 0..k, evaluated exactly in rationals with the product rule
  // ∫ B_i^n B_j^k = C(n,i) C(k,j) / ((n + k + 1) C(n + k, i + j)).
  const std::vector<double> d = {0.5, -1.0, 2.0, 0.25, -0.75};  // degree 4
  const std::vector<double> p = reduce_degree(std::span<const double>(d), 2);
  for (int j = 0; j <= 2; ++j) {
    Rational integral(0);
    for (int i = 0; i <= 4; ++i) {
      integral += Rational(d[static_cast<std::size_t>(i)]) * rbinomial(4, i) * rbinomial(2, j) /
                  (Rational(7) * rbinomial(6, i + j));
    }
    for (int i = 0; i <= 2; ++i) {
      integral -= Rational(p[static_cast<std::size_t>(i)]) * rbinomial(2, i) * rbinomial(2, j) /
                  (Rational(5) * rbinomial(4, i + j));
    }
    EXPECT_LT(std::fabs(integral.to_double()), 1e-15) << j;
  }
}

TEST(DegreeReduction, CurveReductionIsCoordinatewise) {
  const Curve c({{0.0, 1.0}, {1.0, 3.0}, {2.0, -1.0}, {4.0, 0.0}});
  const Curve r = reduce_degree(c, 2);
  std::vector<double> xs, ys;
  for (const Point2 q : c.points()) {
    xs.push_back(q.x);
    ys.push_back(q.y);
  }
  const std::vector<double> rx = reduce_degree(std::span<const double>(xs), 2);
  const std::vector<double> ry = reduce_degree(std::span<const double>(ys), 2);
  for (int i = 0; i <= 2; ++i) {
    EXPECT_EQ(r[i].x, rx[static_cast<std::size_t>(i)]);
    EXPECT_EQ(r[i].y, ry[static_cast<std::size_t>(i)]);
  }
}

}  // namespace
}  // namespace bezier::core
