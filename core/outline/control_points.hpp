#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

#include "core/base/point.hpp"
#include "core/numeric/small_array.hpp"

namespace bezier::outline {

// The control-point arithmetic the offset fits and the stroke repeat for every piece, on
// arrays stored inline for the degrees the API accepts (core::SmallArray), so that a fit
// allocates nothing: hodographs, de Casteljau evaluation and sub-curves, in doubles.

using ControlPoints = core::SmallArray<core::Point2>;

/// The hodograph's control points n (P_{i+1} - P_i) (empty for a single point).
inline void hodograph_into(std::span<const core::Point2> p, ControlPoints& out) {
  const std::size_t n = p.empty() ? 0 : p.size() - 1;
  out.resize(n, ControlPoints::Uninitialized{});
  const auto degree = static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = degree * (p[i + 1] - p[i]);
}

/// B(u) by de Casteljau's algorithm (p not empty): point_at's way above degree 3, out of line
/// (control_points.cpp) so that point_at's few lines for the low degrees inline.
[[nodiscard]] core::Point2 point_at_by_casteljau(std::span<const core::Point2> p, double u);

/// B(u) (p not empty): up to degree 3 from the Bernstein weights directly (positive weights
/// summing to 1: within a few units of rounding of the largest coordinate, as de Casteljau's
/// algorithm is), above by de Casteljau's algorithm.
inline core::Point2 point_at(std::span<const core::Point2> p, double u) {
  const double v = 1.0 - u;
  switch (p.size()) {
    case 1:
      return p[0];
    case 2:
      return v * p[0] + u * p[1];
    case 3:
      return (v * v) * p[0] + (2.0 * u * v) * p[1] + (u * u) * p[2];
    case 4:
      return (v * v * v) * p[0] + (3.0 * u * v * v) * p[1] + (3.0 * u * u * v) * p[2] +
             (u * u * u) * p[3];
    default:
      return point_at_by_casteljau(p, u);
  }
}

/// The control points of B restricted to [a, b] (0 <= a < b <= 1), reparametrised to [0, 1]:
/// the left part at b, then its right part at a / b (de Casteljau, O(n^2)). `out` must not
/// hold p's points.
inline void piece_into(std::span<const core::Point2> p, double a, double b, ControlPoints& out) {
  out.resize(p.size(), ControlPoints::Uninitialized{});
  std::copy(p.begin(), p.end(), out.begin());
  const std::size_t n = p.size() - 1;
  if (b < 1.0) {
    for (std::size_t k = 1; k <= n; ++k)
      for (std::size_t i = n; i >= k; --i) out[i] = core::lerp(out[i - 1], out[i], b);
  }
  if (a > 0.0) {
    const double s = a / b;
    for (std::size_t k = 1; k <= n; ++k)
      for (std::size_t i = 0; i + k <= n; ++i) out[i] = core::lerp(out[i], out[i + 1], s);
  }
}

inline double squared_length(core::Point2 v) noexcept { return v.x * v.x + v.y * v.y; }

/// The largest absolute coordinate of the points (`floor` when larger): for finite
/// coordinates the value core::scale and core::max_abs_coordinate give, with comparisons in
/// place of std::fmax's library calls.
inline double largest_abs_coordinate(std::span<const core::Point2> p, double floor = 0.0) noexcept {
  double s = floor;
  for (const core::Point2 q : p) s = std::max(s, std::max(std::fabs(q.x), std::fabs(q.y)));
  return s;
}

/// The largest squared length of the points (0 for none).
inline double largest_squared_length(std::span<const core::Point2> p) noexcept {
  double m = 0.0;
  for (const core::Point2 q : p) m = std::max(m, squared_length(q));
  return m;
}

}  // namespace bezier::outline
