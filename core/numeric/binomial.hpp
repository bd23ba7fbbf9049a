#pragma once

#include <cassert>

namespace bezier::core {

/// C(n, k) as a double, exact while C(n, k) (n - k) < 2^53 (every k for n <= 50; the
/// multiplicative formula keeps each partial product an integer: C(n, j) * (n - j) / (j + 1)
/// = C(n, j + 1)). Computed per call: no static table, so no hidden shared state.
[[nodiscard]] constexpr double binomial(int n, int k) noexcept {
  assert(n >= 0);
  if (k < 0 || k > n) return 0.0;
  if (k > n - k) k = n - k;
  double c = 1.0;
  for (int j = 0; j < k; ++j) c = c * (n - j) / (j + 1);
  return c;
}

}  // namespace bezier::core
