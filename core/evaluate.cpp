#include "core/evaluate.hpp"

#include <cassert>

namespace bezier::core {

std::vector<double> uniform_parameters(int count) {
  assert(count >= 1);
  std::vector<double> ts(static_cast<std::size_t>(count));
  if (count == 1) return {0.0};
  // i / (count - 1) rather than i * step: one rounding, and the last value is exactly 1.
  const double last = count - 1;
  for (int i = 0; i < count; ++i) ts[static_cast<std::size_t>(i)] = i / last;
  return ts;
}

}  // namespace bezier::core
