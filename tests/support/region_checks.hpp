#pragma once

// Checks of a boolean result's promises (core/region/boolean.hpp) that share no code with the
// implementation, and a winding-number oracle over polylines.

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "core/base/curve.hpp"
#include "core/curve/evaluate.hpp"
#include "core/curve/polar.hpp"
#include "core/path/path.hpp"
#include "core/path/path_intersections.hpp"
#include "core/region/boolean.hpp"

namespace bezier::test {

/// The result's contours as a path, one closed subpath per contour.
[[nodiscard]] inline path::Path result_path(const region::BooleanResult& result) {
  path::Path out;
  for (const region::ResultContour& c : result.contours) {
    out.subpaths.push_back({out.segments.size(), c.end_segment - c.first_segment, true});
    for (std::size_t k = c.first_segment; k < c.end_segment; ++k) {
      out.segments.push_back(result.segments[k].curve);
    }
  }
  return out;
}

/// Closed polylines through `per_segment` + 1 points of every segment of each subpath.
[[nodiscard]] inline std::vector<std::vector<core::Point2>> polylines(const path::Path& path,
                                                                      int per_segment) {
  std::vector<std::vector<core::Point2>> out;
  for (const path::Subpath& sub : path.subpaths) {
    std::vector<core::Point2> line;
    for (std::size_t k = 0; k < sub.segment_count; ++k) {
      const core::Curve& s = path.segments[sub.first_segment + k];
      const int steps = s.degree() == 1 ? 1 : per_segment;
      for (int i = 0; i < steps; ++i) line.push_back(core::evaluate(s, static_cast<double>(i) / steps));
    }
    out.push_back(std::move(line));
  }
  return out;
}

/// The winding number of closed polylines about p (signed crossings of the ray to +x),
/// and the distance from p to the nearest polyline edge.
struct PolylineWinding {
  int winding = 0;
  double distance = INFINITY;
};

[[nodiscard]] inline PolylineWinding polyline_winding(
    const std::vector<std::vector<core::Point2>>& lines, core::Point2 p) {
  PolylineWinding out;
  for (const auto& line : lines) {
    const std::size_t n = line.size();
    for (std::size_t i = 0; i < n; ++i) {
      const core::Point2 a = line[i], b = line[(i + 1) % n];
      const core::Point2 ab = b - a, ap = p - a;
      const double len2 = core::dot(ab, ab);
      const double t = len2 > 0 ? std::fmax(0.0, std::fmin(1.0, core::dot(ap, ab) / len2)) : 0.0;
      out.distance = std::fmin(out.distance, core::length(ap - t * ab));
      if ((a.y <= p.y) != (b.y <= p.y)) {
        const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
        if (x > p.x) out.winding += b.y > a.y ? 1 : -1;
      }
    }
  }
  return out;
}

/// Promises 2 and 3: every segment the named piece of its source (interior control points
/// exactly core::portion's, ends within `end_tolerance`), exact joins, closed contours, no
/// zero-length segment, contour areas of one sign each and summing to the total.
inline void expect_clean(const region::BooleanResult& result, const path::Path& a,
                         const path::Path* b, double end_tolerance) {
  ASSERT_EQ(result.status, region::BooleanStatus::ok);
  double total = 0.0;
  for (const region::ResultContour& c : result.contours) {
    ASSERT_LT(c.first_segment, c.end_segment);
    EXPECT_NE(c.area, 0.0);
    total += c.area;
    for (std::size_t k = c.first_segment; k < c.end_segment; ++k) {
      const region::ResultSegment& s = result.segments[k];
      const std::size_t next = k + 1 < c.end_segment ? k + 1 : c.first_segment;
      EXPECT_EQ(s.curve.back(), result.segments[next].curve.front()) << "join after segment " << k;
      bool has_length = false;  // a loop's ends may meet; a zero-length segment is one point
      for (const core::Point2 p : s.curve.points()) has_length = has_length || p != s.curve.front();
      EXPECT_TRUE(has_length) << "segment " << k;
      const path::Path& source = s.source == region::Operand::a ? a : *b;
      ASSERT_LT(s.segment, source.segments.size());
      const core::Curve piece = core::portion(source.segments[s.segment], s.t0, s.t1);
      ASSERT_EQ(piece.degree(), s.curve.degree());
      for (int i = 1; i < piece.degree(); ++i) EXPECT_EQ(piece[i], s.curve[i]) << "segment " << k;
      EXPECT_LE(core::length(piece.front() - s.curve.front()), end_tolerance) << "segment " << k;
      EXPECT_LE(core::length(piece.back() - s.curve.back()), end_tolerance) << "segment " << k;
    }
  }
  EXPECT_NEAR(total, result.area, 1e-12 * (1.0 + std::fabs(total)));
  // Contours neither cross nor overlap themselves or each other: the certified intersection
  // search finds contacts between result segments only at their ends (vertices, where
  // contours may touch), and no segment crosses itself.
  const path::Path contours = result_path(result);
  const path::PathSelfIntersectionResult contacts = path::self_intersections(contours, core::IntersectOptions{});
  ASSERT_EQ(contacts.status, core::IntersectStatus::ok);
  EXPECT_TRUE(contacts.overlaps.empty());
  const auto at_end = [](double t) { return t <= 1e-9 || t >= 1.0 - 1e-9; };
  for (const path::PathContact& c : contacts.intersections) {
    EXPECT_TRUE(at_end(c.intersection.t) && at_end(c.intersection.s))
        << "segments " << c.segment_t << " and " << c.segment_s << " meet at t = " << c.intersection.t
        << ", s = " << c.intersection.s;
  }
  for (const path::SegmentSelfIntersections& w : contacts.within_segments) {
    EXPECT_TRUE(w.result.pairs.empty() && w.result.overlaps.empty()) << "segment " << w.segment;
  }
}

}  // namespace bezier::test
