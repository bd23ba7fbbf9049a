#include "core/measure/interval_roots.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/bernstein_roots.hpp"
#include "core/intersect/bernstein1d.hpp"

namespace bezier::core {

IntervalRoots interval_roots(std::span<const double> c, double a, double b, IntervalEnds ends) {
  assert(!c.empty() && 0.0 <= a && a <= b && b <= 1.0);
  const BernsteinRoots found = bernstein_roots(c);
  const int n = std::max(static_cast<int>(c.size()) - 1, 1);
  // bernstein_roots' own bound on the rounding of a coefficient of a piece.
  const double e = 3.02 * n * bernstein::kU * bernstein::max_abs(c);
  IntervalRoots out;
  out.isolated = found.isolated;
  for (const double r : found.roots) {
    const bool inside = ends == IntervalEnds::closed ? (a <= r && r <= b) : (a < r && r < b);
    if (!inside) continue;
    if (!out.roots.empty()) {
      const double previous = out.roots.back();
      if (std::fabs(bernstein::evaluate(c, previous + (r - previous) / 2)) <= e) {
        // One flat stretch of p: keep its best representative.
        if (std::fabs(bernstein::evaluate(c, r)) < std::fabs(bernstein::evaluate(c, previous)))
          out.roots.back() = r;
        out.isolated = false;
        continue;
      }
    }
    out.roots.push_back(r);
  }
  return out;
}

}  // namespace bezier::core
