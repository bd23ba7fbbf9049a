#include "core/region/region.hpp"

#include <cassert>
#include <utility>

namespace bezier::region {

namespace {

/// Whether `subpath` of `path` ends exactly (bit for bit) where it starts.
bool ends_at_start(const path::Path& path, const path::Subpath& subpath) {
  const core::Curve& first = path.segments[subpath.first_segment];
  const core::Curve& last = path.segments[subpath.first_segment + subpath.segment_count - 1];
  return last.back() == first.front();
}

}  // namespace

Region region_from_path(path::Path path, FillRule rule) {
  Region region;
  region.fill_rule = rule;
  region.path.arc_tolerance = path.arc_tolerance;
  region.path.segments.reserve(path.segments.size() + path.subpaths.size());
  for (const path::Subpath& subpath : path.subpaths) {
    path::Subpath closed{region.path.segments.size(), subpath.segment_count, true};
    const bool needs_line = !ends_at_start(path, subpath);
    const core::Point2 start = path.segments[subpath.first_segment].front();
    const core::Point2 end =
        path.segments[subpath.first_segment + subpath.segment_count - 1].back();
    for (std::size_t k = 0; k < subpath.segment_count; ++k) {
      region.path.segments.push_back(std::move(path.segments[subpath.first_segment + k]));
    }
    if (needs_line) {
      region.path.segments.emplace_back(std::vector<core::Point2>{end, start});
      ++closed.segment_count;
    }
    region.path.subpaths.push_back(closed);
  }
  return region;
}

std::optional<std::size_t> chain_break(const std::vector<core::Curve>& curves) {
  std::size_t chain_start = 0;
  for (std::size_t k = 1; k < curves.size(); ++k) {
    const bool previous_closed = curves[k - 1].back() == curves[chain_start].front();
    if (previous_closed) {
      chain_start = k;
    } else if (curves[k].front() != curves[k - 1].back()) {
      return k;
    }
  }
  return std::nullopt;
}

Region region_from_curves(std::vector<core::Curve> curves, FillRule rule) {
  assert(!chain_break(curves));
  path::Path path;
  std::size_t chain_start = 0;
  for (std::size_t k = 0; k < curves.size(); ++k) {
    const bool closes = curves[k].back() == curves[chain_start].front();
    if (closes || k + 1 == curves.size()) {
      path.subpaths.push_back({chain_start, k + 1 - chain_start, closes});
      chain_start = k + 1;
    }
  }
  path.segments = std::move(curves);
  return region_from_path(std::move(path), rule);
}

}  // namespace bezier::region
