#pragma once

// An arbitrary-precision signed integer for exact test expectations (tests/support/exact.hpp
// builds its Rational on it). Clarity over speed, with one exception that matters for
// Bézier tests: the denominators of dyadic rationals are powers of two, so gcd and division
// have fast paths for powers of two.

#include <algorithm>
#include <bit>
#include <cassert>
#include <compare>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

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
    return mag_.empty()
               ? 0
               : 32 * static_cast<std::int64_t>(mag_.size() - 1) + std::bit_width(mag_.back());
  }
  /// Number of trailing zero bits of |x|; 0 for zero.
  [[nodiscard]] std::int64_t trailing_zeros() const noexcept {
    for (std::size_t i = 0; i < mag_.size(); ++i)
      if (mag_[i] != 0) return 32 * static_cast<std::int64_t>(i) + std::countr_zero(mag_[i]);
    return 0;
  }
  /// |x| is a power of two.
  [[nodiscard]] bool is_power_of_two() const noexcept {
    return !is_zero() && bit_length() == trailing_zeros() + 1;
  }
  /// The low 64 bits of |x|.
  [[nodiscard]] std::uint64_t low_u64() const noexcept {
    std::uint64_t r = mag_.empty() ? 0 : mag_[0];
    if (mag_.size() > 1) r |= static_cast<std::uint64_t>(mag_[1]) << 32;
    return r;
  }
  [[nodiscard]] BigInt abs() const {
    BigInt r = *this;
    r.neg_ = false;
    return r;
  }

  friend BigInt operator-(BigInt a) {
    a.neg_ = !a.neg_ && !a.is_zero();
    return a;
  }
  friend BigInt operator+(const BigInt& a, const BigInt& b) {
    if (a.neg_ == b.neg_) return make(add_mag(a.mag_, b.mag_), a.neg_);
    // Opposite signs: subtract the smaller magnitude from the larger.
    if (cmp_mag(a.mag_, b.mag_) >= 0) return make(sub_mag(a.mag_, b.mag_), a.neg_);
    return make(sub_mag(b.mag_, a.mag_), b.neg_);
  }
  friend BigInt operator-(const BigInt& a, const BigInt& b) { return a + (-b); }
  friend BigInt operator*(const BigInt& a, const BigInt& b) {
    return make(mul_mag(a.mag_, b.mag_), a.neg_ != b.neg_);
  }
  /// Truncating division (rounds toward zero, like built-in integers). Precondition: b != 0.
  friend BigInt operator/(const BigInt& a, const BigInt& b) { return divmod(a, b).first; }
  /// Remainder with the sign of a (a == (a / b) * b + a % b). Precondition: b != 0.
  friend BigInt operator%(const BigInt& a, const BigInt& b) { return divmod(a, b).second; }
  /// |x| 2^k with the sign of x.
  friend BigInt operator<<(const BigInt& a, std::int64_t k) {
    assert(k >= 0);
    return make(shl_mag(a.mag_, k), a.neg_);
  }
  /// |x| / 2^k truncated, with the sign of x (so it rounds toward zero).
  friend BigInt operator>>(const BigInt& a, std::int64_t k) {
    assert(k >= 0);
    return make(shr_mag(a.mag_, k), a.neg_);
  }

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
      for (int k = 0; k < 9 && (rem != 0 || !m.empty()); ++k, rem /= 10)
        digits.push_back(static_cast<char>('0' + rem % 10));
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
        t = static_cast<std::int64_t>(un[i + j]) - borrow -
            static_cast<std::int64_t>(p & 0xFFFFFFFFu);
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

}  // namespace bezier::test
