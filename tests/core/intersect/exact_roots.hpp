#pragma once

// Exact checks for intersection results, in rational arithmetic (tests/support/exact.hpp):
// the true root near an estimate by Newton's method in rationals (each step doubles the
// correct digits: two steps from a double-precision estimate give ~1e-60), and the exact
// residual |f(t) - g(s)| of an estimate.

#include <optional>
#include <vector>

#include "core/base/curve.hpp"
#include "core/intersect/result.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"

namespace bezier::test {

/// B(t) and B'(t) exactly.
struct ExactPointAndTangent {
  RPoint2 point;
  RPoint2 tangent;
};

inline ExactPointAndTangent exact_point_and_tangent(const core::Curve& c, const Rational& t) {
  std::vector<RPoint2> pts = exact_points(c);
  const std::size_t n = pts.size() - 1;
  if (n == 0) return {pts[0], {Rational(0), Rational(0)}};
  const Rational one_minus = Rational(1) - t;
  for (std::size_t level = n; level > 1; --level) {
    for (std::size_t i = 0; i < level; ++i) pts[i] = one_minus * pts[i] + t * pts[i + 1];
  }
  const Rational dn(static_cast<long long>(n));
  return {one_minus * pts[0] + t * pts[1], dn * (pts[1] - pts[0])};
}

/// Keeps a rational's size bounded: rounds it to a multiple of 2^-precision_bits (an error
/// far below anything compared here, and Newton's method corrects it at the next step).
inline Rational truncate(const Rational& x, int precision_bits = 220) {
  const Rational scale(BigInt(1) << precision_bits, BigInt(1));
  const Rational scaled = x * scale;
  const BigInt q = scaled.num() / scaled.den();
  return Rational(q, BigInt(1) << precision_bits);
}

/// The root of f(t) = g(s) near (t0, s0), by Newton's method in rationals (truncated to
/// 220 bits each step). nullopt when the Jacobian is singular.
struct ExactRoot {
  Rational t;
  Rational s;
};

inline std::optional<ExactRoot> exact_newton(const core::Curve& f, const core::Curve& g, double t0,
                                             double s0, int steps = 3) {
  Rational t(t0), s(s0);
  for (int i = 0; i < steps; ++i) {
    const ExactPointAndTangent a = exact_point_and_tangent(f, t), b = exact_point_and_tangent(g, s);
    const RPoint2 r = a.point - b.point;
    // f' dt - g' ds = -r
    const Rational det = a.tangent.y * b.tangent.x - a.tangent.x * b.tangent.y;  // det [f', -g']
    if (det == Rational(0)) return std::nullopt;
    // Cramer's rule: dt = det [-r, -g'] / det, ds = det [f', -r] / det.
    const Rational dt = (r.x * b.tangent.y - b.tangent.x * r.y) / det;
    const Rational ds = (r.x * a.tangent.y - a.tangent.x * r.y) / det;
    t = truncate(t + dt);
    s = truncate(s + ds);
  }
  return ExactRoot{t, s};
}

/// lo <= x <= hi exactly.
inline bool contains(core::ParamInterval iv, const Rational& x) {
  return Rational(iv.lo) <= x && x <= Rational(iv.hi);
}

/// max(|f(t) - g(s)|) over the coordinates, exactly, as a double (rounded).
inline double exact_gap(const core::Curve& f, const core::Curve& g, double t, double s) {
  const RPoint2 a = exact_evaluate(exact_points(f), Rational(t));
  const RPoint2 b = exact_evaluate(exact_points(g), Rational(s));
  const Rational dx = abs(a.x - b.x), dy = abs(a.y - b.y);
  return (dx < dy ? dy : dx).to_double();
}

}  // namespace bezier::test
