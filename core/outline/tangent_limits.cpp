#include "core/outline/tangent_limits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/bernstein/roots.hpp"
#include "core/outline/control_points.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

}  // namespace

Point2 end_tangent(std::span<const Point2> p, bool at_start) {
  ControlPoints h(p), next;
  double sign = 1.0;
  const double scale =
      std::max(std::sqrt(largest_squared_length(h)), std::numeric_limits<double>::min());
  const double least = 1e-12 * scale * static_cast<double>(p.size());
  while (h.size() > 1) {
    hodograph_into(h, next);
    std::swap(h, next);
    const Point2 v = at_start ? h[0] : h.back();
    const double len = core::length(v);
    if (len > least) return (sign / len) * v;
    if (!at_start) sign = -sign;
  }
  return {1.0, 0.0};
}

std::vector<double> stationary_points(const core::Curve& curve) {
  ControlPoints h;
  hodograph_into(curve.points(), h);
  const double scale = std::sqrt(largest_squared_length(h));
  if (h.size() < 2 || scale == 0.0) return {};
  core::Coeffs xs(h.size(), core::Coeffs::Uninitialized{}), ys(h.size(), core::Coeffs::Uninitialized{});
  for (std::size_t i = 0; i < h.size(); ++i) {
    xs[i] = h[i].x;
    ys[i] = h[i].y;
  }
  const bool use_x = std::any_of(xs.begin(), xs.end(), [](double v) { return v != 0.0; });
  std::vector<double> out;
  for (const double t : core::bernstein_roots(use_x ? std::span<const double>(xs) : std::span<const double>(ys)).roots) {
    if (!(t > 0.0 && t < 1.0)) continue;
    if (core::length(point_at(h, t)) <= 1e-9 * scale) out.push_back(t);
  }
  return out;
}

}  // namespace bezier::outline
