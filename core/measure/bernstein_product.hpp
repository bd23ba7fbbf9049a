#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "core/base/point.hpp"
#include "core/numeric/binomial.hpp"
#include "core/numeric/small_array.hpp"

namespace bezier::core {

/// C(N, k) for N < kBinomialRows (the products of polynomials of degree up to 23), computed
/// at compile time by binomial().
inline constexpr int kBinomialRows = 48;
inline constexpr auto kBinomials = [] {
  std::array<std::array<double, kBinomialRows>, kBinomialRows> table{};
  for (int top = 0; top < kBinomialRows; ++top) {
    for (int k = 0; k <= top; ++k) {
      table[static_cast<std::size_t>(top)][static_cast<std::size_t>(k)] = binomial(top, k);
    }
  }
  return table;
}();

/// C(N, k) from the table or, beyond it, from binomial().
[[nodiscard]] constexpr double choose(int top, int k) {
  return top < kBinomialRows ? kBinomials[static_cast<std::size_t>(top)][static_cast<std::size_t>(k)]
                             : binomial(top, k);
}

/// The weight C(m, i) C(n, j) / C(m + n, i + j) of u_i · v_j in w_{i+j}, ci = C(m, i).
[[nodiscard]] constexpr double product_weight(int m, int n, int i, int j, double ci) {
  return ci * choose(n, j) / choose(m + n, i + j);
}

/// The weights of the product of a degree-m polynomial and a degree-(m - 1) one (a curve's
/// offsets and its hodograph, as /nearest multiplies them), m < kCurveHodographRows,
/// computed at compile time (the same values as product_weight: each is one correctly
/// rounded quotient of exact integers), m + 1 rows of m each, the degrees one after the
/// other from m = 1.
inline constexpr int kCurveHodographRows = 13;
[[nodiscard]] constexpr std::size_t curve_hodograph_offset(int m) {
  return static_cast<std::size_t>((m - 1) * m * (m + 1) / 3);  // Σ_{k<m} (k + 1) k
}
inline constexpr auto kCurveHodographWeights = [] {
  std::array<double, curve_hodograph_offset(kCurveHodographRows)> table{};
  for (int m = 1; m < kCurveHodographRows; ++m) {
    std::size_t next = curve_hodograph_offset(m);
    for (int i = 0; i <= m; ++i) {
      for (int j = 0; j < m; ++j) table[next++] = product_weight(m, m - 1, i, j, choose(m, i));
    }
  }
  return table;
}();

/// The Bernstein coefficients of the scalar polynomial u(t) · v(t), where u and v are vector
/// polynomials in Bernstein form of degrees m and n (coefficients u_0..u_m, v_0..v_n). The
/// product of two Bernstein bases is b_{i,m} b_{j,n} = C(m,i) C(n,j) / C(m+n,i+j) b_{i+j,m+n}
/// (Farouki & Rajan, "Algorithms for polynomials in Bernstein form", CAGD 5, 1988, §4.1), so
///   w_k = Σ_{i+j=k} C(m,i) C(n,j) / C(m+n,k) (u_i · v_j),   k = 0..m+n.
/// Every weight is in [0, 1] and the weights of one k sum to 1: w_k is a convex combination
/// of the dot products, and its rounding error is at most (d + 3) u max_{i+j=k} |u_i| |v_j|
/// for dimension d (the weight, the dot product and the sum each round). 2-D and 3-D share
/// this code. Written into w[0..m+n], u and v given by their points u(i), i = 0..m, and
/// v(j), j = 0..n (so that neither has to be stored). O(m n).
template <class U, class V>
void dot_product_polynomial_into(int m, int n, U u, V v, double* w) {
  std::fill(w, w + m + n + 1, 0.0);
  if (n == m - 1 && m < kCurveHodographRows) {
    const double* weight = kCurveHodographWeights.data() + curve_hodograph_offset(m);
    for (int i = 0; i <= m; ++i) {
      const auto ui = u(i);
      for (int j = 0; j <= n; ++j) w[i + j] += *weight++ * dot(ui, v(j));
    }
    return;
  }
  for (int i = 0; i <= m; ++i) {
    const auto ui = u(i);
    const double ci = choose(m, i);
    for (int j = 0; j <= n; ++j) w[i + j] += product_weight(m, n, i, j, ci) * dot(ui, v(j));
  }
}

/// dot_product_polynomial_into as new coefficients, u and v stored. Precondition: both
/// spans non-empty.
template <class P>
[[nodiscard]] Coeffs dot_product_polynomial(std::span<const P> u, std::span<const P> v) {
  Coeffs w(u.size() + v.size() - 1, Coeffs::Uninitialized{});
  dot_product_polynomial_into(
      static_cast<int>(u.size()) - 1, static_cast<int>(v.size()) - 1,
      [u](int i) { return u[static_cast<std::size_t>(i)]; },
      [v](int j) { return v[static_cast<std::size_t>(j)]; }, w.data());
  return w;
}

/// The Bernstein coefficients of p'(t) for p of degree n: n (c_{i+1} - c_i), i = 0..n-1
/// (degree n - 1; a constant's derivative is the single coefficient 0).
[[nodiscard]] inline Coeffs bernstein_derivative(std::span<const double> c) {
  const std::size_t n = c.size() - 1;
  if (n == 0) return Coeffs(1, 0.0);
  Coeffs d(n, Coeffs::Uninitialized{});
  for (std::size_t i = 0; i < n; ++i) d[i] = static_cast<double>(n) * (c[i + 1] - c[i]);
  return d;
}

}  // namespace bezier::core
