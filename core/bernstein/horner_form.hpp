#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "core/numeric/binomial.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core::bernstein {

/// p(t) and p'(t) at one t.
struct ValueAndSlope {
  double value, slope;
};

/// A polynomial in Bernstein form on [0, 1], c_0..c_n with E = n + 1 fixed at compile time,
/// prepared for evaluation with its derivative in O(n) operations instead of de Casteljau's
/// O(n^2): Horner's rule in s = t / (1 - t),
///   p(t) = (1 - t)^n Σ C(n, k) c_k s^k,   p'(t) = (1 - t)^(n-1) Σ n C(n-1, k) (c_{k+1} - c_k) s^k,
/// for t <= 1/2, and in r = (1 - t) / t (the same sums read from the other end, times t^n and
/// t^(n-1)) for t > 1/2, so that the ratio is at most 1 (the VS algorithm: Schumaker & Volk,
/// "Efficient evaluation of multivariate polynomial patches", CAGD 3, 1986).
///
/// Rounding of the value (Higham, "Accuracy and Stability of Numerical Algorithms", §5.1):
/// each term C(n, k) c_k b_k(t) of the sum carries at most 6n + 1 roundings of relative size
/// u: one in the weight C(n, k) c_k (the binomial is exact), 2n in Horner's rule (a product
/// and a sum a step), 2 per power of the ratio (1 - t rounds once, and is exact for
/// t >= 1/2; the division once), 2n - 1 in the power of 1 - t or t (its own rounding taken
/// n times, and n - 1 products) and one in the last product. So
///   |computed p(t) - p(t)| <= γ_{6n+2} Σ |c_k| b_k(t) <= γ_{6n+2} max|c_k|,
/// plus (2n + 2) times the smallest subnormal for products that underflow (value_bound()).
/// That is about twice de Casteljau's bound, for a fraction of its work: the evaluation for
/// an iteration, where the bound only decides when to stop. The slope has no stated bound:
/// it steers an iteration, never a sign test. Precondition: max|c_k| <= 2^900 (the weights
/// and sums stay finite; prepared() reports whether they do).
template <std::size_t E>
class HornerForm {
  static_assert(E >= 1);

 public:
  static constexpr std::size_t kDegree = E - 1;

  /// The weights of c (c.size() == E).
  explicit HornerForm(const double* c) {
    double largest = 0.0;
    for (std::size_t k = 0; k <= kDegree; ++k) {
      value_weights_[k] = kValueBinomials[k] * c[k];
      largest = std::max(largest, std::fabs(c[k]));
      if (k < kDegree) slope_weights_[k] = kSlopeBinomials[k] * (c[k + 1] - c[k]);
    }
    value_bound_ = kValueRoundings * 1.01 * kUnitRoundoff * largest +
                   (2.0 * kDegree + 2.0) * std::numeric_limits<double>::denorm_min();
    finite_ = largest <= 0x1p900;
  }

  /// Whether c is within the precondition's range (otherwise use de Casteljau).
  [[nodiscard]] bool prepared() const { return finite_; }

  /// The bound on the rounding error of value_and_slope(t).value (see the class comment).
  [[nodiscard]] double value_bound() const { return value_bound_; }

  [[nodiscard]] ValueAndSlope value_and_slope(double t) const {
    if constexpr (kDegree == 0) {
      return {value_weights_[0], 0.0};
    } else {
      constexpr std::size_t n = kDegree;
      const bool near_zero = t <= 0.5;
      const double base = near_zero ? 1.0 - t : t;
      const double ratio = near_zero ? t / base : (1.0 - t) / t;
      double power = 1.0;  // base^(n-1)
      for (std::size_t i = 1; i < n; ++i) power *= base;
      double value, slope;
      if (near_zero) {
        value = value_weights_[n];
        for (std::size_t k = n; k-- > 0;) value = value * ratio + value_weights_[k];
        slope = slope_weights_[n - 1];
        for (std::size_t k = n - 1; k-- > 0;) slope = slope * ratio + slope_weights_[k];
      } else {
        value = value_weights_[0];
        for (std::size_t k = 1; k <= n; ++k) value = value * ratio + value_weights_[k];
        slope = slope_weights_[0];
        for (std::size_t k = 1; k < n; ++k) slope = slope * ratio + slope_weights_[k];
      }
      return {value * (power * base), slope * power};
    }
  }

 private:
  static constexpr double kValueRoundings = 6.0 * static_cast<double>(kDegree) + 2.0;
  /// C(n, k) and n C(n - 1, k), k = 0..n (the last slope entry unused), exact integers.
  static constexpr std::array<double, E> kValueBinomials = [] {
    std::array<double, E> out{};
    for (std::size_t k = 0; k <= kDegree; ++k) out[k] = binomial(static_cast<int>(kDegree), static_cast<int>(k));
    return out;
  }();
  static constexpr std::array<double, E> kSlopeBinomials = [] {
    std::array<double, E> out{};
    for (std::size_t k = 0; k < kDegree; ++k) {
      out[k] = static_cast<double>(kDegree) * binomial(static_cast<int>(kDegree) - 1, static_cast<int>(k));
    }
    return out;
  }();
  std::array<double, E> value_weights_{};
  std::array<double, E> slope_weights_{};
  double value_bound_ = 0.0;
  bool finite_ = true;
};

}  // namespace bezier::core::bernstein
