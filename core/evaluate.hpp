#pragma once

#include <cassert>
#include <cmath>
#include <span>
#include <vector>

#include "core/curve.hpp"

namespace bezier::core {

/// An unevaluated sum hi + lo: the result of an error-free transformation.
template <class T>
struct TwoTerm {
  T hi;
  T lo;
};

/// a + b = hi + lo exactly, with hi = fl(a + b) (Knuth's TwoSum, TAOCP vol. 2, §4.2.2;
/// branch-free, any order of magnitudes). Exact unless a + b overflows. Relies on strict
/// IEEE evaluation: no -ffast-math, no contraction of a - b into a fused operation.
[[nodiscard]] constexpr TwoTerm<double> two_sum(double a, double b) noexcept {
  const double s = a + b;
  const double b_virtual = s - a;
  return {s, (a - (s - b_virtual)) + (b - b_virtual)};
}

/// a b = hi + lo exactly, with hi = fl(a b): the fused multiply-add gives the rounding
/// error of the product in one rounding (exact unless the product over- or underflows).
/// (Dekker's split-based TwoProduct avoids the libm call on x86-64 builds without -mfma,
/// but measured no faster here: glibc dispatches fma to the hardware instruction.)
[[nodiscard]] inline TwoTerm<double> two_product(double a, double b) noexcept {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

/// The same transformations coordinate by coordinate.
[[nodiscard]] inline TwoTerm<Point2> two_sum(Point2 a, Point2 b) noexcept {
  const auto x = two_sum(a.x, b.x), y = two_sum(a.y, b.y);
  return {{x.hi, y.hi}, {x.lo, y.lo}};
}
[[nodiscard]] inline TwoTerm<Point3> two_sum(Point3 a, Point3 b) noexcept {
  const auto x = two_sum(a.x, b.x), y = two_sum(a.y, b.y), z = two_sum(a.z, b.z);
  return {{x.hi, y.hi, z.hi}, {x.lo, y.lo, z.lo}};
}
[[nodiscard]] inline TwoTerm<Point2> two_product(double s, Point2 a) noexcept {
  const auto x = two_product(s, a.x), y = two_product(s, a.y);
  return {{x.hi, y.hi}, {x.lo, y.lo}};
}
[[nodiscard]] inline TwoTerm<Point3> two_product(double s, Point3 a) noexcept {
  const auto x = two_product(s, a.x), y = two_product(s, a.y), z = two_product(s, a.z);
  return {{x.hi, y.hi, z.hi}, {x.lo, y.lo, z.lo}};
}

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
  explicit CasteljauRow(std::span<const P> points) {
    assert(!points.empty());
    entries_.reserve(points.size());
    for (const P& p : points) entries_.push_back({p, P{}});
  }

  /// Number of entries: n + 1 for a degree-n curve, one fewer after each step.
  [[nodiscard]] std::size_t size() const noexcept { return entries_.size(); }

  /// Entry i as one double point: value + error, rounded once. When the error terms are
  /// not finite (a product overflowed while the value did not), the plain value is returned.
  [[nodiscard]] P point(std::size_t i) const noexcept {
    const auto& [value, error] = entries_[i];
    return is_finite(error) ? value + error : value;
  }

  /// One de Casteljau round with parameter t: entry i <- (1 - t) entry i + t entry i+1.
  /// The local error of each new entry is exact before it is rounded into the error row:
  /// (1 - t) a + t b = fl(r a + t b) + [π_ra + π_tb + σ + ρ a], where 1 - t = r + ρ,
  /// r a = s + π_ra, t b = v + π_tb and s + v = fl(s + v) + σ.
  void casteljau_step(double t) {
    assert(size() >= 2);
    const TwoTerm<double> one_minus_t = two_sum(1.0, -t);
    const double r = one_minus_t.hi, rho = one_minus_t.lo;
    for (std::size_t i = 0; i + 1 < size(); ++i) {
      TwoTerm<P>& a = entries_[i];
      const TwoTerm<P>& b = entries_[i + 1];
      const TwoTerm<P> left = two_product(r, a.hi);
      const TwoTerm<P> right = two_product(t, b.hi);
      const TwoTerm<P> sum = two_sum(left.hi, right.hi);
      const P local = (left.lo + right.lo) + (sum.lo + rho * a.hi);
      a.lo = (r * a.lo + t * b.lo) + local;
      a.hi = sum.hi;
    }
    entries_.pop_back();
  }

  /// One hodograph round: entry i <- m (entry i+1 - entry i), m = size() - 1 (the degree),
  /// for i = 0..m-1 (Farin, "Curves and Surfaces for CAGD", 5th ed., §5.3). The difference
  /// and the product are split exactly, so close control points lose nothing to
  /// cancellation. A single entry (degree 0) becomes the zero point.
  void hodograph_step() {
    if (size() == 1) {
      entries_[0] = {P{}, P{}};
      return;
    }
    const double m = static_cast<double>(size() - 1);
    for (std::size_t i = 0; i + 1 < size(); ++i) {
      TwoTerm<P>& a = entries_[i];
      const TwoTerm<P>& b = entries_[i + 1];
      const TwoTerm<P> diff = two_sum(b.hi, -a.hi);
      const TwoTerm<P> scaled = two_product(m, diff.hi);
      a.lo = scaled.lo + m * (diff.lo + (b.lo - a.lo));
      a.hi = scaled.hi;
    }
    entries_.pop_back();
  }

 private:
  std::vector<TwoTerm<P>> entries_;  ///< hi: the rounded value, lo: its rounding error
};

/// B(t) = Σ C(n,i) (1-t)^(n-i) t^i P_i by de Casteljau's algorithm, n rounds of
/// P_i <- (1-t) P_i + t P_{i+1} (Farin, §4.1), compensated (see CasteljauRow): within one
/// rounding of the exact value plus O(n^2 u^2) Σ |P_i| |b_i(t)|, for any degree.
/// Any finite t is allowed; outside [0,1] the polynomial is extrapolated (the bound holds
/// with the same formula, which grows like |2t - 1|^n). Returns P_0 exactly at t = 0 and
/// P_n exactly at t = 1 (every error term is zero there).
template <class P>
[[nodiscard]] P evaluate(const BasicCurve<P>& curve, double t) {
  CasteljauRow<P> row(curve.points());
  while (row.size() > 1) row.casteljau_step(t);
  return row.point(0);
}

/// The parameters of `count` uniform samples: t_i = i / (count - 1), so 0 and 1 are
/// included exactly. count = 1 gives {0}. Precondition: count >= 1.
[[nodiscard]] std::vector<double> uniform_parameters(int count);

/// B(t_i) at each parameter of uniform_parameters(count).
template <class P>
[[nodiscard]] std::vector<P> sample(const BasicCurve<P>& curve, int count) {
  std::vector<P> samples;
  for (const double t : uniform_parameters(count)) samples.push_back(evaluate(curve, t));
  return samples;
}

}  // namespace bezier::core
