#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "core/base/curve.hpp"

namespace bezier::region {

/// An edge of the result: a curve from vertex `from` to vertex `to`, keeping the region on
/// its left. `tag` is the caller's (which arrangement edge, which way).
struct DirectedEdge {
  std::size_t from = 0;
  std::size_t to = 0;
  core::Curve curve = core::Curve({core::Point2{}});
  std::size_t tag = 0;

  DirectedEdge() = default;
  /// Every member given, for emplace_back (which builds an aggregate from parentheses only
  /// from C++20 on, and clang only from version 16).
  DirectedEdge(std::size_t from_vertex, std::size_t to_vertex, core::Curve piece,
               std::size_t edge_tag)
      : from(from_vertex), to(to_vertex), curve(std::move(piece)), tag(edge_tag) {}
};

/// Chains directed edges into closed contours, each a list of indices into `edges` in order.
///
/// Every edge is used once. From an unused edge (the lowest index first) the chain goes on at
/// the end vertex v of the current edge e with an unused edge leaving v; when several leave
/// v, the first one met turning clockwise from e's reverse (the germ of e read backwards
/// from v), edges ordered around v by tangent angle and then by turn (edge_germ.hpp). The
/// region is on the left of e, i.e. in the sector clockwise from e's reverse to the next
/// edge; taking that next edge keeps the contour on the boundary of that one sector, so two
/// contours that meet at v touch there without crossing. A chain closes when it reaches its
/// first edge's start vertex.
///
/// nullopt when a chain reaches a vertex without an unused edge leaving it (the edges do not
/// balance at every vertex: not the boundary of a region).
[[nodiscard]] std::optional<std::vector<std::vector<std::size_t>>> chain_contours(
    const std::vector<DirectedEdge>& edges, std::size_t vertex_count);

}  // namespace bezier::region
