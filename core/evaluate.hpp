#pragma once

#include <vector>

#include "core/curve.hpp"

namespace bezier::core {

/// B(t) by de Casteljau's algorithm: n rounds of P_i <- (1-t) P_i + t P_{i+1}.
/// Any finite t is allowed; outside [0,1] the polynomial is extrapolated. Each step is a
/// convex combination for t in [0,1], which is why the algorithm is backward stable there
/// (Farin, "Curves and Surfaces for CAGD", 5th ed., §4.1). Returns P_0 exactly at t = 0 and
/// P_n exactly at t = 1.
template <class P>
[[nodiscard]] P evaluate(const BasicCurve<P>& curve, double t) {
  std::vector<P> work(curve.points().begin(), curve.points().end());
  for (std::size_t level = work.size() - 1; level > 0; --level) {
    for (std::size_t i = 0; i < level; ++i) work[i] = lerp(work[i], work[i + 1], t);
  }
  return work.front();
}

/// The parameters of `count` uniform samples: t_i = i / (count - 1), so 0 and 1 are
/// included exactly. count = 1 gives {0}. Precondition: count >= 1.
[[nodiscard]] std::vector<double> uniform_parameters(int count);

/// B(t_i) at each parameter of uniform_parameters(count).
template <class P>
[[nodiscard]] std::vector<P> sample(const BasicCurve<P>& curve, int count) {
  std::vector<P> samples;
  for (const double t : uniform_parameters(count)) samples.push_back(evaluate(curve, t));
  return samples;
}

}  // namespace bezier::core
