#include "core/numeric/linear_solve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "tests/support/exact.hpp"

namespace bezier::core {
namespace {

using test::Rational;

/// The matrix with these rational entries (each exactly a double), in T.
template <class T>
DenseMatrix<T> matrix_of(const std::vector<std::vector<Rational>>& rows) {
  DenseMatrix<T> m(rows.size(), rows[0].size());
  for (std::size_t i = 0; i < m.rows; ++i) {
    for (std::size_t j = 0; j < m.cols; ++j) {
      EXPECT_EQ(Rational(rows[i][j].to_double()), rows[i][j]) << "not a double: " << i << ", " << j;
      m(i, j) = static_cast<T>(rows[i][j].to_double());
    }
  }
  return m;
}

/// A X in rationals: the right-hand sides of a system built from its answer X.
std::vector<std::vector<Rational>> product(const std::vector<std::vector<Rational>>& a,
                                           const std::vector<std::vector<Rational>>& x) {
  std::vector<std::vector<Rational>> out(a.size(), std::vector<Rational>(x[0].size(), Rational(0)));
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t c = 0; c < x[0].size(); ++c) {
      for (std::size_t j = 0; j < x.size(); ++j) out[i][c] += a[i][j] * x[j][c];
    }
  }
  return out;
}

/// 60 H for the 3 x 3 Hilbert matrix H_ij = 1 / (i + j + 1): integer entries, condition
/// number (infinity norm) 748.
std::vector<std::vector<Rational>> scaled_hilbert() {
  std::vector<std::vector<Rational>> a(3);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) a[i].push_back(Rational(60) / Rational(i + j + 1));
  }
  return a;
}

/// |x - exact| for every entry, at most `bound`.
template <class T>
void expect_within(const DenseMatrix<T>& x, const std::vector<std::vector<Rational>>& exact,
                   double bound) {
  ASSERT_EQ(x.rows, exact.size());
  ASSERT_EQ(x.cols, exact[0].size());
  for (std::size_t i = 0; i < x.rows; ++i) {
    for (std::size_t c = 0; c < x.cols; ++c) {
      // A long double is exactly a binary fraction too: its two-double split is exact.
      const T v = x(i, c);
      const double hi = static_cast<double>(v), lo = static_cast<double>(v - static_cast<T>(hi));
      const Rational error = abs(Rational(hi) + Rational(lo) - exact[i][c]);
      EXPECT_LE(error, Rational(bound)) << "entry " << i << ", " << c << ": " << error.to_double();
    }
  }
}

TEST(LinearSolve, ScaledHilbertSystemIsSolvedToItsConditioning) {
  // x = (1, -2, 3) and (1/2, 1/4, -1/8): b = 60 H x is exact in integers and binary
  // fractions. Partial pivoting is backward stable (Higham, "Accuracy and Stability of
  // Numerical Algorithms", 2nd ed., Thm. 9.4), so the forward error is about
  // cond(A) n u |x| = 748 * 3 * u * 3: below 1e-12 in double and 1e-15 in long double
  // (u = 2^-64), which only a long double elimination meets.
  const auto a = scaled_hilbert();
  const std::vector<std::vector<Rational>> x = {{Rational(1), Rational(1, 2)},
                                                {Rational(-2), Rational(1, 4)},
                                                {Rational(3), Rational(-1, 8)}};
  const auto b = product(a, x);
  const auto in_double = solve_linear(matrix_of<double>(a), matrix_of<double>(b));
  ASSERT_TRUE(in_double.has_value());
  expect_within(*in_double, x, 1e-12);
  const auto in_long_double = solve_linear(matrix_of<long double>(a), matrix_of<long double>(b));
  ASSERT_TRUE(in_long_double.has_value());
  expect_within(*in_long_double, x, 1e-15);
}

template <class T>
void expect_pivoted_system_exact() {
  // a_00 = 0: elimination without row swaps divides by zero. With partial pivoting the
  // rows go (4 2 0), (2 3 1) -> (0 2 1), then (0 1 2) -> (0 0 3/2): every multiplier is 0 or
  // 1/2 and every intermediate of b a short binary fraction, so the answer, built from
  // x = (1, -2, 3) and (-3, 1/2, 1/4), comes back exactly.
  const std::vector<std::vector<Rational>> a = {{Rational(0), Rational(1), Rational(2)},
                                                {Rational(4), Rational(2), Rational(0)},
                                                {Rational(2), Rational(3), Rational(1)}};
  const std::vector<std::vector<Rational>> x = {
      {Rational(1), Rational(-3)}, {Rational(-2), Rational(1, 2)}, {Rational(3), Rational(1, 4)}};
  const auto solved = solve_linear(matrix_of<T>(a), matrix_of<T>(product(a, x)));
  ASSERT_TRUE(solved.has_value());
  expect_within(*solved, x, 0.0);
}

TEST(LinearSolve, ZeroLeadingEntryIsPivotedAwayExactly) {
  expect_pivoted_system_exact<double>();
  expect_pivoted_system_exact<long double>();
}

TEST(LinearSolve, AnyNumberOfRightHandSides) {
  // One column (a Gauss-Newton step) and the identity (the inverse, here of an exactly
  // invertible diagonal-times-permutation matrix).
  const std::vector<std::vector<Rational>> a = {{Rational(0), Rational(2), Rational(0)},
                                                {Rational(0), Rational(0), Rational(-4)},
                                                {Rational(8), Rational(0), Rational(0)}};
  const auto one = solve_linear(matrix_of<double>(a),
                                matrix_of<double>({{Rational(1)}, {Rational(1)}, {Rational(1)}}));
  ASSERT_TRUE(one.has_value());
  expect_within(*one, {{Rational(1, 8)}, {Rational(1, 2)}, {Rational(-1, 4)}}, 0.0);
  const std::vector<std::vector<Rational>> identity = {{Rational(1), Rational(0), Rational(0)},
                                                       {Rational(0), Rational(1), Rational(0)},
                                                       {Rational(0), Rational(0), Rational(1)}};
  const auto inverse = solve_linear(matrix_of<double>(a), matrix_of<double>(identity));
  ASSERT_TRUE(inverse.has_value());
  expect_within(*inverse,
                {{Rational(0), Rational(0), Rational(1, 8)},
                 {Rational(1, 2), Rational(0), Rational(0)},
                 {Rational(0), Rational(-1, 4), Rational(0)}},
                0.0);
}

TEST(LinearSolve, SingularMatrixIsReported) {
  // Row 1 is twice row 0: elimination leaves an exactly zero last pivot.
  const std::vector<std::vector<Rational>> a = {{Rational(1), Rational(2), Rational(3)},
                                                {Rational(2), Rational(4), Rational(6)},
                                                {Rational(1), Rational(1), Rational(1)}};
  const std::vector<std::vector<Rational>> b = {{Rational(1)}, {Rational(2)}, {Rational(3)}};
  EXPECT_FALSE(solve_linear(matrix_of<double>(a), matrix_of<double>(b)).has_value());
  EXPECT_FALSE(solve_linear(matrix_of<long double>(a), matrix_of<long double>(b)).has_value());
  // The all-zero matrix fails at the first pivot.
  EXPECT_FALSE(solve_linear(DenseMatrix<double>(2, 2), DenseMatrix<double>(2, 1)).has_value());
}

TEST(LinearSolve, NaNPivotIsReportedAsSingular) {
  DenseMatrix<double> a(2, 2), b(2, 1);
  a(0, 0) = std::numeric_limits<double>::quiet_NaN();
  a(1, 1) = 1.0;
  EXPECT_FALSE(solve_linear(a, b).has_value());
}

}  // namespace
}  // namespace bezier::core
