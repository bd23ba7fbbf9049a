#pragma once

#include <optional>
#include <span>

#include "core/base/curve.hpp"
#include "core/base/point.hpp"

namespace bezier::core {

/// Signed area enclosed by the control polygon's curve closed with its chord: the Bézier
/// curve with control points P_0..P_n followed by the segment from P_n back to P_0, by
/// Green's theorem A = 1/2 ∮ (x dy - y dx). Positive when that closed path runs
/// counter-clockwise (y axis up). Exact formula, for any degree n >= 0:
///
///   A = Σ_{0 <= i < j <= n} M_ij cross(P_i - P_0, P_j - P_0),
///   M_ij = (j - i) C(n,i) C(n,j) / (2 (2n - 1) C(2n - 2, i + j - 1)).
///
/// Derivation: with B' = Σ_j P_j (B_j^n)' and (B_j^n)' = n (B_{j-1}^{n-1} - B_j^{n-1}),
/// 1/2 ∫_0^1 cross(B, B') dt = 1/2 Σ_{i,j} cross(P_i, P_j) ∫ B_i^n (B_j^n)' dt, and the
/// Bernstein product integral ∫_0^1 B_i^n B_k^m dt = C(n,i) C(m,k) / ((n+m+1) C(n+m, i+k))
/// (Farouki & Rajan, "Algorithms for polynomials in Bernstein form", CAGD 5, 1988, §2)
/// gives the integrals; since ∫ (B_i B_j)' = 0 for i != j (except the end terms, which the
/// chord cancels), only the antisymmetric part survives and simplifies to M_ij above. The
/// integrand is a polynomial of degree 2n - 1 integrated exactly: no quadrature rule, so no
/// degree above which the answer stops being exact. Coordinates are taken relative to
/// P_0, which makes the result translation invariant up to rounding and removes the chord
/// term. Every weight is one rounded division of two integers that are exact in double
/// for n <= 25 (beyond that the weights carry a few roundings, still accurate).
/// Precondition: finite coordinates. O(n^2).
[[nodiscard]] double enclosed_area(std::span<const Point2> points);

/// Signed area enclosed by B on [a, b] and the chord from B(b) back to B(a): the area of
/// the closed path "curve from B(a) to B(b), then straight back". For a self-intersection
/// pair (B(t1) = B(t2)) this is the signed area of the loop. Computed as enclosed_area of
/// the control points of B on [a, b] (what portion() gives, here by two compensated
/// subdivisions, at b and then at a / b: O(n^2)). Any finite a, b (a > b reverses the path
/// and flips the sign; a = b gives 0). Positive counter-clockwise.
[[nodiscard]] double enclosed_area(const Curve& curve, double a, double b);

/// enclosed_area(curve, 0, 1): the curve closed by its chord from P_n back to P_0.
[[nodiscard]] double enclosed_area(const Curve& curve);

/// The Green's-theorem integral of B itself over [a, b]:
///   1/2 ∫_a^b (x y' - x' y) dt = enclosed_area(curve, a, b) + 1/2 cross(B(a), B(b)),
/// the signed area swept by the segment from the origin to B(t). Unlike enclosed_area it
/// depends on the origin (translating by c adds 1/2 cross(c, B(b) - B(a))); summed over the
/// pieces of a closed path it gives the enclosed area. Any finite a, b.
[[nodiscard]] double signed_area(const Curve& curve, double a, double b);

/// signed_area(curve, 0, 1).
[[nodiscard]] double signed_area(const Curve& curve);

/// Whether the curve is closed: P_0 = P_n exactly (bit for bit, as the API defines
/// `closed`). A curve that only nearly closes is open, and its chord is part of its area.
[[nodiscard]] bool is_closed(const Curve& curve) noexcept;

/// The signed area enclosed by a closed curve (P_0 = P_n), counter-clockwise positive;
/// nullopt when the curve is not closed. Self-overlapping parts count with their winding
/// number (Green's theorem), e.g. a figure eight gives the difference of its two lobes.
[[nodiscard]] std::optional<double> closed_area(const Curve& curve);

}  // namespace bezier::core
