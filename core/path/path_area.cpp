#include "core/path/path_area.hpp"

#include <cassert>
#include <vector>

#include "core/curve/area.hpp"
#include "core/curve/evaluate.hpp"

namespace bezier::path {

namespace {

/// 1/2 Σ cross(v_k - v_0, v_{k+1} - v_0) over the closed polygon v_0 .. v_{m-1}.
double polygon_area(const std::vector<core::Point2>& v) {
  double twice = 0.0;
  for (std::size_t k = 1; k + 1 < v.size(); ++k) twice += core::cross(v[k] - v[0], v[k + 1] - v[0]);
  return 0.5 * twice;
}

}  // namespace

double closed_chain_area(std::span<const core::Curve* const> chain) {
  // polygon_area of the segments' first points, summed as it sums them, without the list.
  double area = 0.0;
  double twice = 0.0;
  const core::Point2 first = chain.empty() ? core::Point2{} : chain.front()->front();
  for (std::size_t k = 0; k < chain.size(); ++k) {
    area += core::enclosed_area(*chain[k]);
    if (k >= 1 && k + 1 < chain.size()) {
      twice += core::cross(chain[k]->front() - first, chain[k + 1]->front() - first);
    }
  }
  return area + 0.5 * twice;
}

double closed_subpath_area(const Path& path, const Subpath& subpath) {
  assert(subpath.closed);
  std::vector<const core::Curve*> chain;
  chain.reserve(subpath.segment_count);
  for (std::size_t k = 0; k < subpath.segment_count; ++k) {
    chain.push_back(&path.segments[subpath.first_segment + k]);
  }
  return closed_chain_area(chain);
}

std::optional<double> closed_area(const Path& path) {
  std::optional<double> sum;
  for (const Subpath& subpath : path.subpaths) {
    if (subpath.closed) sum = sum.value_or(0.0) + closed_subpath_area(path, subpath);
  }
  return sum;
}

double piece_area(const Path& path, std::size_t i, double t, std::size_t j, double s) {
  assert(i <= j);
  if (i == j) return core::enclosed_area(path.segments[i], t, s);
  std::vector<core::Point2> corners{core::evaluate(path.segments[i], t)};
  double area = core::enclosed_area(path.segments[i], t, 1.0);
  for (std::size_t k = i + 1; k < j; ++k) {
    corners.push_back(path.segments[k].front());
    area += core::enclosed_area(path.segments[k]);
  }
  corners.push_back(path.segments[j].front());
  area += core::enclosed_area(path.segments[j], 0.0, s);
  corners.push_back(core::evaluate(path.segments[j], s));
  return area + polygon_area(corners);
}

}  // namespace bezier::path
