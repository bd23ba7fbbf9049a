#pragma once

#include <cstddef>

#include "core/base/point.hpp"

namespace bezier::core {

/// Coordinate k of p (0: x, 1: y, 2: z), for code that runs over the axes of 2-D and 3-D
/// points alike.
[[nodiscard]] inline double& axis(Point2& p, std::size_t k) noexcept { return k == 0 ? p.x : p.y; }
[[nodiscard]] inline double& axis(Point3& p, std::size_t k) noexcept {
  return k == 0 ? p.x : (k == 1 ? p.y : p.z);
}
[[nodiscard]] inline double axis(const Point2& p, std::size_t k) noexcept { return k == 0 ? p.x : p.y; }
[[nodiscard]] inline double axis(const Point3& p, std::size_t k) noexcept {
  return k == 0 ? p.x : (k == 1 ? p.y : p.z);
}

}  // namespace bezier::core
