#include "core/linear_solve.hpp"

#include <cassert>
#include <cmath>
#include <utility>

namespace bezier::core {

template <class T>
std::optional<DenseMatrix<T>> solve_linear(DenseMatrix<T> a, DenseMatrix<T> b) {
  assert(a.rows == a.cols && b.rows == a.rows);
  const std::size_t n = a.rows;
  const std::size_t m = b.cols;
  const auto swap_rows = [](DenseMatrix<T>& x, std::size_t i, std::size_t j) {
    for (std::size_t c = 0; c < x.cols; ++c) std::swap(x(i, c), x(j, c));
  };
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < n; ++r) {
      if (std::fabs(a(r, col)) > std::fabs(a(pivot, col))) pivot = r;
    }
    // Written so that NaN fails: a NaN pivot is as useless as a zero one.
    if (!(std::fabs(a(pivot, col)) > 0)) return std::nullopt;
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

template std::optional<DenseMatrix<double>> solve_linear(DenseMatrix<double>, DenseMatrix<double>);
template std::optional<DenseMatrix<long double>> solve_linear(DenseMatrix<long double>,
                                                              DenseMatrix<long double>);

}  // namespace bezier::core
