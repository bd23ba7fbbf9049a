#include "core/outline/straight_curve.hpp"

#include <cmath>
#include <cstddef>
#include <limits>

#include "core/numeric/expansion.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

/// Whether a coordinate keeps the expansions' products exact: zero, or between 2^-400 and
/// 2^400 in magnitude (the least significant bit of a difference of two such coordinates is
/// at least 2^-452, so products of two stay above 2^-1074, and none overflows).
bool within_exact_range(double x) {
  const double a = std::fabs(x);
  return a == 0.0 || (a >= 0x1p-400 && a <= 0x1p+400);
}

}  // namespace

bool control_points_collinear(std::span<const Point2> p) {
  if (p.size() <= 2) return true;
  const Point2 origin = p[0];
  // The reference P_k: the first control point other than P_0.
  std::size_t k = 1;
  while (k < p.size() && p[k] == origin) ++k;
  if (k == p.size()) return true;
  for (const Point2 q : p) {
    if (!within_exact_range(q.x) || !within_exact_range(q.y)) return false;
  }
  const Point2 reference = p[k];
  constexpr double u = std::numeric_limits<double>::epsilon() / 2.0;
  const double rx = reference.x - origin.x, ry = reference.y - origin.y;
  for (std::size_t i = k + 1; i < p.size(); ++i) {
    const double qx = p[i].x - origin.x, qy = p[i].y - origin.y;
    const double first = qx * ry, second = qy * rx;
    // Each difference is within u of its exact value relatively, each product and the
    // subtraction add one rounding: the computed cross is within 8 u (|first| + |second|)
    // of the exact one (a generous allowance for the terms of order u^2).
    if (std::fabs(first - second) > 8.0 * u * (std::fabs(first) + std::fabs(second))) return false;
    const core::Expansion cross =
        core::Expansion::difference(p[i].x, origin.x) *
            core::Expansion::difference(reference.y, origin.y) -
        core::Expansion::difference(p[i].y, origin.y) *
            core::Expansion::difference(reference.x, origin.x);
    if (cross.sign() != 0) return false;
  }
  return true;
}

}  // namespace bezier::outline
