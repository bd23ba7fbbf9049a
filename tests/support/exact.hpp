#pragma once

// Exact arithmetic for tests: an arbitrary-precision BigInt and a Rational on top of it.
// Every finite double is a dyadic rational m 2^e, so a kernel result computed in doubles
// can be compared with the exact value of the same formula on the same (double) inputs,
// rounded once by Rational::to_double(). Clarity over speed, with one exception that
// matters for Bézier tests: denominators are almost always powers of two, so gcd and
// division have fast paths for powers of two.

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <compare>
#include <concepts>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/curve.hpp"
#include "core/point.hpp"

namespace bezier::test {

/// Signed arbitrary-precision integer: sign and magnitude, the magnitude as base-2^32
/// limbs, least significant first, without leading zero limbs (zero is no limbs and never
/// negative).
class BigInt {
 public:
  using Limbs = std::vector<std::uint32_t>;

  BigInt() = default;
  BigInt(long long v) : neg_(v < 0) {  // NOLINT(google-explicit-constructor): 2 * x reads well
    // Negate in unsigned arithmetic: -LLONG_MIN overflows as a signed value.
    std::uint64_t m = neg_ ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
    for (; m != 0; m >>= 32) mag_.push_back(static_cast<std::uint32_t>(m));
  }

  [[nodiscard]] bool is_zero() const noexcept { return mag_.empty(); }
  [[nodiscard]] bool is_negative() const noexcept { return neg_; }
  /// -1, 0 or 1.
  [[nodiscard]] int sign() const noexcept { return is_zero() ? 0 : (neg_ ? -1 : 1); }
  /// Number of bits of |x| (0 for zero).
  [[nodiscard]] std::int64_t bit_length() const noexcept {
    return mag_.empty() ? 0 : 32 * static_cast<std::int64_t>(mag_.size() - 1) + std::bit_width(mag_.back());
  }
  /// Number of trailing zero bits of |x|; 0 for zero.
  [[nodiscard]] std::int64_t trailing_zeros() const noexcept {
    for (std::size_t i = 0; i < mag_.size(); ++i)
      if (mag_[i] != 0) return 32 * static_cast<std::int64_t>(i) + std::countr_zero(mag_[i]);
    return 0;
  }
  /// |x| is a power of two.
  [[nodiscard]] bool is_power_of_two() const noexcept { return !is_zero() && bit_length() == trailing_zeros() + 1; }
  /// The low 64 bits of |x|.
  [[nodiscard]] std::uint64_t low_u64() const noexcept {
    std::uint64_t r = mag_.empty() ? 0 : mag_[0];
    if (mag_.size() > 1) r |= static_cast<std::uint64_t>(mag_[1]) << 32;
    return r;
  }
  [[nodiscard]] BigInt abs() const { BigInt r = *this; r.neg_ = false; return r; }

  friend BigInt operator-(BigInt a) { a.neg_ = !a.neg_ && !a.is_zero(); return a; }
  friend BigInt operator+(const BigInt& a, const BigInt& b) {
    if (a.neg_ == b.neg_) return make(add_mag(a.mag_, b.mag_), a.neg_);
    // Opposite signs: subtract the smaller magnitude from the larger.
    if (cmp_mag(a.mag_, b.mag_) >= 0) return make(sub_mag(a.mag_, b.mag_), a.neg_);
    return make(sub_mag(b.mag_, a.mag_), b.neg_);
  }
  friend BigInt operator-(const BigInt& a, const BigInt& b) { return a + (-b); }
  friend BigInt operator*(const BigInt& a, const BigInt& b) { return make(mul_mag(a.mag_, b.mag_), a.neg_ != b.neg_); }
  /// Truncating division (rounds toward zero, like built-in integers). Precondition: b != 0.
  friend BigInt operator/(const BigInt& a, const BigInt& b) { return divmod(a, b).first; }
  /// Remainder with the sign of a (a == (a / b) * b + a % b). Precondition: b != 0.
  friend BigInt operator%(const BigInt& a, const BigInt& b) { return divmod(a, b).second; }
  /// |x| 2^k with the sign of x.
  friend BigInt operator<<(const BigInt& a, std::int64_t k) { assert(k >= 0); return make(shl_mag(a.mag_, k), a.neg_); }
  /// |x| / 2^k truncated, with the sign of x (so it rounds toward zero).
  friend BigInt operator>>(const BigInt& a, std::int64_t k) { assert(k >= 0); return make(shr_mag(a.mag_, k), a.neg_); }

  friend bool operator==(const BigInt&, const BigInt&) = default;
  friend std::strong_ordering operator<=>(const BigInt& a, const BigInt& b) {
    if (a.sign() != b.sign()) return a.sign() <=> b.sign();
    const int c = cmp_mag(a.mag_, b.mag_);
    return (a.neg_ ? -c : c) <=> 0;
  }

  /// Quotient (toward zero) and remainder (sign of a). Precondition: b != 0.
  friend std::pair<BigInt, BigInt> divmod(const BigInt& a, const BigInt& b) {
    assert(!b.is_zero());
    auto [q, r] = divmod_mag(a.mag_, b.mag_);
    return {make(std::move(q), a.neg_ != b.neg_), make(std::move(r), a.neg_)};
  }

  /// gcd(|a|, |b|) >= 0; gcd(0, 0) = 0. Binary (Stein) algorithm: shifts and
  /// subtractions only, and O(size) when one operand is a power of two times 1.
  friend BigInt gcd(BigInt a, BigInt b) {
    a.neg_ = b.neg_ = false;
    if (a.is_zero()) return b;
    if (b.is_zero()) return a;
    const std::int64_t za = a.trailing_zeros(), zb = b.trailing_zeros();
    const std::int64_t common = std::min(za, zb);
    a = a >> za;
    b = b >> zb;
    // Both odd from here on; |a - b| is even and nonzero until they meet.
    while (a != b) {
      if (a == BigInt(1) || b == BigInt(1)) return BigInt(1) << common;
      if (a < b) std::swap(a, b);
      a = a - b;
      a = a >> a.trailing_zeros();
    }
    return a << common;
  }

  /// Decimal digits, with a leading '-' when negative.
  [[nodiscard]] std::string str() const {
    if (is_zero()) return "0";
    std::string digits;
    Limbs m = mag_;
    while (!m.empty()) {  // repeated division by 10^9, nine digits at a time
      std::uint64_t rem = 0;
      for (std::size_t i = m.size(); i-- > 0;) {
        const std::uint64_t cur = (rem << 32) | m[i];
        m[i] = static_cast<std::uint32_t>(cur / 1000000000u);
        rem = cur % 1000000000u;
      }
      while (!m.empty() && m.back() == 0) m.pop_back();
      for (int k = 0; k < 9 && (rem != 0 || !m.empty()); ++k, rem /= 10) digits.push_back(static_cast<char>('0' + rem % 10));
    }
    if (neg_) digits.push_back('-');
    return {digits.rbegin(), digits.rend()};
  }

 private:
  static BigInt make(Limbs m, bool neg) {
    while (!m.empty() && m.back() == 0) m.pop_back();
    BigInt r;
    r.neg_ = neg && !m.empty();
    r.mag_ = std::move(m);
    return r;
  }
  static int cmp_mag(const Limbs& a, const Limbs& b) {
    if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
    for (std::size_t i = a.size(); i-- > 0;)
      if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    return 0;
  }
  static Limbs add_mag(const Limbs& a, const Limbs& b) {
    Limbs r(std::max(a.size(), b.size()) + 1);
    std::uint64_t carry = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      carry += (i < a.size() ? a[i] : 0ull) + (i < b.size() ? b[i] : 0ull);
      r[i] = static_cast<std::uint32_t>(carry);
      carry >>= 32;
    }
    return r;
  }
  /// a - b; precondition |a| >= |b|.
  static Limbs sub_mag(const Limbs& a, const Limbs& b) {
    Limbs r(a.size());
    std::int64_t borrow = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      std::int64_t d = static_cast<std::int64_t>(a[i]) - (i < b.size() ? b[i] : 0) - borrow;
      borrow = d < 0;
      r[i] = static_cast<std::uint32_t>(d + (borrow << 32));
    }
    assert(borrow == 0);
    return r;
  }
  static Limbs mul_mag(const Limbs& a, const Limbs& b) {
    if (a.empty() || b.empty()) return {};
    Limbs r(a.size() + b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      std::uint64_t carry = 0;
      for (std::size_t j = 0; j < b.size(); ++j) {
        carry += static_cast<std::uint64_t>(a[i]) * b[j] + r[i + j];
        r[i + j] = static_cast<std::uint32_t>(carry);
        carry >>= 32;
      }
      r[i + b.size()] = static_cast<std::uint32_t>(carry);
    }
    return r;
  }
  static Limbs shl_mag(const Limbs& a, std::int64_t k) {
    if (a.empty()) return {};
    const std::size_t limbs = static_cast<std::size_t>(k / 32);
    const int bits = static_cast<int>(k % 32);
    Limbs r(a.size() + limbs + 1, 0);
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::uint64_t v = static_cast<std::uint64_t>(a[i]) << bits;
      r[i + limbs] |= static_cast<std::uint32_t>(v);
      r[i + limbs + 1] |= static_cast<std::uint32_t>(v >> 32);
    }
    return r;
  }
  static Limbs shr_mag(const Limbs& a, std::int64_t k) {
    const std::size_t limbs = static_cast<std::size_t>(k / 32);
    if (limbs >= a.size()) return {};
    const int bits = static_cast<int>(k % 32);
    Limbs r(a.size() - limbs);
    for (std::size_t i = 0; i < r.size(); ++i) {
      std::uint64_t v = a[i + limbs];
      if (i + limbs + 1 < a.size()) v |= static_cast<std::uint64_t>(a[i + limbs + 1]) << 32;
      r[i] = static_cast<std::uint32_t>(v >> bits);
    }
    return r;
  }
  /// Long division of magnitudes: Knuth, TAOCP vol. 2, §4.3.1, Algorithm D (in the
  /// formulation of Warren, "Hacker's Delight", 2nd ed., §9-2, divmnu). Precondition: v != 0.
  static std::pair<Limbs, Limbs> divmod_mag(const Limbs& u, const Limbs& v) {
    if (cmp_mag(u, v) < 0) return {{}, u};
    const BigInt vb = make(v, false);
    if (vb.is_power_of_two()) {  // the common case for dyadic rationals: a shift
      const std::int64_t k = vb.trailing_zeros();
      Limbs low = u;
      low.resize(static_cast<std::size_t>(k / 32) + 1, 0);
      low.back() &= static_cast<std::uint32_t>((1ull << (k % 32)) - 1);
      return {shr_mag(u, k), std::move(low)};
    }
    if (v.size() == 1) {  // one-limb divisor: schoolbook with 64-bit intermediates
      Limbs q(u.size());
      std::uint64_t rem = 0;
      for (std::size_t i = u.size(); i-- > 0;) {
        const std::uint64_t cur = (rem << 32) | u[i];
        q[i] = static_cast<std::uint32_t>(cur / v[0]);
        rem = cur % v[0];
      }
      return {std::move(q), Limbs{static_cast<std::uint32_t>(rem)}};
    }
    // D1: normalise so that the divisor's top limb has its high bit set; then the trial
    // quotient qhat from the top two limbs is at most 2 too large.
    const int s = std::countl_zero(v.back());
    Limbs vn = shl_mag(v, s);
    vn.resize(v.size());
    Limbs un = shl_mag(u, s);
    un.resize(u.size() + 1);
    const std::size_t n = vn.size(), m = u.size() - n;
    constexpr std::uint64_t kBase = 1ull << 32;
    Limbs q(m + 1);
    for (std::size_t j = m + 1; j-- > 0;) {
      // D3: estimate qhat and correct it with the second divisor limb.
      const std::uint64_t num = (static_cast<std::uint64_t>(un[j + n]) << 32) | un[j + n - 1];
      std::uint64_t qhat = num / vn[n - 1];
      std::uint64_t rhat = num % vn[n - 1];
      while (qhat >= kBase || qhat * vn[n - 2] > ((rhat << 32) | un[j + n - 2])) {
        --qhat;
        rhat += vn[n - 1];
        if (rhat >= kBase) break;
      }
      // D4: multiply and subtract qhat * vn from un[j .. j + n].
      std::int64_t borrow = 0;
      std::int64_t t = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const std::uint64_t p = qhat * vn[i];
        t = static_cast<std::int64_t>(un[i + j]) - borrow - static_cast<std::int64_t>(p & 0xFFFFFFFFu);
        un[i + j] = static_cast<std::uint32_t>(t);
        borrow = static_cast<std::int64_t>(p >> 32) - (t >> 32);
      }
      t = static_cast<std::int64_t>(un[j + n]) - borrow;
      un[j + n] = static_cast<std::uint32_t>(t);
      q[j] = static_cast<std::uint32_t>(qhat);
      if (t < 0) {  // D6: qhat was one too large (rare): add the divisor back.
        --q[j];
        std::uint64_t carry = 0;
        for (std::size_t i = 0; i < n; ++i) {
          carry += static_cast<std::uint64_t>(un[i + j]) + vn[i];
          un[i + j] = static_cast<std::uint32_t>(carry);
          carry >>= 32;
        }
        un[j + n] = static_cast<std::uint32_t>(un[j + n] + carry);
      }
    }
    un.resize(n);  // D8: the remainder is un / 2^s
    return {std::move(q), shr_mag(un, s)};
  }

  bool neg_ = false;
  Limbs mag_;
};

/// An exact rational p / q, always normalised: q > 0 and gcd(p, q) = 1 (zero is 0 / 1),
/// so == compares representations.
class Rational {
 public:
  Rational() = default;
  /// The integer v. Any integral type converts (templated so that Rational(3) is not
  /// ambiguous between the integer and the double constructor).
  template <std::integral I>
  Rational(I v) {  // NOLINT(google-explicit-constructor)
    if constexpr (std::is_unsigned_v<I>) {  // may exceed long long: two 32-bit halves
      const auto u = static_cast<unsigned long long>(v);
      p_ = (BigInt(static_cast<long long>(u >> 32)) << 32) + BigInt(static_cast<long long>(u & 0xFFFFFFFFu));
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
  friend Rational operator*(const Rational& a, const Rational& b) { return Rational(a.p_ * b.p_, a.q_ * b.q_); }
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
    const std::int64_t exponent = quot.bit_length() - 1 - s;  // value in [2^exponent, 2^(exponent+1))
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
    const double magnitude = std::ldexp(static_cast<double>(mantissa), static_cast<int>(std::clamp<std::int64_t>(lsb, -2000, 2000)));
    return sign() < 0 ? -magnitude : magnitude;
  }

  /// "p/q", or "p" when q = 1.
  [[nodiscard]] std::string str() const { return q_ == BigInt(1) ? p_.str() : p_.str() + "/" + q_.str(); }
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
  friend std::ostream& operator<<(std::ostream& os, const RPoint2& p) { return os << "(" << p.x << ", " << p.y << ")"; }
};
struct RPoint3 {
  Rational x, y, z;
  friend bool operator==(const RPoint3&, const RPoint3&) = default;
  friend RPoint3 operator+(const RPoint3& a, const RPoint3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend RPoint3 operator-(const RPoint3& a, const RPoint3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend RPoint3 operator*(const Rational& s, const RPoint3& a) { return {s * a.x, s * a.y, s * a.z}; }
  friend std::ostream& operator<<(std::ostream& os, const RPoint3& p) {
    return os << "(" << p.x << ", " << p.y << ", " << p.z << ")";
  }
};
inline RPoint2 exact(core::Point2 p) { return {p.x, p.y}; }
inline RPoint3 exact(core::Point3 p) { return {p.x, p.y, p.z}; }
inline core::Point2 to_double(const RPoint2& p) { return {p.x.to_double(), p.y.to_double()}; }
inline core::Point3 to_double(const RPoint3& p) { return {p.x.to_double(), p.y.to_double(), p.z.to_double()}; }

/// The exact control points of a curve.
template <class P>
[[nodiscard]] auto exact_points(const core::BasicCurve<P>& curve) {
  std::vector<decltype(exact(P{}))> pts;
  for (const P& p : curve.points()) pts.push_back(exact(p));
  return pts;
}

inline RPoint2 abs(const RPoint2& p) { return {abs(p.x), abs(p.y)}; }
inline RPoint3 abs(const RPoint3& p) { return {abs(p.x), abs(p.y), abs(p.z)}; }

/// The exact polar: k = us.size() de Casteljau rounds in rationals, round j with u_j,
/// P_i <- (1 - u_j) P_i + u_j P_{i+1}; returns the n + 1 - k points left. With all n
/// arguments equal to t, the single point left is B(t); with n arguments, the blossom.
template <class RP>
[[nodiscard]] std::vector<RP> exact_polar(std::vector<RP> pts, const std::vector<Rational>& us) {
  for (const Rational& u : us) {
    assert(pts.size() >= 2);
    const Rational one_minus_u = Rational(1) - u;
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) pts[i] = one_minus_u * pts[i] + u * pts[i + 1];
    pts.pop_back();
  }
  return pts;
}

/// The condition scale of the same polar: the triangle run on |P_i| with weights |1 - u_j|
/// and |u_j|, i.e. Σ_i |P_i| |coefficient of P_i| per coordinate. Floating-point
/// de Casteljau errors are bounded relative to it (for t in [0,1] and one t it is
/// Σ |P_i| b_i(t) >= |B(t)|).
template <class RP>
[[nodiscard]] std::vector<RP> exact_abs_polar(std::vector<RP> pts, const std::vector<Rational>& us) {
  for (RP& p : pts) p = abs(p);
  for (const Rational& u : us) {
    const Rational a = abs(Rational(1) - u), b = abs(u);
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) pts[i] = a * pts[i] + b * pts[i + 1];
    pts.pop_back();
  }
  return pts;
}

/// B(t) exactly, by de Casteljau in rationals.
template <class RP>
[[nodiscard]] RP exact_evaluate(std::vector<RP> pts, const Rational& t) {
  std::vector<Rational> us(pts.size() - 1, t);
  return exact_polar(std::move(pts), us).front();
}

/// The exact hodograph: n (P_{i+1} - P_i), i = 0..n-1 (a single point gives zero).
template <class RP>
[[nodiscard]] std::vector<RP> exact_hodograph(const std::vector<RP>& pts) {
  if (pts.size() == 1) return {Rational(0) * pts[0]};
  std::vector<RP> h;
  const Rational n(static_cast<long long>(pts.size() - 1));
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) h.push_back(n * (pts[i + 1] - pts[i]));
  return h;
}

/// γ_m = m u / (1 - m u) with u = 2^-53: the bound on m accumulated relative roundings
/// (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed., Lemma 3.1).
[[nodiscard]] inline double rounding_gamma(int m) { return m * 0x1p-53 / (1 - m * 0x1p-53); }

/// The second-order coefficient c of the compensated kernel's bound for degree n (de
/// Casteljau, hodograph or blossom rounds, up to n of each): c = 4 γ_{3n+4}^2. Jiang et al.
/// (2010) prove |CompDeCasteljau - p(t)| <= u |p(t)| + 2 γ_{3n}^2 Σ |b_i| B_i(t); the factor
/// 2 and the +4 cover the error terms that hodograph rounds add (O(k u^2) relative each)
/// and the evaluation of the error row with r = fl(1 - t) in place of 1 - t.
[[nodiscard]] inline double compensated_coefficient(int n) {
  const double g = rounding_gamma(3 * n + 4);
  return 4 * g * g;
}

/// Checks, exactly and per coordinate, |got - exact| <= u |exact| + c scale with u = 2^-53:
/// one rounding of the exact value plus c times a condition scale (the accuracy contract
/// of the compensated kernel, with c = O(n^2 u^2)). Returns "" when it holds, else a
/// description of the worst coordinate for the failure message.
template <class P, class RP>
[[nodiscard]] std::string accuracy_violation(P got, const RP& exact_value, const RP& scale, double c) {
  const RP e = exact_value, err = abs(test::exact(got) - e);
  const RP bound = Rational(0x1p-53) * abs(e) + Rational(c) * scale;
  std::string out;
  const auto check = [&](const Rational& er, const Rational& b, const Rational& ex, const char* name) {
    if (er <= b) return;
    char text[160];
    std::snprintf(text, sizeof text, "%s: error %.3g > bound %.3g (exact %.17g) ", name, er.to_double(),
                  b.to_double(), ex.to_double());
    out += text;
  };
  check(err.x, bound.x, e.x, "x");
  check(err.y, bound.y, e.y, "y");
  if constexpr (requires { e.z; }) check(err.z, bound.z, e.z, "z");
  return out;
}

}  // namespace bezier::test
