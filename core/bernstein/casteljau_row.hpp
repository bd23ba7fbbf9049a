#pragma once

#include <cassert>
#include <span>

#include "core/numeric/error_free.hpp"
#include "core/numeric/small_array.hpp"
#include "core/base/point.hpp"

namespace bezier::core {

/// One row of de Casteljau's triangle, each entry carried as a rounded value plus an
/// approximation of its rounding error (value + error ~ the exact entry). This is the
/// compensated de Casteljau algorithm (H. Jiang, S. Li, L. Cheng, F. Su, "Accurate
/// evaluation of a polynomial and its derivative in Bernstein form", Computers & Mathematics
/// with Applications 60(3), 2010, 744-755): every de Casteljau step splits its rounding
/// errors off exactly (TwoSum / TwoProduct) and propagates them through the same recurrence
/// in a second triangle. The result, value + error rounded once, is as accurate as plain
/// de Casteljau in twice the working precision: |error| <= u |B(t)| + O(n^2 u^2) S(t) with
/// u = 2^-53 and S(t) = Σ |P_i| |C(n,i) (1-t)^(n-i) t^i|, i.e. within one rounding of the
/// exact value unless B(t) cancels to below about n^2 u S(t). Plain de Casteljau only
/// guarantees O(n u) S(t) (about 10 ulps of S at degree 20 in practice, and far more than
/// that relative to |B(t)| when B(t) cancels).
///
/// The row of values alone is exactly the plain algorithm, (1 - t) P_i + t P_{i+1} rounded
/// as lerp() rounds it, so evaluate, subdivide and polar share every bit of it. Every
/// routine that needs a de Casteljau step uses this class, so that quantities that must
/// agree (a split point and B(t); blossom(t, ..., t) and B(t)) come out bit for bit equal.
template <class P>
class CasteljauRow {
 public:
  /// The control points, taken as exact (zero error).
  explicit CasteljauRow(std::span<const P> points)
      : entries_(points.size(), typename SmallArray<Entry>::Uninitialized{}), size_(points.size()) {
    assert(!points.empty());
    Entry* e = entries();
    for (std::size_t i = 0; i < size_; ++i) e[i] = {points[i], P{}};
  }

  /// Number of entries: n + 1 for a degree-n curve, one fewer after each step.
  [[nodiscard]] std::size_t size() const noexcept { return size_; }

  /// Entry i as one double point: value + error, rounded once. When the error terms are
  /// not finite (a product overflowed while the value did not), the plain value is returned.
  [[nodiscard]] P point(std::size_t i) const noexcept {
    const auto& [value, error] = entries()[i];
    return is_finite(error) ? value + error : value;
  }

  /// Entry i as its two parts, unrounded: the difference of two nearly equal evaluations
  /// keeps the error parts that point(i) would round away.
  [[nodiscard]] const TwoTerm<P>& entry(std::size_t i) const noexcept { return entries()[i]; }

  /// One de Casteljau round with parameter t: entry i <- (1 - t) entry i + t entry i+1.
  /// The local error of each new entry is exact before it is rounded into the error row:
  /// (1 - t) a + t b = fl(r a + t b) + [π_ra + π_tb + σ + ρ a], where 1 - t = r + ρ,
  /// r a = s + π_ra, t b = v + π_tb and s + v = fl(s + v) + σ.
  void casteljau_step(double t) {
    assert(size() >= 2);
    const TwoTerm<double> one_minus_t = two_sum(1.0, -t);
    const double r = one_minus_t.hi, rho = one_minus_t.lo;
    Entry* e = entries();
    for (std::size_t i = 0; i + 1 < size_; ++i) {
      Entry& a = e[i];
      const Entry& b = e[i + 1];
      const TwoTerm<P> left = two_product(r, a.hi);
      const TwoTerm<P> right = two_product(t, b.hi);
      const TwoTerm<P> sum = two_sum(left.hi, right.hi);
      const P local = (left.lo + right.lo) + (sum.lo + rho * a.hi);
      a.lo = (r * a.lo + t * b.lo) + local;
      a.hi = sum.hi;
    }
    --size_;
  }

  /// One hodograph round: entry i <- m (entry i+1 - entry i), m = size() - 1 (the degree),
  /// for i = 0..m-1 (Farin, "Curves and Surfaces for CAGD", 5th ed., §5.3). The difference
  /// and the product are split exactly, so close control points lose nothing to
  /// cancellation. A single entry (degree 0) becomes the zero point.
  void hodograph_step() {
    Entry* e = entries();
    if (size_ == 1) {
      e[0] = {P{}, P{}};
      return;
    }
    const double m = static_cast<double>(size_ - 1);
    for (std::size_t i = 0; i + 1 < size_; ++i) {
      Entry& a = e[i];
      const Entry& b = e[i + 1];
      const TwoTerm<P> diff = two_sum(b.hi, -a.hi);
      const TwoTerm<P> scaled = two_product(m, diff.hi);
      a.lo = scaled.lo + m * (diff.lo + (b.lo - a.lo));
      a.hi = scaled.hi;
    }
    --size_;
  }

 private:
  using Entry = TwoTerm<P>;  ///< hi: the rounded value, lo: its rounding error

  [[nodiscard]] Entry* entries() noexcept { return entries_.data(); }
  [[nodiscard]] const Entry* entries() const noexcept { return entries_.data(); }

  /// The row's first n + 1 entries (inline for short rows, unset until the constructor
  /// writes them); each step uses one fewer of them.
  SmallArray<Entry> entries_;
  std::size_t size_;
};

}  // namespace bezier::core
