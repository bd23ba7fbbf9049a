#include "core/path/path_loops.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/path/path_area.hpp"

namespace bezier::path {

std::vector<PathLoop> loops(const Path& path, const PathSelfIntersectionResult& self) {
  std::vector<PathLoop> out;
  for (const PathContact& c : self.intersections) {
    if (&subpath_of(path, c.segment_t) != &subpath_of(path, c.segment_s)) continue;
    const double a =
        piece_area(path, c.segment_t, c.intersection.t, c.segment_s, c.intersection.s);
    out.push_back({c.segment_t, c.segment_s, c.intersection.t, c.intersection.s,
                   c.intersection.point, std::fabs(a), a, c.intersection.kind});
  }
  for (const SegmentSelfIntersections& within : self.within_segments) {
    for (const core::SelfIntersection& pair : within.result.pairs) {
      const double a = piece_area(path, within.segment, pair.t, within.segment, pair.s);
      out.push_back({within.segment, within.segment, pair.t, pair.s, pair.point, std::fabs(a), a,
                     pair.kind});
    }
  }
  std::sort(out.begin(), out.end(), [](const PathLoop& p, const PathLoop& q) {
    return std::tuple(p.segment_t, p.t, p.segment_s, p.s) <
           std::tuple(q.segment_t, q.t, q.segment_s, q.s);
  });
  return out;
}

}  // namespace bezier::path
