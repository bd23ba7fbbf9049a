#pragma once

#include <cmath>
#include <span>
#include <vector>

#include "core/bernstein/tuning.hpp"

namespace bezier::core {

/// The roots in [0, 1] of a scalar polynomial in Bernstein form, ascending.
struct BernsteinRoots {
  std::vector<double> roots;
  /// False when some root stands for a stretch where p is zero to within its rounding:
  /// p within its rounding bound on a whole interval (then every point there is a root),
  /// a cluster still unresolved at the depth limit, or several roots found on one flat
  /// stretch and reported as one (a multiple root). Exact zeros, at the ends or at the
  /// points where the interval was split, leave it true.
  bool isolated = true;
  /// The intervals examined, each a portion of p (O(n^2) operations) and a few evaluations:
  /// the measure of the search's work (clusters and multiple roots take many).
  int intervals = 0;
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
/// sign change beyond their rounding bound e = 3.02 n u max|c_i| holds no root; one sign
/// change means exactly one root, found by bisection to full precision (every bisection
/// step is a sign of p evaluated by de Casteljau); more sign changes split the interval in
/// two. Exact zeros of p at 0, at 1 and at a split point are roots, reported exactly, and
/// the intervals on either side leave that end out of their count. A cluster that is still
/// unresolved at width 2^-max_depth is reported at its midpoint, then polished by Newton's
/// method. Each root is reported once: where p stays within e of zero (a multiple root, a
/// cluster) the search may find several points a little apart, and consecutive ones whose
/// midpoint has a computed |p| <= 3e (e for the points, e for the evaluation) are one
/// root, the one with the smallest |p| (a double root is then within about
/// sqrt(2e / |p''|) of it, a root of multiplicity m within about (m! e / |p^(m)|)^(1/m));
/// roots closer than 2^-30 are one root too. Bounded: at most 2^max_depth intervals, in
/// practice a few per root.
[[nodiscard]] BernsteinRoots bernstein_roots(std::span<const double> c,
                                            int max_depth = bernstein_tuning::kRootDepth);

}  // namespace bezier::core
