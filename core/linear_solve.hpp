#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace bezier::core {

/// A small dense matrix of T (double or long double), row-major: entry (i, j) is
/// entries[i * cols + j]. Zero-filled on construction.
template <class T>
struct DenseMatrix {
  std::size_t rows = 0;
  std::size_t cols = 0;
  std::vector<T> entries;

  DenseMatrix(std::size_t r, std::size_t c) : rows(r), cols(c), entries(r * c, T(0)) {}
  T& operator()(std::size_t i, std::size_t j) { return entries[i * cols + j]; }
  T operator()(std::size_t i, std::size_t j) const { return entries[i * cols + j]; }
};

/// X with A X = B, for A square (n x n) and B n x m: m right-hand sides at once, the
/// columns of B, solved with the same elimination. Gaussian elimination with partial
/// pivoting (Golub & Van Loan, "Matrix Computations", 4th ed., §3.4): in column k the row
/// of largest |a_ik|, i >= k, is swapped up (the first such row on a tie), the rows below
/// are reduced with l_ik = a_ik / a_kk, then back substitution
/// x_i = (b_i - sum_{j>i} a_ij x_j) / a_ii with the sum taken in increasing j. Everything is
/// computed in T, in this order, so the caller chooses the precision (core/degree.cpp's
/// ill-conditioned Gram systems in long double, core/intersect/common_arc.cpp's
/// interpolation in double) and results are reproducible bit for bit.
///
/// std::nullopt when a pivot is zero or NaN: A is singular (exactly, or once rounded in T),
/// or held a NaN (a NaN in B only comes through into X). No condition estimate: a nearly
/// singular A gives a large, inaccurate X.
/// Precondition: a.rows == a.cols == b.rows. Defined for T = double and long double.
template <class T>
[[nodiscard]] std::optional<DenseMatrix<T>> solve_linear(DenseMatrix<T> a, DenseMatrix<T> b);

extern template std::optional<DenseMatrix<double>> solve_linear(DenseMatrix<double>,
                                                                DenseMatrix<double>);
extern template std::optional<DenseMatrix<long double>> solve_linear(DenseMatrix<long double>,
                                                                     DenseMatrix<long double>);

}  // namespace bezier::core
