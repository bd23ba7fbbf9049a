#pragma once

#include <span>
#include <vector>

#include "core/base/curve.hpp"

namespace bezier::core {

/// A dense row-major matrix acting on Bernstein coefficient vectors: rows x cols entries,
/// result_i = Σ_j entry(i, j) coefficient_j. Used for degree elevation and reduction,
/// where one matrix is built per (from, to) pair and applied many times.
struct BernsteinMatrix {
  int rows = 0;
  int cols = 0;
  std::vector<double> entries;  ///< rows * cols, row-major

  [[nodiscard]] double operator()(int i, int j) const noexcept {
    return entries[static_cast<std::size_t>(i * cols + j)];
  }
};

/// The matrix that elevates a degree-`from` Bernstein polynomial to degree `to` >= from
/// without changing it: c_i = Σ_j C(from, j) C(to - from, i - j) / C(to, i) p_j
/// (Farin, "Curves and Surfaces for CAGD", 5th ed., §6.1, iterated). Every row is a convex
/// combination (entries >= 0, summing to 1). Precondition: 0 <= from <= to.
[[nodiscard]] BernsteinMatrix elevation_matrix(int from, int to);

/// The matrix of the L2-best degree reduction: for a degree-n polynomial with Bernstein
/// coefficients a, R a are the Bernstein coefficients of the degree-k polynomial p that
/// minimises ∫_0^1 (B(t) - p(t))^2 dt (the orthogonal projection onto degree <= k).
/// Built from the Gram matrices of the Bernstein bases, G_k R = M with
///   G_k[i][j] = ∫ B_i^k B_j^k = C(k,i) C(k,j) / ((2k+1) C(2k, i+j)),
///   M[i][j]   = ∫ B_i^k B_j^n = C(k,i) C(n,j) / ((k+n+1) C(k+n, i+j))
/// (Lutterkort, Peters, Reif, "Polynomial degree reduction in the L2-norm equals best
/// Euclidean approximation of Bézier coefficients", CAGD 16, 1999), solved by Gaussian
/// elimination with partial pivoting in long double. G_k is ill-conditioned for large k
/// (its condition grows like 4^k): exact enough for k <= 10, which covers every use here
/// (fat curves take k = 2 or 3). For k >= n the projection is the identity followed by
/// elevation. Precondition: n >= 0, k >= 0.
[[nodiscard]] BernsteinMatrix l2_reduction_matrix(int n, int k);

/// The row-major entries of l2_reduction_matrix(n, k) from a table built at compile time,
/// for k in {2, 3} and k < n <= 20 (the fat curves' operators); nullptr otherwise.
[[nodiscard]] const double* l2_reduction_table(int n, int k) noexcept;

/// The row-major entries of elevation_matrix(from, to) from a table built at compile time,
/// for 1 <= from <= 3 and from <= to <= 20; nullptr otherwise.
[[nodiscard]] const double* elevation_table(int from, int to) noexcept;

/// m v for a coefficient vector of size m.cols.
[[nodiscard]] std::vector<double> apply(const BernsteinMatrix& m, std::span<const double> v);

/// The same scalar Bernstein polynomial written with degree `to` >= its degree.
[[nodiscard]] std::vector<double> elevate_degree(std::span<const double> coefficients, int to);

/// The L2-best degree-k approximation (see l2_reduction_matrix) of a scalar Bernstein
/// polynomial; for k >= its degree, the polynomial itself elevated to degree k.
[[nodiscard]] std::vector<double> reduce_degree(std::span<const double> coefficients, int k);

/// The same curve with degree `to` >= curve.degree(): control points
/// Q_i = Σ_j C(n, j) C(to - n, i - j) / C(to, i) P_j. The curve B(t) is unchanged (up to
/// rounding: each Q_i is a convex combination of the P_j, so within a few ulps of the
/// coordinate scale).
[[nodiscard]] Curve elevate_degree(const Curve& curve, int to);

/// The L2-best degree-k approximation of a planar curve, coordinate by coordinate (the L2
/// norm of a vector-valued polynomial splits into its coordinates, so the coordinate-wise
/// projection is the best approximation of the curve in ∫ |B(t) - p(t)|^2 dt).
/// Precondition: k >= 0. Degree-elevated curves come back as the original exactly up to
/// rounding.
[[nodiscard]] Curve reduce_degree(const Curve& curve, int k);

}  // namespace bezier::core
