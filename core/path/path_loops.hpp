#pragma once

#include <cstddef>
#include <vector>

#include "core/base/point.hpp"
#include "core/intersect/result.hpp"
#include "core/path/path.hpp"
#include "core/path/path_intersections.hpp"

namespace bezier::path {

/// A loop of a path: the piece of one subpath from segment_t at t to segment_s at s, which
/// starts and ends at the same point (a self-intersection).
struct PathLoop {
  std::size_t segment_t = 0;
  std::size_t segment_s = 0;
  double t = 0.0;
  double s = 0.0;
  core::Point2 point;
  /// |signed_area|.
  double area = 0.0;
  /// piece_area of the loop: counter-clockwise positive.
  double signed_area = 0.0;
  core::IntersectionKind kind = core::IntersectionKind::transversal;
};

/// The loops of a path's self-intersections (as self_intersections found them): one per
/// contact between two points of the same subpath, the piece between them in drawing order
/// (for a closed subpath, the piece that does not pass its start), and one per pair of a
/// segment with itself. Contacts between different subpaths close no loop and give none.
/// Sorted by (segment_t, t, segment_s, s).
[[nodiscard]] std::vector<PathLoop> loops(const Path& path,
                                          const PathSelfIntersectionResult& self);

}  // namespace bezier::path
