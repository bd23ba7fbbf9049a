#include "core/outline/stroke_shapes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/path/elliptical_arc.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

constexpr std::size_t kMostCirclePieces = 4096;

/// The closed polygon through `corners`, counter-clockwise (reversed when its shoelace area is
/// negative).
Contour polygon(std::vector<Point2> corners) {
  double twice_area = 0.0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    twice_area += core::cross(corners[i], corners[(i + 1) % corners.size()]);
  }
  if (twice_area < 0.0) std::reverse(corners.begin(), corners.end());
  Contour out;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    out.push_back(core::Curve({corners[i], corners[(i + 1) % corners.size()]}));
  }
  return out;
}

Point2 right_normal(Point2 unit) { return {unit.y, -unit.x}; }

}  // namespace

std::size_t circle_pieces(double radius, double tolerance) {
  std::size_t n = 4;
  while (n < kMostCirclePieces &&
         radius * path::circular_arc_cubic_error(2.0 * std::numbers::pi / static_cast<double>(n)) >
             tolerance) {
    ++n;
  }
  return n;
}

Contour circle(Point2 centre, double radius, std::size_t pieces) {
  const double delta = 2.0 * std::numbers::pi / static_cast<double>(pieces);
  const double k = 4.0 / 3.0 * std::tan(delta / 4.0);
  // The quarter turns exactly (cos(π/2) is not 0 in doubles), the other angles as rounded.
  auto on_circle = [&](std::size_t i) {
    i %= pieces;
    if ((4 * i) % pieces == 0) {
      constexpr std::array<Point2, 4> kAxes{Point2{1, 0}, Point2{0, 1}, Point2{-1, 0}, Point2{0, -1}};
      return kAxes[(4 * i) / pieces];
    }
    const double angle = static_cast<double>(i) * delta;
    return Point2{std::cos(angle), std::sin(angle)};
  };
  Contour out;
  for (std::size_t i = 0; i < pieces; ++i) {
    const Point2 e0 = on_circle(i), e1 = on_circle(i + 1);
    const Point2 d0{-e0.y, e0.x}, d1{-e1.y, e1.x};
    out.push_back(core::Curve({centre + radius * e0, centre + radius * (e0 + k * d0),
                               centre + radius * (e1 - k * d1), centre + radius * e1}));
  }
  return out;
}

std::optional<Contour> join_polygon(Point2 point, Point2 t0, Point2 t1, double w, bool miter,
                                    double miter_limit) {
  const double turn = core::cross(t0, t1);
  if (turn == 0.0) return std::nullopt;
  // The outer side is to the right of a left turn (turn > 0), to the left of a right turn.
  const double side = turn > 0.0 ? 1.0 : -1.0;
  const Point2 n0 = side * right_normal(t0), n1 = side * right_normal(t1);
  const double c = core::dot(t0, t1);
  std::vector<Point2> corners{point, point + w * n0};
  if (miter && miter_limit * miter_limit * (1.0 + c) >= 2.0) {
    corners.push_back(point + (w / (1.0 + c)) * (n0 + n1));
  }
  corners.push_back(point + w * n1);
  return polygon(std::move(corners));
}

Contour square_cap(Point2 point, Point2 outward, double w) {
  const Point2 n{-outward.y, outward.x};
  return polygon({point + w * n, point - w * n, point - w * n + w * outward,
                  point + w * n + w * outward});
}

}  // namespace bezier::outline
