#include "core/degree.hpp"

#include <cassert>
#include <cmath>
#include <utility>

#include "core/binomial.hpp"

namespace bezier::core {

namespace {

/// Row-major long double matrix with its column count (small: the Gram systems here have
/// k + 1 <= 11 rows).
struct Matrix {
  std::size_t rows = 0, cols = 0;
  std::vector<long double> v;
  Matrix(std::size_t r, std::size_t c) : rows(r), cols(c), v(r * c, 0.0L) {}
  long double& operator()(std::size_t i, std::size_t j) { return v[i * cols + j]; }
  long double operator()(std::size_t i, std::size_t j) const { return v[i * cols + j]; }
  void swap_rows(std::size_t a, std::size_t b) {
    for (std::size_t j = 0; j < cols; ++j) std::swap((*this)(a, j), (*this)(b, j));
  }
};

long double binomial_ld(int n, int k) {
  return static_cast<long double>(binomial(n, k));
}

/// Solves A X = B for X (A square, B with several columns) by Gaussian elimination with
/// partial pivoting. A is a Gram matrix of a basis, so it is symmetric positive definite
/// and never singular.
Matrix solve(Matrix a, Matrix b) {
  const std::size_t n = a.rows;
  const std::size_t m = b.cols;
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < n; ++r) {
      if (std::fabs(a(r, col)) > std::fabs(a(pivot, col))) pivot = r;
    }
    a.swap_rows(col, pivot);
    b.swap_rows(col, pivot);
    for (std::size_t r = col + 1; r < n; ++r) {
      const long double factor = a(r, col) / a(col, col);
      for (std::size_t c = col; c < n; ++c) a(r, c) -= factor * a(col, c);
      for (std::size_t c = 0; c < m; ++c) b(r, c) -= factor * b(col, c);
    }
  }
  Matrix x(n, m);
  for (std::size_t r = n; r-- > 0;) {
    for (std::size_t c = 0; c < m; ++c) {
      long double sum = b(r, c);
      for (std::size_t j = r + 1; j < n; ++j) sum -= a(r, j) * x(j, c);
      x(r, c) = sum / a(r, r);
    }
  }
  return x;
}

/// L2 reduction matrices for the fat curves (k = 2, 3) of every degree up to 20, computed
/// at compile time by the same Gram-system elimination as below, so that building a fat
/// curve operator costs no elimination per request.
constexpr int kTableDegree = 20;

constexpr long double const_binomial(int n, int k) {
  if (k < 0 || k > n) return 0.0L;
  long double c = 1.0L;
  for (int j = 0; j < k; ++j) c = c * (n - j) / (j + 1);
  return c;
}

constexpr long double const_abs(long double x) {
  return x < 0 ? -x : x;
}

struct ReductionTable {
  // [k - 2][n] -> (k + 1) x (n + 1) entries, row-major.
  double entries[2][kTableDegree + 1][4 * (kTableDegree + 1)] = {};
};

constexpr ReductionTable make_reduction_table() {
  ReductionTable table;
  for (int k = 2; k <= 3; ++k) {
    for (int n = k + 1; n <= kTableDegree; ++n) {
      long double a[4][4] = {};
      long double b[4][kTableDegree + 1] = {};
      for (int i = 0; i <= k; ++i) {
        for (int j = 0; j <= k; ++j) {
          a[i][j] = const_binomial(k, i) * const_binomial(k, j) /
                    ((2 * k + 1) * const_binomial(2 * k, i + j));
        }
        for (int j = 0; j <= n; ++j) {
          b[i][j] = const_binomial(k, i) * const_binomial(n, j) /
                    ((k + n + 1) * const_binomial(k + n, i + j));
        }
      }
      for (int col = 0; col <= k; ++col) {
        int pivot = col;
        for (int r = col + 1; r <= k; ++r) {
          if (const_abs(a[r][col]) > const_abs(a[pivot][col])) pivot = r;
        }
        for (int j = 0; j <= k; ++j) std::swap(a[col][j], a[pivot][j]);
        for (int j = 0; j <= n; ++j) std::swap(b[col][j], b[pivot][j]);
        for (int r = col + 1; r <= k; ++r) {
          const long double factor = a[r][col] / a[col][col];
          for (int c = col; c <= k; ++c) a[r][c] -= factor * a[col][c];
          for (int c = 0; c <= n; ++c) b[r][c] -= factor * b[col][c];
        }
      }
      long double x[4][kTableDegree + 1] = {};
      for (int r = k; r >= 0; --r) {
        for (int c = 0; c <= n; ++c) {
          long double sum = b[r][c];
          for (int j = r + 1; j <= k; ++j) sum -= a[r][j] * x[j][c];
          x[r][c] = sum / a[r][r];
        }
      }
      for (int i = 0; i <= k; ++i) {
        for (int j = 0; j <= n; ++j)
          table.entries[k - 2][n][i * (n + 1) + j] = static_cast<double>(x[i][j]);
      }
    }
  }
  return table;
}

constexpr ReductionTable kReductionTable = make_reduction_table();

struct ElevationTable {
  // [from - 1][to] -> (to + 1) x (from + 1) entries, row-major.
  double entries[3][kTableDegree + 1][4 * (kTableDegree + 1)] = {};
};

constexpr ElevationTable make_elevation_table() {
  ElevationTable table;
  for (int from = 1; from <= 3; ++from) {
    for (int to = from; to <= kTableDegree; ++to) {
      for (int i = 0; i <= to; ++i) {
        for (int j = 0; j <= from; ++j) {
          if (i - j < 0 || i - j > to - from) continue;
          table.entries[from - 1][to][i * (from + 1) + j] = static_cast<double>(
              const_binomial(from, j) * const_binomial(to - from, i - j) / const_binomial(to, i));
        }
      }
    }
  }
  return table;
}

constexpr ElevationTable kElevationTable = make_elevation_table();

}  // namespace

const double* l2_reduction_table(int n, int k) noexcept {
  if ((k != 2 && k != 3) || n <= k || n > kTableDegree) return nullptr;
  return kReductionTable.entries[k - 2][n];
}

const double* elevation_table(int from, int to) noexcept {
  if (from < 1 || from > 3 || to < from || to > kTableDegree) return nullptr;
  return kElevationTable.entries[from - 1][to];
}

BernsteinMatrix elevation_matrix(int from, int to) {
  assert(0 <= from && from <= to);
  BernsteinMatrix m{to + 1, from + 1,
                    std::vector<double>(static_cast<std::size_t>((to + 1) * (from + 1)), 0.0)};
  for (int i = 0; i <= to; ++i) {
    for (int j = 0; j <= from; ++j) {
      if (i - j < 0 || i - j > to - from) continue;
      // The numerator is an exact integer product (small degrees); one rounding in the
      // division.
      m.entries[static_cast<std::size_t>(i * m.cols + j)] =
          binomial(from, j) * binomial(to - from, i - j) / binomial(to, i);
    }
  }
  return m;
}

BernsteinMatrix l2_reduction_matrix(int n, int k) {
  assert(n >= 0 && k >= 0);
  if (k >= n) return elevation_matrix(n, k);
  if ((k == 2 || k == 3) && n <= kTableDegree) {
    const double* e = kReductionTable.entries[k - 2][n];
    return {k + 1, n + 1, std::vector<double>(e, e + (k + 1) * (n + 1))};
  }
  const auto K = static_cast<std::size_t>(k), N = static_cast<std::size_t>(n);
  Matrix gram(K + 1, K + 1), mixed(K + 1, N + 1);
  for (int i = 0; i <= k; ++i) {
    for (int j = 0; j <= k; ++j) {
      gram(static_cast<std::size_t>(i), static_cast<std::size_t>(j)) =
          binomial_ld(k, i) * binomial_ld(k, j) / ((2 * k + 1) * binomial_ld(2 * k, i + j));
    }
    for (int j = 0; j <= n; ++j) {
      mixed(static_cast<std::size_t>(i), static_cast<std::size_t>(j)) =
          binomial_ld(k, i) * binomial_ld(n, j) / ((k + n + 1) * binomial_ld(k + n, i + j));
    }
  }
  const Matrix r = solve(std::move(gram), std::move(mixed));
  BernsteinMatrix out{k + 1, n + 1, {}};
  out.entries.reserve(r.v.size());
  for (const long double v : r.v) out.entries.push_back(static_cast<double>(v));
  return out;
}

std::vector<double> apply(const BernsteinMatrix& m, std::span<const double> v) {
  assert(static_cast<int>(v.size()) == m.cols);
  std::vector<double> out(static_cast<std::size_t>(m.rows), 0.0);
  for (int i = 0; i < m.rows; ++i) {
    double sum = 0.0;
    for (int j = 0; j < m.cols; ++j) sum += m(i, j) * v[static_cast<std::size_t>(j)];
    out[static_cast<std::size_t>(i)] = sum;
  }
  return out;
}

std::vector<double> elevate_degree(std::span<const double> coefficients, int to) {
  assert(!coefficients.empty());
  return apply(elevation_matrix(static_cast<int>(coefficients.size()) - 1, to), coefficients);
}

std::vector<double> reduce_degree(std::span<const double> coefficients, int k) {
  assert(!coefficients.empty());
  return apply(l2_reduction_matrix(static_cast<int>(coefficients.size()) - 1, k), coefficients);
}

namespace {

Curve apply_to_curve(const BernsteinMatrix& m, const Curve& curve) {
  std::vector<double> xs, ys;
  for (const Point2 p : curve.points()) {
    xs.push_back(p.x);
    ys.push_back(p.y);
  }
  const std::vector<double> qx = apply(m, xs), qy = apply(m, ys);
  std::vector<Point2> pts;
  pts.reserve(qx.size());
  for (std::size_t i = 0; i < qx.size(); ++i) pts.push_back({qx[i], qy[i]});
  return Curve(std::move(pts));
}

}  // namespace

Curve elevate_degree(const Curve& curve, int to) {
  assert(to >= curve.degree());
  return apply_to_curve(elevation_matrix(curve.degree(), to), curve);
}

Curve reduce_degree(const Curve& curve, int k) {
  assert(k >= 0);
  return apply_to_curve(l2_reduction_matrix(curve.degree(), k), curve);
}

}  // namespace bezier::core
