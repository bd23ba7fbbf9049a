#pragma once

#include <cassert>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace bezier::core {

/// A small dense matrix of T (double or long double), row-major: entry (i, j) is
/// entries[i * cols + j]. Zero-filled on construction.
template <class T>
struct DenseMatrix {
  std::size_t rows = 0;
  std::size_t cols = 0;
  std::vector<T> entries;

  constexpr DenseMatrix(std::size_t r, std::size_t c) : rows(r), cols(c), entries(r * c, T(0)) {}
  constexpr T& operator()(std::size_t i, std::size_t j) { return entries[i * cols + j]; }
  constexpr T operator()(std::size_t i, std::size_t j) const { return entries[i * cols + j]; }
};

/// X with A X = B, for A square (n x n) and B n x m: m right-hand sides at once, the
/// columns of B, solved with the same elimination. Gaussian elimination with partial
/// pivoting (Golub & Van Loan, "Matrix Computations", 4th ed., §3.4): in column k the row
/// of largest |a_ik|, i >= k, is swapped up (the first such row on a tie), the rows below
/// are reduced with l_ik = a_ik / a_kk, then back substitution
/// x_i = (b_i - sum_{j>i} a_ij x_j) / a_ii with the sum taken in increasing j. Everything is
/// computed in T, in this order, so the caller chooses the precision (core/bernstein/degree.cpp's
/// ill-conditioned Gram systems in long double, core/intersect/common_arc.cpp's
/// interpolation in double) and results are reproducible bit for bit.
///
/// std::nullopt when a pivot is zero or NaN: A is singular (exactly, or once rounded in T),
/// or held a NaN (a NaN in B only comes through into X). No condition estimate: a nearly
/// singular A gives a large, inaccurate X.
/// Precondition: a.rows == a.cols == b.rows. constexpr, so that tables of solutions can be
/// built at compile time with the same arithmetic (core/bernstein/degree.cpp).
template <class T>
[[nodiscard]] constexpr std::optional<DenseMatrix<T>> solve_linear(DenseMatrix<T> a,
                                                                   DenseMatrix<T> b) {
  assert(a.rows == a.cols && b.rows == a.rows);
  const std::size_t n = a.rows;
  const std::size_t m = b.cols;
  const auto magnitude = [](T x) { return x < 0 ? -x : x; };  // std::fabs: not constexpr
  const auto swap_rows = [](DenseMatrix<T>& x, std::size_t i, std::size_t j) {
    for (std::size_t c = 0; c < x.cols; ++c) std::swap(x(i, c), x(j, c));
  };
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < n; ++r) {
      if (magnitude(a(r, col)) > magnitude(a(pivot, col))) pivot = r;
    }
    // Written so that NaN fails: a NaN pivot is as useless as a zero one.
    if (!(magnitude(a(pivot, col)) > 0)) return std::nullopt;
    swap_rows(a, col, pivot);
    swap_rows(b, col, pivot);
    for (std::size_t r = col + 1; r < n; ++r) {
      const T factor = a(r, col) / a(col, col);
      for (std::size_t c = col; c < n; ++c) a(r, c) -= factor * a(col, c);
      for (std::size_t c = 0; c < m; ++c) b(r, c) -= factor * b(col, c);
    }
  }
  // Back substitution in place: row i of b becomes row i of X once the rows below it have.
  for (std::size_t i = n; i-- > 0;) {
    for (std::size_t c = 0; c < m; ++c) {
      T sum = b(i, c);
      for (std::size_t j = i + 1; j < n; ++j) sum -= a(i, j) * b(j, c);
      b(i, c) = sum / a(i, i);
    }
  }
  return b;
}

}  // namespace bezier::core
