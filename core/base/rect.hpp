#pragma once

#include <cassert>
#include <span>

#include "core/base/point.hpp"

namespace bezier::core {

/// A closed axis-aligned rectangle of the plane: the points q with min.x <= q.x <= max.x
/// and min.y <= q.y <= max.y. Invariant (not checked): min.x <= max.x and min.y <= max.y;
/// a single point when min == max. Plain coordinates, passed by value; nothing here rounds
/// except grown().
struct Rect {
  Point2 min;
  Point2 max;

  /// The least rectangle holding this one and p. A face equal to p's coordinate stays as it
  /// is (as std::min(face, p.x) keeps it), so +0 and -0 faces keep their sign.
  [[nodiscard]] constexpr Rect including(Point2 p) const noexcept {
    return {{p.x < min.x ? p.x : min.x, p.y < min.y ? p.y : min.y},
            {max.x < p.x ? p.x : max.x, max.y < p.y ? p.y : max.y}};
  }

  /// Each face moved outward by `margin` >= 0. Each face rounds once (to nearest), so a
  /// caller that needs the exact widened rectangle inside the result allows for that half
  /// ulp in its margin.
  [[nodiscard]] constexpr Rect grown(double margin) const noexcept {
    return {{min.x - margin, min.y - margin}, {max.x + margin, max.y + margin}};
  }

  /// Whether the two closed rectangles share a point (touching counts): neither lies
  /// wholly beyond the other along an axis. With a NaN face no comparison is true, so the
  /// rectangles are not proven apart and count as meeting.
  [[nodiscard]] constexpr bool intersects(const Rect& other) const noexcept {
    return !(max.x < other.min.x || other.max.x < min.x || max.y < other.min.y ||
             other.max.y < min.y);
  }

  friend constexpr bool operator==(const Rect&, const Rect&) = default;
};

/// The least rectangle holding the points: its faces are the points' extreme coordinates,
/// exactly (no arithmetic). Precondition: at least one point.
[[nodiscard]] constexpr Rect bounding_rect(std::span<const Point2> points) noexcept {
  assert(!points.empty());
  Rect r{points.front(), points.front()};
  for (const Point2 p : points) r = r.including(p);
  return r;
}

}  // namespace bezier::core
