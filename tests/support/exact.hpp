#pragma once

// Exact arithmetic for tests: Rational, an exact fraction of BigInts (big_int.hpp), and exact
// 2-D / 3-D points. Every finite double is a dyadic rational m 2^e, so a kernel result
// computed in doubles can be compared with the exact value of the same formula on the same
// (double) inputs, rounded once by Rational::to_double(). Bézier-specific helpers (exact
// de Casteljau, condition scales, the accuracy contract) are in exact_bezier.hpp.

#include <algorithm>
#include <cassert>
#include <cmath>
#include <compare>
#include <concepts>
#include <cstdint>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>

#include "core/base/point.hpp"
#include "tests/support/big_int.hpp"

namespace bezier::test {

/// An exact rational p / q, always normalised: q > 0 and gcd(p, q) = 1 (zero is 0 / 1),
/// so == compares representations.
class Rational {
 public:
  Rational() = default;
  /// The integer v. Any integral type converts (templated so that Rational(3) is not
  /// ambiguous between the integer and the double constructor).
  template <std::integral I>
  Rational(I v) {                           // NOLINT(google-explicit-constructor)
    if constexpr (std::is_unsigned_v<I>) {  // may exceed long long: two 32-bit halves
      const auto u = static_cast<unsigned long long>(v);
      p_ = (BigInt(static_cast<long long>(u >> 32)) << 32) +
           BigInt(static_cast<long long>(u & 0xFFFFFFFFu));
    } else {
      p_ = BigInt(static_cast<long long>(v));
    }
  }
  /// Exactly the value of the finite double x: with frexp, x = m 2^e, 0.5 <= |m| < 1, so
  /// m 2^53 is an integer (subnormals included) and x = (m 2^53) 2^(e-53) exactly.
  Rational(double x) {  // NOLINT(google-explicit-constructor)
    assert(std::isfinite(x));
    int e = 0;
    const double m = std::frexp(x, &e);
    p_ = BigInt(static_cast<long long>(std::ldexp(m, 53)));
    const std::int64_t shift = static_cast<std::int64_t>(e) - 53;
    if (shift >= 0) {
      p_ = p_ << shift;
    } else {
      q_ = BigInt(1) << -shift;
      normalise();
    }
  }
  /// p / q. Precondition: q != 0.
  Rational(BigInt p, BigInt q) : p_(std::move(p)), q_(std::move(q)) { normalise(); }

  [[nodiscard]] const BigInt& num() const noexcept { return p_; }
  [[nodiscard]] const BigInt& den() const noexcept { return q_; }
  [[nodiscard]] int sign() const noexcept { return p_.sign(); }
  [[nodiscard]] bool is_zero() const noexcept { return p_.is_zero(); }
  [[nodiscard]] Rational abs() const { return Rational(p_.abs(), q_, Normalised{}); }
  friend Rational abs(const Rational& r) { return r.abs(); }

  friend Rational operator-(const Rational& a) { return Rational(-a.p_, a.q_, Normalised{}); }
  friend Rational operator+(const Rational& a, const Rational& b) {
    if (a.q_ == b.q_) return Rational(a.p_ + b.p_, a.q_);
    return Rational(a.p_ * b.q_ + b.p_ * a.q_, a.q_ * b.q_);
  }
  friend Rational operator-(const Rational& a, const Rational& b) { return a + (-b); }
  friend Rational operator*(const Rational& a, const Rational& b) {
    return Rational(a.p_ * b.p_, a.q_ * b.q_);
  }
  /// Precondition: b != 0.
  friend Rational operator/(const Rational& a, const Rational& b) {
    assert(!b.is_zero());
    return Rational(a.p_ * b.q_, a.q_ * b.p_);
  }
  Rational& operator+=(const Rational& b) { return *this = *this + b; }
  Rational& operator-=(const Rational& b) { return *this = *this - b; }
  Rational& operator*=(const Rational& b) { return *this = *this * b; }
  Rational& operator/=(const Rational& b) { return *this = *this / b; }

  friend bool operator==(const Rational&, const Rational&) = default;
  friend std::strong_ordering operator<=>(const Rational& a, const Rational& b) {
    return a.p_ * b.q_ <=> b.p_ * a.q_;  // q > 0 on both sides keeps the order
  }

  /// The double nearest to p / q, ties to even (IEEE 754 round-to-nearest), with gradual
  /// underflow to subnormals and zero, and overflow to ±infinity exactly where IEEE
  /// rounding overflows (|x| >= 2^1024 - 2^970).
  [[nodiscard]] double to_double() const {
    if (is_zero()) return 0.0;
    const BigInt p = p_.abs();
    // Scale so that the integer quotient Q = floor(p 2^s / q) has at least 55 bits; the
    // value is (Q + r/q) 2^-s, and r != 0 is the sticky bit for rounding.
    const std::int64_t s = 55 - (p.bit_length() - q_.bit_length()) + 1;
    auto [quot, rem] = s >= 0 ? divmod(p << s, q_) : divmod(p, q_ << -s);
    const std::int64_t exponent =
        quot.bit_length() - 1 - s;  // value in [2^exponent, 2^(exponent+1))
    // Exponent of the last kept bit: 53 significant bits, but never below 2^-1074.
    const std::int64_t lsb = std::max<std::int64_t>(exponent - 52, -1074);
    const std::int64_t drop = lsb + s;  // low bits of Q to round away (>= 2 when normal)
    std::uint64_t mantissa = 0;
    if (drop <= quot.bit_length()) {
      mantissa = (quot >> drop).low_u64();
      const BigInt low = quot - ((quot >> drop) << drop);
      const BigInt half = BigInt(1) << (drop - 1);
      const auto c = low <=> half;
      const bool exact_half = c == 0 && rem.is_zero();
      if (c > 0 || (c == 0 && !exact_half) || (exact_half && (mantissa & 1))) ++mantissa;
    }  // else Q < 2^(drop-1): below half of the smallest subnormal, rounds to 0
    // mantissa <= 2^53, so mantissa 2^lsb is representable or overflows to infinity.
    const double magnitude =
        std::ldexp(static_cast<double>(mantissa),
                   static_cast<int>(std::clamp<std::int64_t>(lsb, -2000, 2000)));
    return sign() < 0 ? -magnitude : magnitude;
  }

  /// "p/q", or "p" when q = 1.
  [[nodiscard]] std::string str() const {
    return q_ == BigInt(1) ? p_.str() : p_.str() + "/" + q_.str();
  }
  friend std::ostream& operator<<(std::ostream& os, const Rational& r) { return os << r.str(); }

 private:
  struct Normalised {};
  Rational(BigInt p, BigInt q, Normalised) : p_(std::move(p)), q_(std::move(q)) {}

  void normalise() {
    assert(!q_.is_zero());
    if (q_.is_negative()) {
      p_ = -p_;
      q_ = -q_;
    }
    if (p_.is_zero()) {
      q_ = BigInt(1);
      return;
    }
    const BigInt g = gcd(p_, q_);
    if (g != BigInt(1)) {
      p_ = p_ / g;
      q_ = q_ / g;
    }
  }

  BigInt p_;
  BigInt q_ = BigInt(1);
};

/// Exact 2-D and 3-D points: the coordinates of a core point as Rationals, with the vector
/// operations de Casteljau needs. exact(p) converts exactly, to_double(p) rounds each
/// coordinate once.
struct RPoint2 {
  Rational x, y;
  friend bool operator==(const RPoint2&, const RPoint2&) = default;
  friend RPoint2 operator+(const RPoint2& a, const RPoint2& b) { return {a.x + b.x, a.y + b.y}; }
  friend RPoint2 operator-(const RPoint2& a, const RPoint2& b) { return {a.x - b.x, a.y - b.y}; }
  friend RPoint2 operator*(const Rational& s, const RPoint2& a) { return {s * a.x, s * a.y}; }
  friend std::ostream& operator<<(std::ostream& os, const RPoint2& p) {
    return os << "(" << p.x << ", " << p.y << ")";
  }
};
struct RPoint3 {
  Rational x, y, z;
  friend bool operator==(const RPoint3&, const RPoint3&) = default;
  friend RPoint3 operator+(const RPoint3& a, const RPoint3& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
  }
  friend RPoint3 operator-(const RPoint3& a, const RPoint3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
  }
  friend RPoint3 operator*(const Rational& s, const RPoint3& a) {
    return {s * a.x, s * a.y, s * a.z};
  }
  friend std::ostream& operator<<(std::ostream& os, const RPoint3& p) {
    return os << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  }
};
inline RPoint2 exact(core::Point2 p) {
  return {p.x, p.y};
}
inline RPoint3 exact(core::Point3 p) {
  return {p.x, p.y, p.z};
}
inline core::Point2 to_double(const RPoint2& p) {
  return {p.x.to_double(), p.y.to_double()};
}
inline core::Point3 to_double(const RPoint3& p) {
  return {p.x.to_double(), p.y.to_double(), p.z.to_double()};
}
inline RPoint2 abs(const RPoint2& p) {
  return {abs(p.x), abs(p.y)};
}
inline RPoint3 abs(const RPoint3& p) {
  return {abs(p.x), abs(p.y), abs(p.z)};
}

}  // namespace bezier::test
