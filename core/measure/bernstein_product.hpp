#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/numeric/binomial.hpp"
#include "core/numeric/small_array.hpp"
#include "core/base/point.hpp"

namespace bezier::core {

/// The Bernstein coefficients of the scalar polynomial u(t) · v(t), where u and v are vector
/// polynomials in Bernstein form of degrees m and n (coefficients u_0..u_m, v_0..v_n). The
/// product of two Bernstein bases is b_{i,m} b_{j,n} = C(m,i) C(n,j) / C(m+n,i+j) b_{i+j,m+n}
/// (Farouki & Rajan, "Algorithms for polynomials in Bernstein form", CAGD 5, 1988, §4.1), so
///   w_k = Σ_{i+j=k} C(m,i) C(n,j) / C(m+n,k) (u_i · v_j),   k = 0..m+n.
/// Every weight is in [0, 1] and the weights of one k sum to 1: w_k is a convex combination
/// of the dot products, and its rounding error is at most (d + 3) u max_{i+j=k} |u_i| |v_j|
/// for dimension d (the weight, the dot product and the sum each round). 2-D and 3-D share
/// this code. Precondition: both spans non-empty. O(m n).
template <class P>
[[nodiscard]] std::vector<double> dot_product_polynomial(std::span<const P> u,
                                                         std::span<const P> v) {
  const int m = static_cast<int>(u.size()) - 1, n = static_cast<int>(v.size()) - 1;
  std::vector<double> w(static_cast<std::size_t>(m + n + 1), 0.0);
  // The binomials once each (exact integers, so the same values as computed per term).
  SmallArray<double> cn(static_cast<std::size_t>(n + 1)), cmn(static_cast<std::size_t>(m + n + 1));
  for (int j = 0; j <= n; ++j) cn[static_cast<std::size_t>(j)] = binomial(n, j);
  for (int k = 0; k <= m + n; ++k) cmn[static_cast<std::size_t>(k)] = binomial(m + n, k);
  for (int i = 0; i <= m; ++i) {
    const double ci = binomial(m, i);
    for (int j = 0; j <= n; ++j) {
      const double weight =
          ci * cn[static_cast<std::size_t>(j)] / cmn[static_cast<std::size_t>(i + j)];
      w[static_cast<std::size_t>(i + j)] +=
          weight * dot(u[static_cast<std::size_t>(i)], v[static_cast<std::size_t>(j)]);
    }
  }
  return w;
}

/// The Bernstein coefficients of p'(t) for p of degree n: n (c_{i+1} - c_i), i = 0..n-1
/// (degree n - 1; a constant's derivative is the single coefficient 0).
[[nodiscard]] inline std::vector<double> bernstein_derivative(std::span<const double> c) {
  const std::size_t n = c.size() - 1;
  if (n == 0) return {0.0};
  std::vector<double> d(n);
  for (std::size_t i = 0; i < n; ++i) d[i] = static_cast<double>(n) * (c[i + 1] - c[i]);
  return d;
}

}  // namespace bezier::core
