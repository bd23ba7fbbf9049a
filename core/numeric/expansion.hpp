#pragma once

#include <span>
#include <vector>

namespace bezier::core {

/// An exact real number held as a floating-point expansion: a sum of doubles
/// e_0 + e_1 + ... + e_{m-1}, nonoverlapping and sorted by increasing magnitude, with no
/// zero components (J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast
/// Robust Geometric Predicates", Discrete & Computational Geometry 18, 1997, §2). Sums,
/// differences and products of expansions are exact, so the sign of a polynomial in double
/// inputs can be decided exactly: it is the sign of the largest component.
///
/// Contract: exact as long as nothing overflows and no product's rounding error falls below
/// the subnormal range, i.e. every product a b taken has exponent(lsb a) + exponent(lsb b)
/// >= -1074 (lsb: least significant set bit). Callers scale their inputs by a power of two
/// (exact) to stay in that window; see cubic_predicates.hpp. Round-to-nearest-even (the IEEE
/// default) is assumed, and no -ffast-math. Inputs must be finite.
///
/// This is the slow, exact path behind floating-point filters: it allocates, and an
/// expansion may grow to a few dozen components for degree-4 polynomials.
class Expansion {
 public:
  /// Zero.
  Expansion() = default;
  /// The double x exactly (one component, none when x = 0).
  explicit Expansion(double x) {
    if (x != 0.0) components_.push_back(x);
  }

  /// The exact difference a - b, as at most two components (TwoSum of a and -b).
  [[nodiscard]] static Expansion difference(double a, double b);

  /// Components, nonoverlapping, increasing magnitude, all nonzero (empty for zero).
  [[nodiscard]] std::span<const double> components() const noexcept { return components_; }

  /// -1, 0 or +1: the sign of the exact value (that of the largest component).
  [[nodiscard]] int sign() const noexcept;

  /// The value rounded to a double (the components summed from the smallest up, which is
  /// within about one ulp after compress()).
  [[nodiscard]] double estimate() const noexcept;

  friend Expansion operator+(const Expansion& e, const Expansion& f);
  friend Expansion operator-(const Expansion& e, const Expansion& f);
  friend Expansion operator-(Expansion e);
  /// e b, exact (Shewchuk's Scale-Expansion with zero elimination, then compressed).
  friend Expansion operator*(const Expansion& e, double b);
  friend Expansion operator*(double b, const Expansion& e) { return e * b; }
  /// e f, exact: the sum of e f_j over the components f_j of f.
  friend Expansion operator*(const Expansion& e, const Expansion& f);

 private:
  /// Shewchuk's Compress: the same value with as few components as the greedy
  /// renormalisation gives (the largest component then approximates the value to within
  /// one ulp).
  void compress();

  std::vector<double> components_;
};

}  // namespace bezier::core
