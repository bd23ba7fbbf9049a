#pragma once

#include <span>
#include <vector>

namespace bezier::core {

/// The roots in [0, 1] of a scalar polynomial in Bernstein form, ascending.
struct BernsteinRoots {
  std::vector<double> roots;
  /// False when the polynomial is zero to within its rounding on some interval (then
  /// every point there is a root, and that interval's midpoint is reported), or when the
  /// subdivision reached its depth limit around a cluster of roots.
  bool isolated = true;
};

/// Roots of p(t) = Σ c_i C(n,i) (1-t)^(n-i) t^i on [0, 1] by subdivision with Descartes'
/// rule of signs on the Bernstein coefficients (Lane & Riesenfeld, "Bounds on a polynomial",
/// BIT 21, 1981): an interval whose coefficients (each a portion of p, rounded) have no
/// sign change beyond their rounding bound holds no root; one sign change means exactly
/// one root, found by bisection to full precision (every bisection step is a sign of p
/// evaluated by de Casteljau); more sign changes split the interval in two. A cluster that
/// is still unresolved at width 2^-max_depth is reported once, at its midpoint, then
/// polished by Newton's method. Exact zeros at 0 and 1 are reported exactly; roots closer
/// than 2^-30 to each other are reported once. Bounded: at most 2^max_depth intervals, in practice
/// a few per root.
[[nodiscard]] BernsteinRoots bernstein_roots(std::span<const double> c, int max_depth = 40);

}  // namespace bezier::core
