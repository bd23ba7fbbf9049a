#pragma once

#include <span>
#include <vector>

namespace bezier::core {

/// Which ends of [a, b] count: the critical points of /bounds lie in the open interval,
/// the candidates of /nearest in the closed one.
enum class IntervalEnds { open, closed };

/// The roots of a scalar polynomial in Bernstein form on [0, 1], c_0..c_n, that lie in
/// [a, b] (or (a, b)), ascending, each root once.
///
/// The roots come from bernstein_roots (core/bernstein_roots.hpp): an interval is discarded
/// only when its Bernstein coefficients, each computed within its rounding bound
/// e = 3.02 n u max|c_i|, have one strict sign (then p has no root there: the convex hull
/// property of Lane & Riesenfeld 1981), so no root of the polynomial with the given
/// coefficients is lost except where |p| <= e throughout; a simple root is bisected to full
/// precision. Where p stays within e of zero (a multiple root, a cluster), the finder may
/// report several points a little apart: consecutive roots with |p| <= e at their midpoint
/// are one root here, represented by the one with the smallest |p|. `isolated` is false when
/// the finder met such a flat stretch (a double root is then within about sqrt(e / |p''|) of
/// the reported t, a root of multiplicity m within about (e / |p^(m)|)^(1/m)).
struct IntervalRoots {
  std::vector<double> roots;
  bool isolated = true;
};

/// Precondition: c non-empty, 0 <= a <= b <= 1.
[[nodiscard]] IntervalRoots interval_roots(std::span<const double> c, double a, double b,
                                           IntervalEnds ends);

}  // namespace bezier::core
