#pragma once

// Exact polynomial helpers for the area and self-intersection tests: a planar Bézier curve
// converted to the power basis in rationals, so that expected values come from a method
// independent of the kernel's (power basis and antiderivatives instead of Bernstein-form
// double sums and subdivision).

#include <cassert>
#include <cstddef>
#include <optional>
#include <vector>

#include "core/base/curve.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"

namespace bezier::test {

/// A scalar polynomial, coefficient k of t^k.
using Poly = std::vector<Rational>;

inline Poly poly_mul(const Poly& a, const Poly& b) {
  Poly r(a.size() + b.size() - 1, Rational(0));
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  }
  return r;
}

inline Poly poly_sub(Poly a, const Poly& b) {
  if (a.size() < b.size()) a.resize(b.size(), Rational(0));
  for (std::size_t i = 0; i < b.size(); ++i) a[i] -= b[i];
  return a;
}

inline Poly poly_derivative(const Poly& a) {
  Poly r;
  for (std::size_t k = 1; k < a.size(); ++k)
    r.push_back(Rational(static_cast<long long>(k)) * a[k]);
  if (r.empty()) r.push_back(Rational(0));
  return r;
}

/// ∫ a: coefficient k + 1 is a_k / (k + 1), constant term 0.
inline Poly poly_antiderivative(const Poly& a) {
  Poly r{Rational(0)};
  for (std::size_t k = 0; k < a.size(); ++k)
    r.push_back(a[k] / Rational(static_cast<long long>(k + 1)));
  return r;
}

/// Horner.
inline Rational poly_value(const Poly& a, const Rational& t) {
  Rational v(0);
  for (std::size_t k = a.size(); k-- > 0;) v = v * t + a[k];
  return v;
}

/// x(t), y(t) of a Bézier curve in the power basis: Σ_i C(n,i) t^i (1-t)^(n-i) P_i expanded
/// with the binomial theorem, exactly.
struct PowerCurve {
  Poly x;
  Poly y;
};

inline PowerCurve power_form(const std::vector<RPoint2>& pts) {
  const int n = static_cast<int>(pts.size()) - 1;
  PowerCurve pc{Poly(static_cast<std::size_t>(n) + 1, Rational(0)),
                Poly(static_cast<std::size_t>(n) + 1, Rational(0))};
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n - i; ++j) {
      // C(n,i) t^i C(n-i,j) (-t)^j
      const Rational c(binom(n, i) * binom(n - i, j) * (j % 2 == 0 ? 1 : -1));
      pc.x[static_cast<std::size_t>(i + j)] += c * pts[static_cast<std::size_t>(i)].x;
      pc.y[static_cast<std::size_t>(i + j)] += c * pts[static_cast<std::size_t>(i)].y;
    }
  }
  return pc;
}

inline PowerCurve power_form(const core::Curve& curve) {
  return power_form(exact_points(curve));
}

inline RPoint2 power_value(const PowerCurve& pc, const Rational& t) {
  return {poly_value(pc.x, t), poly_value(pc.y, t)};
}

inline Rational rcross(const RPoint2& a, const RPoint2& b) {
  return a.x * b.y - a.y * b.x;
}

/// 1/2 ∫_a^b (x y' - x' y) dt exactly, through the antiderivative of the power form.
inline Rational exact_green_integral(const PowerCurve& pc, const Rational& a, const Rational& b) {
  const Poly integrand =
      poly_sub(poly_mul(pc.x, poly_derivative(pc.y)), poly_mul(poly_derivative(pc.x), pc.y));
  const Poly anti = poly_antiderivative(integrand);
  return (poly_value(anti, b) - poly_value(anti, a)) / Rational(2);
}

/// The area enclosed by B on [a, b] and the chord from B(b) back to B(a), exactly.
inline Rational exact_enclosed_area(const PowerCurve& pc, const Rational& a, const Rational& b) {
  return exact_green_integral(pc, a, b) +
         rcross(power_value(pc, b), power_value(pc, a)) / Rational(2);
}

/// Bernstein coefficients from power coefficients (a_k of t^k, degree n = size - 1):
/// b_i = Σ_{k <= i} C(i,k) / C(n,k) a_k, from t^k = Σ_{i >= k} C(i,k) / C(n,k) B_i^n(t)
/// (the inverse of power_form).
inline BernsteinPoly bernstein_from_power(const Poly& a) {
  const int n = static_cast<int>(a.size()) - 1;
  BernsteinPoly b;
  for (int i = 0; i <= n; ++i) {
    Rational sum(0);
    for (int k = 0; k <= i; ++k)
      sum += Rational(binom(i, k)) / Rational(binom(n, k)) * a[static_cast<std::size_t>(k)];
    b.push_back(sum);
  }
  return b;
}

/// Control points from the power coefficients of both coordinates (same degree).
inline std::vector<RPoint2> bernstein_from_power(const Poly& x, const Poly& y) {
  assert(x.size() == y.size());
  const BernsteinPoly bx = bernstein_from_power(x), by = bernstein_from_power(y);
  std::vector<RPoint2> pts;
  for (std::size_t i = 0; i < bx.size(); ++i) pts.push_back({bx[i], by[i]});
  return pts;
}

/// The polynomial p(s) rewritten in t = s + shift: p(t - shift).
inline Poly poly_shift(const Poly& p, const Rational& shift) {
  Poly r{Rational(0)};
  Poly base{Rational(1)};
  const Poly step{-shift, Rational(1)};  // t - shift
  for (const Rational& c : p) {
    Poly term = base;
    for (Rational& v : term) v *= c;
    if (r.size() < term.size()) r.resize(term.size(), Rational(0));
    for (std::size_t k = 0; k < term.size(); ++k) r[k] += term[k];
    base = poly_mul(base, step);
  }
  return r;
}

/// The curve with exactly these control points when every coordinate is a double, else
/// nullopt (constructions in the tests are chosen to be dyadic).
inline std::optional<core::Curve> exact_curve(const std::vector<RPoint2>& pts) {
  std::vector<core::Point2> out;
  for (const RPoint2& p : pts) {
    const core::Point2 q = to_double(p);
    if (Rational(q.x) != p.x || Rational(q.y) != p.y) return std::nullopt;
    out.push_back(q);
  }
  return core::Curve(std::move(out));
}

/// Degree elevation, exactly: Q_i = i/(n+1) P_{i-1} + (1 - i/(n+1)) P_i (Farin, §5.1).
inline std::vector<RPoint2> elevate(const std::vector<RPoint2>& pts) {
  const long long n = static_cast<long long>(pts.size()) - 1;
  std::vector<RPoint2> q;
  q.push_back(pts.front());
  for (long long i = 1; i <= n; ++i) {
    const Rational a(Rational(i) / Rational(n + 1));
    q.push_back(a * pts[static_cast<std::size_t>(i - 1)] +
                (Rational(1) - a) * pts[static_cast<std::size_t>(i)]);
  }
  q.push_back(pts.back());
  return q;
}

/// A root of p in [lo, hi] where p(lo) and p(hi) have opposite signs, by bisection in
/// rationals with dyadic midpoints, to a bracket narrower than 2^-bits.
inline Rational bisect_root(const Poly& p, Rational lo, Rational hi, int bits) {
  const int s_lo = poly_value(p, lo).sign();
  assert(s_lo != 0 && poly_value(p, hi).sign() == -s_lo);
  for (int i = 0; i < bits; ++i) {
    const Rational mid = (lo + hi) / Rational(2);
    const int s = poly_value(p, mid).sign();
    if (s == 0) return mid;
    (s == s_lo ? lo : hi) = mid;
  }
  return (lo + hi) / Rational(2);
}

/// The square root of r >= 0 to within 2^-bits (relative to max(1, r)), by bisection.
inline Rational sqrt_approx(const Rational& r, int bits) {
  Rational lo(0), hi = r > Rational(1) ? r : Rational(1);
  for (int i = 0; i < bits; ++i) {
    const Rational mid = (lo + hi) / Rational(2);
    (mid * mid <= r ? lo : hi) = mid;
  }
  return (lo + hi) / Rational(2);
}

}  // namespace bezier::test
