#include "core/numeric/quadratic_roots.hpp"

#include <cassert>
#include <cmath>

namespace bezier::core {

RootPair quadratic_roots(double c2, double c1, double c0, double disc) noexcept {
  assert(c2 != 0.0);
  const double root = disc > 0.0 ? std::sqrt(disc) : 0.0;
  // sgn(c1) with sgn(0) = +1: either sign is stable then, since nothing cancels.
  const double q = -0.5 * (c1 + std::copysign(root, c1));
  if (q == 0.0) return {0.0, 0.0};
  const double r1 = q / c2;
  const double r2 = c0 / q;
  return r1 <= r2 ? RootPair{r1, r2} : RootPair{r2, r1};
}

}  // namespace bezier::core
