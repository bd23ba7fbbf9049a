#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>

#include "core/numeric/binomial.hpp"
#include "core/numeric/min_max.hpp"
#include "core/bernstein/tuning.hpp"
#include "core/numeric/small_array.hpp"
#include "core/numeric/fixed_extent.hpp"
#include "core/numeric/power_of_two.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {

namespace monomial_detail {

/// The differences for monomial, in place in d (E entries, with_fixed_extent: a constant
/// number for degrees 1 to 3, so the loops unroll).
template <std::size_t E>
Coeffs monomial_from(std::span<double, E> d) {
  const std::size_t n = d.size() - 1;
  Coeffs a(d.size(), Coeffs::Uninitialized{});
  double choose = 1.0;  // C(n, k), exact for the degrees accepted
  for (std::size_t k = 0; k <= n; ++k) {
    a[k] = choose * d[0];
    for (std::size_t i = 0; i + k < n; ++i) d[i] = d[i + 1] - d[i];
    choose = choose * static_cast<double>(n - k) / static_cast<double>(k + 1);
  }
  return a;
}

}  // namespace monomial_detail

/// Monomial coefficients a_k = C(n,k) Δ^k P_0 of one coordinate of a Bézier curve on
/// [0, 1] (Δ^k: the k-th forward difference of the control points; Farin, §5.4), by
/// repeated differences.
[[nodiscard]] inline Coeffs monomial(std::span<const double> c) {
  return with_fixed_extent(c.size(), [&](auto e) {
    constexpr std::size_t E = decltype(e)::value;
    if constexpr (E == std::dynamic_extent) {
      Coeffs d(c);
      return monomial_detail::monomial_from(d.span());
    } else {
      std::array<double, E> d;
      std::copy_n(c.begin(), E, d.begin());  // E, not c.size(): no memcpy call
      return monomial_detail::monomial_from(std::span<double, E>(d));
    }
  });
}

namespace monomial_detail {

/// Δ^(E-1) of E values: level by level into fresh arrays, d_i <- d_(i+1) - d_i as in
/// monomial_from, the first level read from d itself. (A copy of d, differenced in place,
/// makes GCC store the values and reload overlapping pairs, which stalls store forwarding.)
template <std::size_t E>
double top_forward_difference(std::span<const double, E> d) noexcept {
  if constexpr (E == 1) {
    return d[0];
  } else {
    std::array<double, E - 1> next;
    for (std::size_t i = 0; i + 1 < E; ++i) next[i] = d[i + 1] - d[i];
    return top_forward_difference(std::span<const double, E - 1>(next));
  }
}

}  // namespace monomial_detail

/// The top monomial coefficient a_n = Δ^n P_0 of one coordinate, by the same differences in
/// the same order as monomial() (so bit for bit its a_n: C(n, n) = 1 there exactly), on the
/// stack for the low degrees.
[[nodiscard]] inline double top_monomial_coefficient(const Coeffs& c) {
  return with_fixed_extent(c.size(), [&](auto e) {
    constexpr std::size_t E = decltype(e)::value;
    if constexpr (E == std::dynamic_extent) {
      return monomial(c)[c.size() - 1];
    } else {
      return monomial_detail::top_forward_difference(fixed_span<E>(c.data(), E));
    }
  });
}

/// Whether monomial coefficient k = (ax_k, ay_k) of a degree-n curve is above the rounding
/// of the conversion (C(n,k) 2^k u magnitude, with the safety factor
/// bernstein_tuning::kSignificantCoefficientFactor).
[[nodiscard]] inline bool significant_coefficient(int n, int k, double ax_k, double ay_k,
                                                  double magnitude) {
  const double tol = bernstein_tuning::kSignificantCoefficientFactor * binomial(n, k) *
                     power_of_two(k) * kUnitRoundoff * magnitude;
  return max2(std::fabs(ax_k), std::fabs(ay_k)) > tol;
}

/// The largest k whose monomial coefficient is significant: a degree-elevated curve, rounded
/// to doubles, has nothing else above its true degree.
[[nodiscard]] inline int true_degree(const Coeffs& ax, const Coeffs& ay, double magnitude) {
  const int n = static_cast<int>(ax.size()) - 1;
  for (int k = n; k >= 1; --k) {
    const auto i = static_cast<std::size_t>(k);
    if (significant_coefficient(n, k, ax[i], ay[i], magnitude)) return k;
  }
  return 0;
}

}  // namespace bezier::core
