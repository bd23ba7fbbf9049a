#include "core/region/edge_box_index.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

namespace bezier::region {

namespace {

EdgeBox joined(const EdgeBox& a, const EdgeBox& b) {
  return {std::min(a.x_lo, b.x_lo), std::max(a.x_hi, b.x_hi), std::min(a.y_lo, b.y_lo),
          std::max(a.y_hi, b.y_hi)};
}

}  // namespace

EdgeBoxIndex::EdgeBoxIndex(std::vector<EdgeBox> boxes) : boxes_(std::move(boxes)) {
  order_.resize(boxes_.size());
  std::iota(order_.begin(), order_.end(), std::size_t{0});
  if (!boxes_.empty()) {
    nodes_.reserve(2 * boxes_.size());
    build(0, static_cast<std::uint32_t>(boxes_.size()));
  }
}

std::size_t EdgeBoxIndex::build(std::uint32_t begin, std::uint32_t end) {
  const std::size_t here = nodes_.size();
  nodes_.push_back({});
  EdgeBox box = boxes_[order_[begin]];
  for (std::uint32_t k = begin + 1; k < end; ++k) box = joined(box, boxes_[order_[k]]);
  nodes_[here].box = box;
  nodes_[here].begin = begin;
  nodes_[here].end = end;
  if (end - begin <= kLeafEdges) return here;
  // Centres doubled (lo + hi) to stay exact up to overflow; ties broken by index so that the
  // hierarchy does not depend on the standard library's nth_element.
  const bool along_x = box.x_hi - box.x_lo >= box.y_hi - box.y_lo;
  const auto centre = [&](std::size_t e) {
    return along_x ? boxes_[e].x_lo + boxes_[e].x_hi : boxes_[e].y_lo + boxes_[e].y_hi;
  };
  const std::uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                   [&](std::size_t i, std::size_t j) {
                     const double ci = centre(i), cj = centre(j);
                     return ci < cj || (ci == cj && i < j);
                   });
  build(begin, middle);
  nodes_[here].right = build(middle, end);
  return here;
}

}  // namespace bezier::region
