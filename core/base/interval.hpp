#pragma once

namespace bezier::core {

/// A closed parameter interval [lo, hi], lo <= hi (a single point when lo == hi).
struct ParamInterval {
  double lo = 0.0;
  double hi = 0.0;

  [[nodiscard]] constexpr double width() const noexcept { return hi - lo; }
  [[nodiscard]] constexpr bool contains(double x) const noexcept { return lo <= x && x <= hi; }
  friend constexpr bool operator==(ParamInterval, ParamInterval) = default;
};

}  // namespace bezier::core
