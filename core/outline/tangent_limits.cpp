#include "core/outline/tangent_limits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/bernstein/roots.hpp"
#include "core/measure/bernstein_product.hpp"
#include "core/numeric/power_of_two.hpp"
#include "core/outline/control_points.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

/// The largest absolute coordinate of the control points (at least the least normal double).
double control_scale(std::span<const Point2> p) {
  return largest_abs_coordinate(p, std::numeric_limits<double>::min());
}

}  // namespace

Point2 end_tangent(std::span<const Point2> p, bool at_start) {
  if (p.size() >= 2) {
    // The first derivative, when it is not zero to the threshold below (the common case).
    const Point2 v = at_start ? p[1] - p[0] : p[p.size() - 1] - p[p.size() - 2];
    const double len = core::length(static_cast<double>(p.size() - 1) * v);
    const double scale = control_scale(p);
    if (len > 1e-12 * scale * static_cast<double>(p.size())) {
      return (1.0 / len) * (static_cast<double>(p.size() - 1) * v);
    }
  }
  ControlPoints h(p), next;
  double sign = 1.0;
  const double scale = control_scale(p);
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
  double scale = 0.0;
  for (const Point2 q : h) scale = std::max(scale, core::length(q));
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
  if (h.size() < 3) return out;
  // The minima of |B'| inside (0, 1): roots of B' · B'' (degree 2n - 3), on the curve scaled
  // by a power of two (exact) so that the products neither overflow nor underflow.
  const int e = -core::exponent_of(control_scale(curve.points()));
  const core::PowerOfTwo factor(e);
  ControlPoints first(h.size(), ControlPoints::Uninitialized{}), second;
  for (std::size_t i = 0; i < h.size(); ++i) first[i] = factor.times(h[i]);
  hodograph_into(first, second);
  const core::Coeffs dots = core::dot_product_polynomial<Point2>(first, second);
  // Half end_tangent's threshold for |B'| (1e-12 n of the largest control point), so that
  // offset.hpp's frames take the limit tangent at every such minimum.
  double largest = 0.0;
  for (const Point2 p : curve.points()) largest = std::max(largest, core::length(factor.times(p)));
  const double least = 0.5e-12 * static_cast<double>(curve.degree()) * largest;
  const std::size_t found = out.size();
  for (const double t : core::bernstein_roots(std::span<const double>(dots)).roots) {
    if (!(t > 0.0 && t < 1.0) || !(core::length(point_at(first, t)) <= least)) continue;
    const bool known = std::any_of(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(found),
                                   [t](double z) { return std::fabs(z - t) < 1e-6; });
    if (!known) out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace bezier::outline
