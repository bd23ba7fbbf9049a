#include "core/path/path.hpp"

#include <algorithm>
#include <cassert>

namespace bezier::path {

const Subpath& subpath_of(const Path& path, std::size_t segment) {
  assert(segment < path.segments.size());
  // Subpaths are in order of their first segment: the last one starting at or before it.
  const auto after = std::upper_bound(
      path.subpaths.begin(), path.subpaths.end(), segment,
      [](std::size_t s, const Subpath& sub) { return s < sub.first_segment; });
  assert(after != path.subpaths.begin());
  return *(after - 1);
}

std::optional<std::size_t> next_segment(const Path& path, std::size_t segment) {
  const Subpath& sub = subpath_of(path, segment);
  const std::size_t last = sub.first_segment + sub.segment_count - 1;
  if (segment < last) return segment + 1;
  if (sub.closed && sub.segment_count > 1) return sub.first_segment;
  return std::nullopt;
}

bool adjacent(const Path& path, std::size_t i, std::size_t j) {
  assert(i != j);
  return next_segment(path, i) == j || next_segment(path, j) == i;
}

}  // namespace bezier::path
