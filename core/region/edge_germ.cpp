#include "core/region/edge_germ.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/curve/derivative.hpp"
#include "core/region/boolean_tuning.hpp"

namespace bezier::region {

EdgeGerm germ_at_start(const core::Curve& curve) {
  EdgeGerm germ;
  const int n = curve.degree();
  if (n < 1) return germ;
  germ.reach = core::length(curve.back() - curve.front());
  const std::vector<core::Point2> d = core::derivatives_at(curve, 0.0, n);
  int k = 0;
  while (k < n && d[static_cast<std::size_t>(k)].x == 0.0 && d[static_cast<std::size_t>(k)].y == 0.0) ++k;
  if (k == n) return germ;
  const core::Point2 lead = d[static_cast<std::size_t>(k)];
  const double size = core::length(lead);
  const core::Point2 unit = lead / size;
  germ.angle = std::atan2(unit.y, unit.x);
  for (int j = k + 1; j < n; ++j) {
    const double side = core::cross(unit, d[static_cast<std::size_t>(j)]);
    if (side != 0.0) {
      germ.turn = side / std::pow(size, static_cast<double>(j + 1) / (k + 1));
      germ.turn_is_curvature = k == 0 && j == 1;
      break;
    }
  }
  return germ;
}

double ccw_angle(const EdgeGerm& from, const EdgeGerm& to) {
  constexpr double two_pi = 2.0 * std::numbers::pi;
  double a = std::fmod(to.angle - from.angle, two_pi);
  if (a < 0.0) a += two_pi;
  if (a < kTangentTieAngle || two_pi - a < kTangentTieAngle) {
    if (from.turn_is_curvature && to.turn_is_curvature) {
      // The offset of `to` from `from` seen from the vertex at half the shorter reach.
      const double r = 0.5 * std::min(from.reach, to.reach);
      const double offset =
          (a < kTangentTieAngle ? a : a - two_pi) + 0.5 * r * (to.turn - from.turn);
      if (offset > 0.0) return kTangentTieAngle * offset / (1.0 + offset) * 0.5;
      if (offset < 0.0) return two_pi + kTangentTieAngle * offset / (1.0 - offset) * 0.5;
      return 0.0;
    }
    // One tangent: the one that bends further left lies counter-clockwise.
    if (to.turn > from.turn) return kTangentTieAngle * (to.turn - from.turn) / (1.0 + std::fabs(to.turn - from.turn)) * 0.5;
    if (to.turn < from.turn) return two_pi - kTangentTieAngle * (from.turn - to.turn) / (1.0 + std::fabs(from.turn - to.turn)) * 0.5;
    return 0.0;
  }
  return a;
}

}  // namespace bezier::region
