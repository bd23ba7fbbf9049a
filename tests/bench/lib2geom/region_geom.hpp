#pragma once
// Conversions between the region benchmarks' inputs and lib2geom's PathVector, and the area
// of a lib2geom result (tests/bench/lib2geom/regions_bench.cpp, region_cases.cpp).

#include <2geom/bezier-curve.h>
#include <2geom/path.h>
#include <2geom/pathvector.h>

#include <cmath>
#include <vector>

#include "tests/bench/region_bench_shapes.hpp"
#include "tests/bench/region_case_truth.hpp"

namespace bezier::bench {

/// A closed path of the outline's cubics (its last point is its first: no closing line).
inline Geom::PathVector geom_outline(const CubicOutline& points) {
  Geom::Path path(Geom::Point(points[0].x, points[0].y));
  for (std::size_t k = 0; k + 3 < points.size(); k += 3) {
    path.appendNew<Geom::CubicBezier>(Geom::Point(points[k + 1].x, points[k + 1].y),
                                      Geom::Point(points[k + 2].x, points[k + 2].y),
                                      Geom::Point(points[k + 3].x, points[k + 3].y));
  }
  path.close(true);
  Geom::PathVector pv;
  pv.push_back(path);
  return pv;
}

/// The signed area of a PathVector, counter-clockwise positive (y up), by Green's theorem on
/// each Bézier curve including the closing segments; `non_bezier` counts curves of other
/// kinds (none are expected from the path operations on Bézier input).
inline double geom_area(const Geom::PathVector& pv, int* non_bezier = nullptr) {
  double sum = 0;
  for (const Geom::Path& path : pv) {
    for (std::size_t i = 0; i < path.size_closed(); ++i) {
      const auto* bezier = dynamic_cast<const Geom::BezierCurve*>(&path[i]);
      if (bezier == nullptr) {
        if (non_bezier != nullptr) ++*non_bezier;
        continue;
      }
      std::vector<core::Point2> points;
      for (const Geom::Point& q : bezier->controlPoints()) points.push_back({q.x(), q.y()});
      sum += green_area(points);
    }
  }
  return sum;
}

/// The area lib2geom's boolean result fills, read under the even-odd rule: the orientation of
/// its contours follows its inputs' and is not made consistent, so that their signed areas do
/// not add up (overlapping squares' xor comes back as two contours of opposite turn). Each
/// contour counts |area| with the sign (-1)^depth, depth the number of other contours around a
/// point 1e-7 inside it (from its first curve's middle); the contours of a boolean result do not
/// cross.
inline double geom_filled_area(const Geom::PathVector& pv, int* non_bezier = nullptr) {
  double total = 0;
  for (std::size_t k = 0; k < pv.size(); ++k) {
    Geom::PathVector one;
    one.push_back(pv[k]);
    const double area = geom_area(one, non_bezier);
    if (pv[k].size_closed() == 0) continue;
    const Geom::Curve& first = pv[k][0];
    const Geom::Point mid = first.pointAt(0.5);
    Geom::Point tangent = first.unitTangentAt(0.5);
    // The left normal (y up) points inside a counter-clockwise contour.
    const Geom::Point inward = Geom::Point(-tangent.y(), tangent.x()) * (area > 0 ? 1e-7 : -1e-7);
    const Geom::Point probe = mid + inward;
    int depth = 0;
    for (std::size_t j = 0; j < pv.size(); ++j) {
      if (j != k) depth += (pv[j].winding(probe) % 2 != 0) ? 1 : 0;
    }
    total += std::fabs(area) * (depth % 2 != 0 ? -1.0 : 1.0);
  }
  return total;
}

}  // namespace bezier::bench
