#pragma once

// Sederberg and Nishita's convex-hull clip of a scalar Bernstein polynomial in exact
// rationals: the reference for bernstein::hull_clip and for how tight the clipping methods'
// kept intervals are.

#include <cstddef>
#include <utility>
#include <vector>

#include "tests/support/exact.hpp"

namespace bezier::test {

/// The least and the largest abscissa where the convex hull of the points (i / k, p_i) meets
/// the band lo <= y <= hi (its extreme points there lie on segments between two control
/// points, or are control points in the band). Precondition: the hull meets the band.
[[nodiscard]] inline std::pair<Rational, Rational> exact_hull_clip(const std::vector<double>& p,
                                                                   const Rational& lo,
                                                                   const Rational& hi) {
  const Rational k(static_cast<int>(p.size()) - 1);
  std::vector<Rational> xs;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Rational xi = Rational(static_cast<int>(i)) / k, ci(p[i]);
    if (lo <= ci && ci <= hi) xs.push_back(xi);
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const Rational xj = Rational(static_cast<int>(j)) / k, cj(p[j]);
      for (const Rational& level : {lo, hi}) {
        if ((ci < level && level < cj) || (cj < level && level < ci))
          xs.push_back(xi + (xj - xi) * (level - ci) / (cj - ci));
      }
    }
  }
  Rational least = xs.at(0), largest = xs.at(0);
  for (const Rational& x : xs) {
    if (x < least) least = x;
    if (largest < x) largest = x;
  }
  return {least, largest};
}

}  // namespace bezier::test
