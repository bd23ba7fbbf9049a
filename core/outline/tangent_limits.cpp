#include "core/outline/tangent_limits.hpp"

#include <algorithm>
#include <limits>

#include "core/bernstein/roots.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

std::vector<Point2> hodograph(std::span<const Point2> p) {
  const double n = static_cast<double>(p.size() - 1);
  std::vector<Point2> h;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) h.push_back(n * (p[i + 1] - p[i]));
  return h;
}

double largest_norm(std::span<const Point2> q) {
  double m = 0.0;
  for (const Point2 p : q) m = std::max(m, core::length(p));
  return m;
}

Point2 plain_point(std::vector<Point2> q, double t) {
  for (std::size_t k = q.size() - 1; k > 0; --k)
    for (std::size_t i = 0; i < k; ++i) q[i] = core::lerp(q[i], q[i + 1], t);
  return q.front();
}

}  // namespace

Point2 end_tangent(std::span<const Point2> p, bool at_start) {
  std::vector<Point2> h(p.begin(), p.end());
  double sign = 1.0;
  const double scale = std::max(largest_norm(h), std::numeric_limits<double>::min());
  while (h.size() > 1) {
    h = hodograph(h);
    const Point2 v = at_start ? h.front() : h.back();
    const double len = core::length(v);
    if (len > 1e-12 * scale * static_cast<double>(p.size())) return (sign / len) * v;
    if (!at_start) sign = -sign;
  }
  return {1.0, 0.0};
}

std::vector<double> stationary_points(const core::Curve& curve) {
  const std::vector<Point2> h = hodograph(curve.points());
  const double scale = largest_norm(h);
  if (h.size() < 2 || scale == 0.0) return {};
  std::vector<double> xs, ys;
  for (const Point2 p : h) {
    xs.push_back(p.x);
    ys.push_back(p.y);
  }
  const bool use_x = std::any_of(xs.begin(), xs.end(), [](double v) { return v != 0.0; });
  std::vector<double> out;
  for (const double t : core::bernstein_roots(use_x ? xs : ys).roots) {
    if (!(t > 0.0 && t < 1.0)) continue;
    if (core::length(plain_point(h, t)) <= 1e-9 * scale) out.push_back(t);
  }
  return out;
}

}  // namespace bezier::outline
