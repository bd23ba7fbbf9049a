#include "core/region/contour_chain.hpp"

#include "core/region/edge_germ.hpp"

namespace bezier::region {

std::optional<std::vector<std::vector<std::size_t>>> chain_contours(
    const std::vector<DirectedEdge>& edges, std::size_t vertex_count) {
  // The edges leaving each vertex, in edge order: leaving[leaving_start[v] ..
  // leaving_start[v + 1]) (a counting sort, one list for all vertices).
  std::vector<std::size_t> leaving_start(vertex_count + 1, 0);
  for (const DirectedEdge& e : edges) ++leaving_start[e.from + 1];
  for (std::size_t v = 0; v < vertex_count; ++v) leaving_start[v + 1] += leaving_start[v];
  std::vector<std::size_t> leaving(edges.size());
  {
    std::vector<std::size_t> next(leaving_start.begin(), leaving_start.end() - 1);
    for (std::size_t e = 0; e < edges.size(); ++e) leaving[next[edges[e].from]++] = e;
  }
  std::vector<char> used(edges.size(), 0);  // bytes, not bits
  std::vector<std::vector<std::size_t>> contours;
  std::size_t unused = edges.size();
  for (std::size_t first = 0; first < edges.size(); ++first) {
    if (used[first]) continue;
    // A contour takes at most the edges not used yet: room for them at once (one allocation
    // for a long contour instead of a doubling per power of two).
    std::vector<std::size_t> contour;
    contour.reserve(unused);
    contour.push_back(first);
    used[first] = 1;
    std::size_t current = first;
    while (edges[current].to != edges[first].from) {
      const std::size_t v = edges[current].to;
      std::optional<std::size_t> next;
      std::optional<EdgeGerm> back;
      double best = -1.0;
      for (std::size_t k = leaving_start[v]; k < leaving_start[v + 1]; ++k) {
        const std::size_t candidate = leaving[k];
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
      used[*next] = 1;
      contour.push_back(*next);
      current = *next;
    }
    unused -= contour.size();
    // What is kept stays within twice the contours' lengths (many short contours must not
    // each hold room for all the edges).
    if (contour.capacity() > 2 * contour.size() + 16) contour.shrink_to_fit();
    contours.push_back(std::move(contour));
  }
  return contours;
}

}  // namespace bezier::region
