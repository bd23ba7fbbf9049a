#include "core/outline/loose_curve.hpp"

#include <cmath>
#include <limits>

namespace bezier::outline {

namespace {

using core::Point2;

/// loose_curve.hpp's test on one part: g1, g2 the control points of B' and B'' on it, with
/// the rounding allowances of the parts (0 for the whole curve's own control points).
bool loose_part(const ControlPoints& g1, const ControlPoints& g2, double reach,
                double speed_slack, double bend_slack) {
  const Point2 mid = point_at(g1, 0.5);
  const double mid_squared = squared_length(mid);
  if (!(mid_squared > 0.0)) return false;
  const Point2 direction = mid / std::sqrt(mid_squared);
  double m = std::numeric_limits<double>::infinity();
  for (const Point2 p : g1) m = std::min(m, core::dot(p, direction));
  m -= speed_slack;
  if (!(m > 0.0)) return false;
  const double M2 = std::sqrt(largest_squared_length(g2)) + bend_slack;
  // The factor covers the rounding of the few operations above.
  return reach * M2 < (1.0 - 1e-9) * m * m;
}

}  // namespace

bool loose_everywhere(const ControlPoints& h1, const ControlPoints& h2, double reach,
                      std::int64_t* work) {
  if (h1.empty()) return false;
  if (h2.empty()) {
    // A line: κ = 0 wherever B' is not zero; B' is constant.
    return squared_length(h1[0]) > 0.0;
  }
  if (loose_part(h1, h2, reach, 0.0, 0.0)) return true;
  const double unit = std::numeric_limits<double>::epsilon();
  const double speed_slack = 64.0 * unit * std::sqrt(largest_squared_length(h1));
  const double bend_slack = 64.0 * unit * std::sqrt(largest_squared_length(h2));
  ControlPoints g1, g2;
  for (int parts = 2; parts <= 8; parts *= 2) {
    bool all = true;
    for (int k = 0; k < parts && all; ++k) {
      const double a = static_cast<double>(k) / parts, b = static_cast<double>(k + 1) / parts;
      piece_into(h1, a, b, g1);
      piece_into(h2, a, b, g2);
      if (work != nullptr) {
        const auto k1 = static_cast<std::int64_t>(h1.size()), k2 = static_cast<std::int64_t>(h2.size());
        *work += 2 * (k1 * k1 + k2 * k2);
      }
      all = loose_part(g1, g2, reach, speed_slack, bend_slack);
    }
    if (all) return true;
  }
  return false;
}

}  // namespace bezier::outline
