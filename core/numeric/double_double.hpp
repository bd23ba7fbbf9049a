#pragma once

#include <cmath>

#include "core/numeric/error_free.hpp"

namespace bezier::core::dd {

/// A double-double number hi + lo with |lo| <= ulp(hi) / 2: about 106 bits. Used where the
/// intersection search must see below double rounding: pieces of the curves near a
/// tangency, and Newton residuals f(t) - g(s). Error bounds below are relative, with
/// u = 2^-53 (M. Joldes, J.-M. Muller, V. Popescu, "Tight and rigorous error bounds for
/// basic building blocks of double-word arithmetic", ACM TOMS 44(2), 2017).
struct Real {
  double hi = 0.0;
  double lo = 0.0;
};

/// Exact value of a double.
[[nodiscard]] constexpr Real from(double x) noexcept {
  return {x, 0.0};
}

/// hi + lo renormalised, assuming |a| >= |b| or a = 0 (Dekker's Fast2Sum, exact).
[[nodiscard]] constexpr Real fast_two_sum(double a, double b) noexcept {
  const double s = a + b;
  return {s, b - (s - a)};
}

/// a + b, relative error <= 3 u^2 (Joldes et al., Algorithm 6, "AccurateDWPlusDW").
[[nodiscard]] inline Real add(Real a, Real b) noexcept {
  const TwoTerm<double> s = two_sum(a.hi, b.hi);
  const TwoTerm<double> t = two_sum(a.lo, b.lo);
  Real v = fast_two_sum(s.hi, s.lo + t.hi);
  v = fast_two_sum(v.hi, v.lo + t.lo);
  return v;
}

[[nodiscard]] inline Real neg(Real a) noexcept {
  return {-a.hi, -a.lo};
}
[[nodiscard]] inline Real sub(Real a, Real b) noexcept {
  return add(a, neg(b));
}

/// a b for a double b, relative error <= 2 u^2 (Joldes et al., Algorithm 9).
[[nodiscard]] inline Real mul(Real a, double b) noexcept {
  const TwoTerm<double> p = two_product(a.hi, b);
  return fast_two_sum(p.hi, std::fma(a.lo, b, p.lo));
}

/// a b, relative error <= 6 u^2 (Joldes et al., Algorithm 11, "DWTimesDW2": the product of the
/// low parts is left out, which is what separates it from their Algorithm 12).
[[nodiscard]] inline Real mul(Real a, Real b) noexcept {
  const TwoTerm<double> p = two_product(a.hi, b.hi);
  const double cross = std::fma(a.lo, b.hi, a.hi * b.lo);
  return fast_two_sum(p.hi, p.lo + cross);
}

/// (1 - t) a + t b for a double t in [0, 1]: 1 - t is formed exactly as a double-double,
/// so the error is <= 10 u^2 max(|a|, |b|) (two products and one sum, bounds above).
[[nodiscard]] inline Real lerp(Real a, Real b, double t) noexcept {
  const TwoTerm<double> one_minus = two_sum(1.0, -t);
  return add(mul(a, Real{one_minus.hi, one_minus.lo}), mul(b, t));
}

/// The value rounded to a double.
[[nodiscard]] constexpr double to_double(Real a) noexcept {
  return a.hi + a.lo;
}

}  // namespace bezier::core::dd
