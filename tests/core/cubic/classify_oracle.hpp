#pragma once

// An exact, independent oracle for the type of a cubic, for the classification tests:
// the Stone–DeRose canonical point computed in exact rationals (tests/support/exact.hpp)
// and the regions of Pomax's primer read off with exact comparisons (the √ edge squared
// out). It shares no code with core/ (neither the expansion arithmetic nor the
// inflection-form predicates), so agreement with classify() checks both derivations.

#include <array>
#include <span>

#include "core/cubic/cubic_type.hpp"
#include "core/base/point.hpp"
#include "tests/support/exact.hpp"

namespace bezier::test {

inline Rational exact_cross(const RPoint2& a, const RPoint2& b) {
  return a.x * b.y - a.y * b.x;
}

/// The exact canonical point of P0..P3, when P0, P1, P2 are not collinear.
inline std::optional<RPoint2> exact_canonical_point(std::span<const RPoint2, 4> p) {
  const RPoint2 u = p[1] - p[0], v = p[2] - p[0], w = p[3] - p[0];
  const Rational det = exact_cross(u, v);
  if (det.is_zero()) return std::nullopt;
  // Solve w = α u + β v; the image of P3 is (β, α + β).
  const Rational alpha = exact_cross(w, v) / det, beta = exact_cross(u, w) / det;
  return RPoint2{beta, alpha + beta};
}

/// The region of the canonical plane containing (x, y), per the edges:
/// cusp y = (−x² + 2x + 3)/4 (x <= 1); loop at t = 0: y = (−x² + 3x)/3 (x <= 0); loop at
/// t = 1: y = (√(3(4x − x²)) − x)/2 (0 <= x <= 1); y = 1 (inflection at t = 1).
inline core::CubicType exact_region(const Rational& x, const Rational& y) {
  using core::CubicType;
  const Rational one(1), zero(0);
  if (x == Rational(3) && y.is_zero()) return CubicType::quadratic;
  const Rational cusp_y = (-x * x + Rational(2) * x + Rational(3)) / Rational(4);
  if (y == cusp_y && x <= one) return CubicType::cusp;
  if (y > one) return CubicType::single_inflection;
  if (y == one) return x < one ? CubicType::double_inflection : CubicType::single_inflection;
  if (y > cusp_y) return x <= one ? CubicType::double_inflection : CubicType::arch;
  if (y == cusp_y) return CubicType::arch;
  if (x <= zero) {
    const Rational start_y = (-x * x + Rational(3) * x) / Rational(3);
    if (y < start_y) return CubicType::arch;
    return y == start_y ? CubicType::loop_at_start : CubicType::loop;
  }
  if (x <= one) {
    // y >= (s − x)/2 with s = √(12x − 3x²) >= 0  <=>  2y + x >= 0 and (2y + x)² >= s².
    const Rational lhs = Rational(2) * y + x;
    if (lhs < zero) return CubicType::arch;
    const Rational sq = lhs * lhs, s2 = Rational(12) * x - Rational(3) * x * x;
    if (sq < s2) return CubicType::arch;
    return sq == s2 ? CubicType::loop_at_end : CubicType::loop;
  }
  return CubicType::arch;
}

/// The type a cubic reversed (t -> 1 − t) has, given the original's.
inline core::CubicType mirrored(core::CubicType t) {
  if (t == core::CubicType::loop_at_start) return core::CubicType::loop_at_end;
  if (t == core::CubicType::loop_at_end) return core::CubicType::loop_at_start;
  return t;
}

/// The exact type of the cubic p (CubicType's precedence, core/cubic/cubic_type.hpp).
inline core::CubicType exact_type(std::span<const core::Point2, 4> points) {
  using core::CubicType;
  std::array<RPoint2, 4> p;
  for (std::size_t i = 0; i < 4; ++i) p[i] = exact(points[i]);
  if (p[0] == p[1] && p[1] == p[2] && p[2] == p[3]) return CubicType::point;
  const RPoint2 u = p[1] - p[0], v = p[2] - p[0], w = p[3] - p[0];
  if (exact_cross(u, v).is_zero() && exact_cross(u, w).is_zero() && exact_cross(v, w).is_zero()) {
    return CubicType::line;
  }
  const RPoint2 c = (p[3] - p[0]) + Rational(3) * (p[1] - p[2]);
  if (c.x.is_zero() && c.y.is_zero()) return CubicType::quadratic;
  if (p[0] == p[3]) return CubicType::loop_at_start;  // closed: t1 = 0 and t2 = 1
  if (const auto q = exact_canonical_point(p)) return exact_region(q->x, q->y);
  const std::array<RPoint2, 4> r{p[3], p[2], p[1], p[0]};
  if (const auto q = exact_canonical_point(r)) return mirrored(exact_region(q->x, q->y));
  // P0, P1, P2 and P1, P2, P3 both collinear but not all four: P1 = P2. Then B'' is
  // parallel to B' at both ends (B''(0) = 6 (P0 − P1), B''(1) = 6 (P3 − P2)), B' never
  // vanishes (it is (1−t)² (P1 − P0) + t² (P3 − P1), two independent vectors), and
  // B' × B'' = 18 d t (1 − t) with d = (P1 − P0) × (P3 − P1) != 0: two inflections, at the
  // ends.
  return CubicType::double_inflection;
}

}  // namespace bezier::test
