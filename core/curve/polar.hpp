#pragma once

#include <cassert>
#include <span>
#include <vector>

#include "core/base/curve.hpp"

namespace bezier::core {

/// The polar of B with respect to the parameters u_1..u_k (k <= n): the curve of degree
/// n - k whose control points are the blossom values b(u_1, ..., u_k, t^(n-k)) at the
/// Bézier points of the remaining arguments. Computed as k de Casteljau rounds, round j
/// with parameter u_j: P_i <- (1 - u_j) P_i + u_j P_{i+1} (Ramshaw, "Blossoming: a
/// connect-the-dots approach to splines", 1987; Farin, §4.4). The blossom is symmetric
/// and multi-affine, so the order of the u_j changes nothing but rounding.
/// Any finite u_j is allowed: a blossom is defined everywhere.
/// The rounds are the compensated ones of evaluate() (CasteljauRow): each control point is
/// within about one rounding of its exact value, and with all u_j = t the result is
/// bit for bit what evaluate(curve, t) and subdivide(curve, t) compute.
[[nodiscard]] Curve polar(const Curve& curve, std::span<const double> us);
[[nodiscard]] Curve3 polar(const Curve3& curve, std::span<const double> us);

/// The first polar at t0: control points b_i^1(t0) = (1 - t0) P_i + t0 P_{i+1},
/// i = 0..n-1, a curve of degree n - 1. Its point at t0 is B(t0), and there it is
/// tangent to B: d/dt b(t0, t^(n-1)) at t = t0 is (n-1)/n B'(t0). Precondition: n >= 1.
template <class P>
[[nodiscard]] BasicCurve<P> first_polar(const BasicCurve<P>& curve, double t0) {
  assert(curve.degree() >= 1);
  const double us[] = {t0};
  return polar(curve, us);
}

/// The blossom b(u_1, ..., u_n) of a degree-n curve: the polar with respect to all n
/// arguments, a single point. b(t, ..., t) = B(t). Precondition: us.size() == n.
template <class P>
[[nodiscard]] P blossom(const BasicCurve<P>& curve, std::span<const double> us) {
  assert(static_cast<int>(us.size()) == curve.degree());
  return polar(curve, us).front();
}

/// B restricted to [a, b], reparametrised to [0, 1]: control point i is the blossom
/// value b(a^(n-i), b^i) (Ramshaw 1987), bit for bit blossom(curve, {a, ..., a, b, ..., b})
/// (polar's rounds, n - i with a, then i with b). Exact in the sense that no division
/// appears, so a = b, a > b (reversed piece) and values outside [0, 1] all work. The rounds
/// with a are the same for every control point, so they are done once and their rows
/// shared: O(n^3) operations, one allocation (the result's points) for the degrees a
/// CasteljauRow keeps inline.
[[nodiscard]] Curve portion(const Curve& curve, double a, double b);
[[nodiscard]] Curve3 portion(const Curve3& curve, double a, double b);

}  // namespace bezier::core
