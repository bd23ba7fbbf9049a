#include "core/bernstein/degree.hpp"

#include <cassert>
#include <optional>
#include <utility>

#include "core/numeric/binomial.hpp"
#include "core/bernstein/tuning.hpp"
#include "core/numeric/linear_solve.hpp"

namespace bezier::core {

namespace {

constexpr long double binomial_ld(int n, int k) {
  return static_cast<long double>(binomial(n, k));
}

/// The L2 reduction matrix of degree n to degree k in long double: the Gram system
/// G_k X = M_kn in Bernstein form, (G_k)_ij = C(k,i) C(k,j) / ((2k+1) C(2k,i+j)) and
/// (M_kn)_ij = C(k,i) C(n,j) / ((k+n+1) C(k+n,i+j)), solved by solve_linear. In long double:
/// G_k's condition grows like 4^k (see the header). constexpr, so that the fat curves'
/// table below is built by the same arithmetic at compile time.
constexpr DenseMatrix<long double> reduction_in_long_double(int n, int k) {
  const auto K = static_cast<std::size_t>(k), N = static_cast<std::size_t>(n);
  DenseMatrix<long double> gram(K + 1, K + 1), mixed(K + 1, N + 1);
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
  // G_k is a Gram matrix of a basis: symmetric positive definite, never singular.
  const std::optional<DenseMatrix<long double>> x = solve_linear(std::move(gram), std::move(mixed));
  assert(x.has_value());
  return *x;
}

/// L2 reduction matrices for the fat curves (k = 2, 3) of every degree up to kTableDegree,
/// computed at compile time, so that building a fat curve operator costs no elimination per
/// request.
using bernstein_tuning::kTableDegree;

struct ReductionTable {
  // [k - 2][n] -> (k + 1) x (n + 1) entries, row-major.
  double entries[2][kTableDegree + 1][4 * (kTableDegree + 1)] = {};
};

constexpr ReductionTable make_reduction_table() {
  ReductionTable table;
  for (int k = 2; k <= 3; ++k) {
    for (int n = k + 1; n <= kTableDegree; ++n) {
      const DenseMatrix<long double> x = reduction_in_long_double(n, k);
      for (int i = 0; i <= k; ++i) {
        for (int j = 0; j <= n; ++j)
          table.entries[k - 2][n][i * (n + 1) + j] = static_cast<double>(x(i, j));
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
              binomial_ld(from, j) * binomial_ld(to - from, i - j) / binomial_ld(to, i));
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
  const DenseMatrix<long double> r = reduction_in_long_double(n, k);
  BernsteinMatrix out{k + 1, n + 1, {}};
  out.entries.reserve(r.entries.size());
  for (const long double v : r.entries) out.entries.push_back(static_cast<double>(v));
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
