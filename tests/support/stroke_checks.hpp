#pragma once

// The membership oracle of a stroke's outline (core/outline/stroke.hpp) that shares no code
// with the stroker: the distance to the path from the nearest-point kernel (core/measure/
// nearest.hpp, what /nearest answers with) and the outline's winding numbers from the exact
// winding of core/region (region/winding.hpp).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/measure/nearest.hpp"
#include "core/outline/stroke.hpp"
#include "core/path/path.hpp"
#include "core/region/winding.hpp"

namespace bezier::test {

/// The distance from p to the path (the least over its segments).
[[nodiscard]] inline double distance_to_path(const path::Path& path, core::Point2 p) {
  double d = std::numeric_limits<double>::infinity();
  for (const core::Curve& s : path.segments) d = std::min(d, core::nearest(s, p, 0.0, 1.0).distance);
  return d;
}

/// The outline's contours as a region under the nonzero rule.
[[nodiscard]] inline region::Region outline_region(const outline::StrokeOutline& outline) {
  path::Path boundary;
  for (const outline::Contour& c : outline.contours) {
    boundary.subpaths.push_back({boundary.segments.size(), c.size(), true});
    for (const core::Curve& s : c) boundary.segments.push_back(s);
  }
  return region::Region{std::move(boundary), region::FillRule::nonzero};
}

/// What the membership check saw.
struct MembershipCounts {
  int inside = 0;   ///< points at distance < r checked to be inside
  int outside = 0;  ///< points at distance > r + tolerance checked to be outside
};

/// For each point: the outline's winding number is >= 0 (each contour winds >= 0), nonzero
/// when the point's distance to the path is below r, zero when it is above r + tolerance;
/// points between, and points on the outline itself, are not judged.
inline MembershipCounts check_round_membership(const path::Path& path,
                                               const outline::StrokeOutline& outline, double r,
                                               double tolerance,
                                               const std::vector<core::Point2>& points) {
  MembershipCounts counts;
  const region::RegionWinding winding(outline_region(outline));
  for (const core::Point2 p : points) {
    core::WorkBudget work(std::int64_t{1} << 40);
    const std::optional<region::Winding> w = winding.at(p, work);
    EXPECT_TRUE(w.has_value());
    if (!w || w->boundary) continue;
    const double d = distance_to_path(path, p);
    EXPECT_GE(w->winding, 0) << "at (" << p.x << ", " << p.y << ")";
    const double rounding = 1e-12 * (r + std::fabs(p.x) + std::fabs(p.y));
    if (d < r - rounding) {
      EXPECT_NE(w->winding, 0) << "at (" << p.x << ", " << p.y << "), distance " << d
                               << " < r = " << r;
      ++counts.inside;
    } else if (d > r + tolerance + rounding) {
      EXPECT_EQ(w->winding, 0) << "at (" << p.x << ", " << p.y << "), distance " << d
                               << " > r + tolerance = " << r + tolerance;
      ++counts.outside;
    }
  }
  return counts;
}

}  // namespace bezier::test
