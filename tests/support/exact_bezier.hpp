#pragma once

// Exact Bézier arithmetic for tests of the kernel: de Casteljau, polars and hodographs in
// rationals (tests/support/exact.hpp) on a curve's double control points, the condition
// scales that floating-point errors are measured against, the accuracy contract of the
// compensated kernel (core/curve/evaluate.hpp, CasteljauRow), and seeded random test curves.

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/base/curve.hpp"
#include "core/base/point.hpp"
#include "core/bernstein/bernstein1d.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::test {

/// The exact control points of a curve.
template <class P>
[[nodiscard]] auto exact_points(const core::BasicCurve<P>& curve) {
  std::vector<decltype(exact(P{}))> pts;
  for (const P& p : curve.points()) pts.push_back(exact(p));
  return pts;
}

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
[[nodiscard]] std::vector<RP> exact_abs_polar(std::vector<RP> pts,
                                              const std::vector<Rational>& us) {
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

/// C(n, k) as an exact integer (small n: every intermediate c (n - j) fits in 64 bits).
[[nodiscard]] inline long long binom(int n, int k) {
  long long c = 1;
  for (int j = 0; j < k; ++j) c = c * (n - j) / (j + 1);
  return c;
}

/// A scalar polynomial by its Bernstein coefficients on [0, 1]: b_i of B_i^m, m = size - 1.
using BernsteinPoly = std::vector<Rational>;

/// p(t) exactly, for p given by its double Bernstein coefficients c on [0, 1].
[[nodiscard]] inline Rational exact_bernstein_value(const std::vector<double>& c, const Rational& t) {
  return exact_evaluate(BernsteinPoly(c.begin(), c.end()), t);
}

/// Whether lo <= p(t) <= hi exactly, for p given by its double Bernstein coefficients c on
/// [0, 1]. p(t) in doubles (de Casteljau: n rounds of convex combinations) is within
/// 3.02 n u max|c_i| of the exact value, far below the margin 2^-40 max(1, |c_i|, |lo|, |hi|)
/// for any degree used here (the margin also covers rounding lo and hi to doubles): a value
/// farther than that from both edges decides, and only one within it takes the exact value
/// in rationals.
[[nodiscard]] inline bool exactly_in_band(const std::vector<double>& c, double t, const Rational& lo,
                                          const Rational& hi) {
  const double lo_d = lo.to_double(), hi_d = hi.to_double();
  double scale = std::max({1.0, std::fabs(lo_d), std::fabs(hi_d)});
  for (const double v : c) scale = std::max(scale, std::fabs(v));
  const double margin = 0x1p-40 * scale;
  const double near = core::bernstein::evaluate(std::span<const double>(c), t);
  if (near < lo_d - margin || near > hi_d + margin) return false;
  if (near > lo_d + margin && near < hi_d - margin) return true;
  const Rational v = exact_bernstein_value(c, Rational(t));
  return lo <= v && v <= hi;
}

/// The product of two polynomials in Bernstein form, exactly: degree m + n, coefficients
/// (A B)_i = Σ_j C(m,j) C(n,i-j) / C(m+n,i) A_j B_(i-j) (Farouki & Rajan, "Algorithms for
/// polynomials in Bernstein form", CAGD 5, 1988).
[[nodiscard]] inline BernsteinPoly exact_bernstein_product(const BernsteinPoly& a,
                                                           const BernsteinPoly& b) {
  const int m = static_cast<int>(a.size()) - 1, n = static_cast<int>(b.size()) - 1;
  BernsteinPoly out;
  for (int i = 0; i <= m + n; ++i) {
    Rational sum(0);
    for (int j = std::max(0, i - n); j <= std::min(m, i); ++j) {
      sum += Rational(binom(m, j) * binom(n, i - j)) * a[static_cast<std::size_t>(j)] *
             b[static_cast<std::size_t>(i - j)];
    }
    out.push_back(sum / Rational(binom(m + n, i)));
  }
  return out;
}

/// H(q(s)) exactly, for H with control points h (degree n) and q in Bernstein form
/// (degree m): the control points of degree n m, by de Casteljau's algorithm with
/// polynomial entries, H_i <- (1 - q) H_i + q H_(i+1) (the polar with every argument q).
/// Any q: the composition traces H's points at another speed where q runs within [0, 1]
/// and leaves them elsewhere.
[[nodiscard]] inline std::vector<RPoint2> exact_compose(const std::vector<RPoint2>& h,
                                                        const BernsteinPoly& q) {
  assert(!h.empty() && !q.empty());
  BernsteinPoly one_minus_q;
  for (const Rational& c : q) one_minus_q.push_back(Rational(1) - c);
  std::vector<BernsteinPoly> x, y;
  for (const RPoint2& p : h) {
    x.push_back({p.x});
    y.push_back({p.y});
  }
  const auto step = [&](const BernsteinPoly& lo, const BernsteinPoly& hi) {
    BernsteinPoly sum = exact_bernstein_product(one_minus_q, lo);
    const BernsteinPoly right = exact_bernstein_product(q, hi);
    for (std::size_t k = 0; k < sum.size(); ++k) sum[k] += right[k];
    return sum;
  };
  for (std::size_t level = h.size() - 1; level > 0; --level) {
    for (std::size_t i = 0; i < level; ++i) {
      x[i] = step(x[i], x[i + 1]);
      y[i] = step(y[i], y[i + 1]);
    }
  }
  std::vector<RPoint2> out;
  for (std::size_t k = 0; k < x[0].size(); ++k) out.push_back({x[0][k], y[0][k]});
  return out;
}

/// γ_m = m u / (1 - m u) with u = 2^-53: the bound on m accumulated relative roundings
/// (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed., Lemma 3.1).
[[nodiscard]] inline double rounding_gamma(int m) {
  return m * 0x1p-53 / (1 - m * 0x1p-53);
}

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
[[nodiscard]] std::string accuracy_violation(P got, const RP& exact_value, const RP& scale,
                                             double c) {
  const RP e = exact_value, err = abs(test::exact(got) - e);
  const RP bound = Rational(0x1p-53) * abs(e) + Rational(c) * scale;
  std::string out;
  const auto check = [&](const Rational& er, const Rational& b, const Rational& ex,
                         const char* name) {
    if (er <= b) return;
    char text[160];
    std::snprintf(text, sizeof text, "%s: error %.3g > bound %.3g (exact %.17g) ", name,
                  er.to_double(), b.to_double(), ex.to_double());
    out += text;
  };
  check(err.x, bound.x, e.x, "x");
  check(err.y, bound.y, e.y, "y");
  if constexpr (requires { e.z; }) check(err.z, bound.z, e.z, "z");
  return out;
}

/// A point with every coordinate drawn uniformly from [lo, hi).
template <class P>
[[nodiscard]] P random_point(Mulberry32& rng, double lo, double hi) {
  if constexpr (std::is_same_v<P, core::Point2>) {
    return {rng.uniform(lo, hi), rng.uniform(lo, hi)};
  } else {
    return {rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi)};
  }
}

/// A curve of the given degree with random_point control points.
template <class P>
[[nodiscard]] core::BasicCurve<P> random_curve(Mulberry32& rng, int degree, double lo, double hi) {
  std::vector<P> pts;
  for (int i = 0; i <= degree; ++i) pts.push_back(random_point<P>(rng, lo, hi));
  return core::BasicCurve<P>(std::move(pts));
}

/// "seed S, degree n, t = ..." for failure messages, so a failing draw can be replayed.
[[nodiscard]] inline std::string case_name(std::uint32_t seed, int degree, double t) {
  char text[120];
  std::snprintf(text, sizeof text, "seed %u, degree %d, t = %.17g", seed, degree, t);
  return text;
}

}  // namespace bezier::test
