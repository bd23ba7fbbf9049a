#include "core/degree.hpp"

#include <cassert>
#include <cmath>
#include <utility>

#include "core/binomial.hpp"

namespace bezier::core {

namespace {

using Matrix = std::vector<std::vector<long double>>;

long double binomial_ld(int n, int k) { return static_cast<long double>(binomial(n, k)); }

/// Solves A X = B for X (A square, B with several columns) by Gaussian elimination with
/// partial pivoting. A is a Gram matrix of a basis, so it is symmetric positive definite
/// and never singular.
Matrix solve(Matrix a, Matrix b) {
  const std::size_t n = a.size();
  const std::size_t m = b.empty() ? 0 : b[0].size();
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < n; ++r) {
      if (std::fabs(a[r][col]) > std::fabs(a[pivot][col])) pivot = r;
    }
    std::swap(a[col], a[pivot]);
    std::swap(b[col], b[pivot]);
    for (std::size_t r = col + 1; r < n; ++r) {
      const long double factor = a[r][col] / a[col][col];
      for (std::size_t c = col; c < n; ++c) a[r][c] -= factor * a[col][c];
      for (std::size_t c = 0; c < m; ++c) b[r][c] -= factor * b[col][c];
    }
  }
  Matrix x(n, std::vector<long double>(m, 0.0L));
  for (std::size_t r = n; r-- > 0;) {
    for (std::size_t c = 0; c < m; ++c) {
      long double sum = b[r][c];
      for (std::size_t j = r + 1; j < n; ++j) sum -= a[r][j] * x[j][c];
      x[r][c] = sum / a[r][r];
    }
  }
  return x;
}

}  // namespace

BernsteinMatrix elevation_matrix(int from, int to) {
  assert(0 <= from && from <= to);
  BernsteinMatrix m{to + 1, from + 1, std::vector<double>(static_cast<std::size_t>((to + 1) * (from + 1)), 0.0)};
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
  Matrix gram(static_cast<std::size_t>(k + 1), std::vector<long double>(static_cast<std::size_t>(k + 1)));
  Matrix mixed(static_cast<std::size_t>(k + 1), std::vector<long double>(static_cast<std::size_t>(n + 1)));
  for (int i = 0; i <= k; ++i) {
    for (int j = 0; j <= k; ++j) {
      gram[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          binomial_ld(k, i) * binomial_ld(k, j) / ((2 * k + 1) * binomial_ld(2 * k, i + j));
    }
    for (int j = 0; j <= n; ++j) {
      mixed[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          binomial_ld(k, i) * binomial_ld(n, j) / ((k + n + 1) * binomial_ld(k + n, i + j));
    }
  }
  const Matrix r = solve(std::move(gram), std::move(mixed));
  BernsteinMatrix out{k + 1, n + 1, {}};
  out.entries.reserve(static_cast<std::size_t>((k + 1) * (n + 1)));
  for (const auto& row : r) {
    for (const long double v : row) out.entries.push_back(static_cast<double>(v));
  }
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
