#pragma once

#include <cmath>
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

/// Descartes' rule of signs on Bernstein coefficients, counting only the coefficients
/// that are clearly nonzero: those within the rounding bound e of zero may have either
/// sign, so they neither count nor separate a change.
struct SignChanges {
  int changes = 0;          ///< sign changes among the coefficients with |c_i| > e
  bool any_small = false;   ///< some coefficient within e of zero
  bool all_small = true;    ///< every coefficient within e of zero (p is zero to rounding)
};

[[nodiscard]] inline SignChanges sign_changes(std::span<const double> c, double e) noexcept {
  SignChanges out;
  int last = 0;
  for (const double v : c) {
    if (std::fabs(v) <= e) {
      out.any_small = true;
      continue;
    }
    const int sign = v > 0 ? 1 : -1;
    if (last != 0 && sign != last) ++out.changes;
    last = sign;
  }
  out.all_small = last == 0;
  return out;
}

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
