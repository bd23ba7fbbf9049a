#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/base/curve.hpp"

namespace bezier::region {

/// An axis-aligned box: x_lo <= x <= x_hi, y_lo <= y <= y_hi.
struct EdgeBox {
  double x_lo = 0.0, x_hi = 0.0, y_lo = 0.0, y_hi = 0.0;
};

/// The box of a curve's control points, which holds the curve (convex hull property).
/// Written over spans of any extent: with four points (a cubic) the loop unrolls; the
/// comparisons and their order are the same either way.
template <std::size_t Extent>
[[nodiscard]] inline EdgeBox control_point_box_of(std::span<const core::Point2, Extent> points) {
  EdgeBox box{points.front().x, points.front().x, points.front().y, points.front().y};
  for (const core::Point2 p : points) {
    box.x_lo = std::min(box.x_lo, p.x);
    box.x_hi = std::max(box.x_hi, p.x);
    box.y_lo = std::min(box.y_lo, p.y);
    box.y_hi = std::max(box.y_hi, p.y);
  }
  return box;
}

[[nodiscard]] inline EdgeBox control_point_box(const core::Curve& curve) {
  const std::span<const core::Point2> points = curve.points();
  if (points.size() == 4) return control_point_box_of(points.first<4>());
  return control_point_box_of(points);
}

/// The boxes of an arrangement's edges in a bounding-volume hierarchy, so that each ray of
/// side_windings visits only the edges near it (built once per operation, and only when an
/// operation casts enough rays to repay it: side_winding.hpp).
///
/// Each edge's box is control_point_box of its `piece` (the curve the rays test). Each node's box is the smallest box
/// holding its edges' boxes: a node is a range of the edges, ordered by their boxes'
/// centres, split at the median along the longer side of its box until a range holds at
/// most kLeafEdges edges.
///
/// The hierarchy only prunes: `collect` reports every edge whose node boxes all pass the
/// caller's test, so a test that passes every box holding a point that matters loses no
/// edge. Building costs O(E log E) for E edges; a query visits the nodes whose boxes pass.
class EdgeBoxIndex {
 public:
  /// The hierarchy over `boxes`, edge e's box at index e.
  explicit EdgeBoxIndex(std::vector<EdgeBox> boxes);

  /// The box of edge e's piece.
  [[nodiscard]] const EdgeBox& box(std::size_t e) const { return boxes_[e]; }

  /// Appends to `out`, in no particular order, every edge whose box and every enclosing
  /// node's box pass `may_meet(const EdgeBox&)`.
  template <class MayMeet>
  void collect(const MayMeet& may_meet, std::vector<std::size_t>& out) const {
    if (nodes_.empty()) return;
    std::size_t stack[kMaxDepth];
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      if (!may_meet(node.box)) continue;
      if (node.right == 0) {
        for (std::uint32_t k = node.begin; k < node.end; ++k) {
          const std::size_t e = order_[k];
          if (may_meet(boxes_[e])) out.push_back(e);
        }
        continue;
      }
      const std::size_t here = static_cast<std::size_t>(&node - nodes_.data());
      stack[top++] = node.right;
      stack[top++] = here + 1;
    }
  }

 private:
  /// At most this many edges in a leaf: a few box tests are cheaper than another level.
  static constexpr std::uint32_t kLeafEdges = 4;
  /// Median splits halve the range, so the depth stays below log2(edges) + 1 < 64 and the
  /// traversal stack (one pending right child per level, plus the current pair) fits.
  static constexpr std::size_t kMaxDepth = 130;

  /// Nodes in preorder: the left child of node i is node i + 1; right is 0 for a leaf.
  struct Node {
    EdgeBox box;
    std::uint32_t begin = 0, end = 0;
    std::size_t right = 0;
  };

  std::size_t build(std::uint32_t begin, std::uint32_t end);

  std::vector<EdgeBox> boxes_;
  std::vector<std::size_t> order_;
  std::vector<Node> nodes_;
};

}  // namespace bezier::region
