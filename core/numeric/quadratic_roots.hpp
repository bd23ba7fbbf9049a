#pragma once

namespace bezier::core {

/// Two real roots, lo <= hi.
struct RootPair {
  double lo = 0.0;
  double hi = 0.0;
};

/// The real roots of c2 z² + c1 z + c0 (c2 != 0), given its discriminant
/// disc = c1² − 4 c2 c0. The caller passes disc because it often knows it better than
/// c1² − 4 c2 c0 evaluated in floating point (e.g. from an exact or compensated
/// evaluation, or in a different algebraic form); disc < 0 is taken as 0, a double root.
///
/// Cancellation-free form (Numerical Recipes, 3rd ed., §5.6; the same as Skia's
/// SkFindUnitQuadRoots and kurbo's solve_quadratic): q = −(c1 + sgn(c1) √disc) / 2, roots
/// q / c2 and c0 / q. Each root is then as accurate as the coefficients allow; the naive
/// (−c1 ± √disc) / (2 c2) loses the smaller root to cancellation when c1² ≫ |c2 c0|.
/// When q = 0 (c1 = 0 and disc = 0) the double root is 0.
///
/// Precondition: finite inputs, c2 != 0. NaN in gives NaN out.
[[nodiscard]] RootPair quadratic_roots(double c2, double c1, double c0, double disc) noexcept;

}  // namespace bezier::core
