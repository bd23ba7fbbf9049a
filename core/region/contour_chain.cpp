#include "core/region/contour_chain.hpp"

#include "core/region/edge_germ.hpp"

namespace bezier::region {

std::optional<std::vector<std::vector<std::size_t>>> chain_contours(
    const std::vector<DirectedEdge>& edges, std::size_t vertex_count) {
  std::vector<std::vector<std::size_t>> leaving(vertex_count);
  for (std::size_t e = 0; e < edges.size(); ++e) leaving[edges[e].from].push_back(e);
  std::vector<bool> used(edges.size(), false);
  std::vector<std::vector<std::size_t>> contours;
  for (std::size_t first = 0; first < edges.size(); ++first) {
    if (used[first]) continue;
    std::vector<std::size_t> contour{first};
    used[first] = true;
    std::size_t current = first;
    while (edges[current].to != edges[first].from) {
      const std::size_t v = edges[current].to;
      std::optional<std::size_t> next;
      std::optional<EdgeGerm> back;
      double best = -1.0;
      for (std::size_t candidate : leaving[v]) {
        if (used[candidate]) continue;
        if (!next) {
          next = candidate;
          continue;
        }
        if (!back) {
          back = germ_at_start(core::reversed(edges[current].curve));
          best = ccw_angle(*back, germ_at_start(edges[*next].curve));
        }
        const double angle = ccw_angle(*back, germ_at_start(edges[candidate].curve));
        if (angle > best) {
          best = angle;
          next = candidate;
        }
      }
      if (!next) return std::nullopt;
      used[*next] = true;
      contour.push_back(*next);
      current = *next;
    }
    contours.push_back(std::move(contour));
  }
  return contours;
}

}  // namespace bezier::region
