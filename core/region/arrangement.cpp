#include "core/region/arrangement.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <numeric>
#include <span>
#include <tuple>
#include <utility>

#include "core/base/curve.hpp"
#include "core/base/sort_by_key.hpp"
#include "core/curve/derivative.hpp"
#include "core/curve/evaluate.hpp"
#include "core/intersect/options.hpp"
#include "core/path/path_intersections.hpp"
#include "core/region/boolean_tuning.hpp"
#include "core/region/segment_piece.hpp"

namespace bezier::region {

namespace {

using core::Point2;

/// A place on a segment of the combined path that must be a vertex.
struct Event {
  std::size_t segment = 0;
  double t = 0.0;
  Point2 point;
  double radius = 0.0;
  bool segment_end = false;

  Event() = default;
  // Every member given, for emplace_back (which builds an aggregate from parentheses only
  // from C++20 on, and clang only from version 16).
  Event(std::size_t of_segment, double at, Point2 where, double within, bool at_end)
      : segment(of_segment), t(at), point(where), radius(within), segment_end(at_end) {}
};

/// Union-find over event indices.
class Clusters {
 public:
  explicit Clusters(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];
      i = parent_[i];
    }
    return i;
  }
  void join(std::size_t i, std::size_t j) {
    i = find(i);
    j = find(j);
    if (i == j) return;
    if (j < i) std::swap(i, j);
    parent_[j] = i;  // the lower index is the root: vertices are numbered in event order
  }

 private:
  std::vector<std::size_t> parent_;
};

/// Whether two points have the same coordinates bit for bit (+0 and -0 differ).
bool same_bits(Point2 p, Point2 q) {
  return std::bit_cast<std::uint64_t>(p.x) == std::bit_cast<std::uint64_t>(q.x) &&
         std::bit_cast<std::uint64_t>(p.y) == std::bit_cast<std::uint64_t>(q.y);
}

/// n max |P_{i+1} - P_i|: a bound on |B'(t)| over [0, 1].
double speed_bound(const core::Curve& c) {
  double m = 0.0;
  for (int i = 0; i < c.degree(); ++i) m = std::max(m, core::length(c[i + 1] - c[i]));
  return c.degree() * m;
}

double diameter_bound(const core::Curve& c) {
  double m = 0.0;
  for (int i = 0; i < c.degree(); ++i) m = std::max(m, core::length(c[i + 1] - c.front()));
  return 2.0 * m;
}

/// The largest core::scale of the segments, by comparisons rather than library fmax calls:
/// for finite coordinates (the precondition) both give the same largest |coordinate|. Each
/// segment's largest first, as a tree of comparisons for a cubic, then one comparison with
/// the running maximum, so that the steps of one segment do not wait for those of the one
/// before. Not in line: a double still needed after a call is kept in memory by the
/// compiler, and the running maximum would then wait on its own stores at every step.
[[gnu::noinline]] double largest_coordinate(const std::vector<core::Curve>& segments) {
  const auto larger = [](double a, double b) { return a > b ? a : b; };
  const auto magnitude = [&](Point2 p) { return larger(std::fabs(p.x), std::fabs(p.y)); };
  double scale = 0.0;
  for (const core::Curve& s : segments) {
    const std::span<const Point2> points = s.points();
    double m = 0.0;
    if (points.size() == 4) {
      m = larger(larger(magnitude(points[0]), magnitude(points[1])),
                 larger(magnitude(points[2]), magnitude(points[3])));
    } else {
      for (const Point2 p : points) m = larger(m, magnitude(p));
    }
    scale = larger(scale, m);
  }
  return scale;
}

/// Both operands' segments as one path, without the zero-length ones (a single point adds
/// no boundary; inside a subpath it is a joint of its neighbours, and a subpath of points
/// alone is left out), and where each came from.
struct Combined {
  path::Path path;
  std::vector<std::pair<Operand, std::size_t>> origin;
};

void append(Combined& all, const path::Path& p, Operand source) {
  for (const path::Subpath& sub : p.subpaths) {
    const std::size_t first = all.path.segments.size();
    for (std::size_t k = sub.first_segment; k < sub.first_segment + sub.segment_count; ++k) {
      if (core::is_point(p.segments[k])) continue;
      all.path.segments.push_back(p.segments[k]);
      all.origin.emplace_back(source, k);
    }
    const std::size_t count = all.path.segments.size() - first;
    if (count > 0) all.path.subpaths.push_back({first, count, sub.closed});
  }
}

Combined combined(const path::Path& a, const path::Path* b) {
  Combined all;
  const std::size_t most = a.segments.size() + (b != nullptr ? b->segments.size() : 0);
  all.path.segments.reserve(most);
  all.origin.reserve(most);
  append(all, a, Operand::a);
  if (b != nullptr) append(all, *b, Operand::b);
  return all;
}

/// A contact search's findings as events: both ends of every segment (radius base_radius),
/// and each contact as a pair of events, one on each segment through it, listed in `same`
/// (a crossing's radius grows by its parameter intervals' widths times the segments'
/// speed bounds; an overlap's two ends are contacts with exact parameters). Events 2i and
/// 2i + 1 are segment i's ends (t = 0 and t = 1); the contacts' events follow.
struct ContactEvents {
  std::vector<Event> events;
  std::vector<std::pair<std::size_t, std::size_t>> same;  // events that are one vertex
  double largest_radius = 0.0;  // of all the events (kept as they are made)
};

ContactEvents contact_events(const path::Path& all, const path::PathSelfIntersectionResult& found,
                             double base_radius) {
  ContactEvents contacts;
  std::vector<Event>& events = contacts.events;
  std::vector<std::pair<std::size_t, std::size_t>>& same = contacts.same;
  // Each segment's speed bound, found when a contact on it first needs it (-1: not yet).
  std::vector<double> speed(all.segments.size(), -1.0);
  const auto speed_of = [&](std::size_t i) {
    if (speed[i] == -1.0) speed[i] = speed_bound(all.segments[i]);
    return speed[i];
  };

  // Segment ends first (so that a vertex holding one takes its point), then contacts.
  events.reserve(2 * all.segments.size() + 2 * found.intersections.size() +
                 4 * found.overlaps.size());
  same.reserve(found.intersections.size() + 2 * found.overlaps.size());
  if (!all.segments.empty()) contacts.largest_radius = base_radius;
  // Built in place (no Event copied whole: GCC reads a copied Event back in wide pieces
  // across the narrower stores just made, a store-buffer stall each).
  for (std::size_t i = 0; i < all.segments.size(); ++i) {
    const core::Curve& s = all.segments[i];
    events.emplace_back(i, 0.0, s.front(), base_radius, true);
    events.emplace_back(i, 1.0, s.back(), base_radius, true);
  }
  const auto add_pair = [&](std::size_t i, double t, double t_width, std::size_t j, double s,
                            double s_width, Point2 p) {
    const double r = base_radius + std::max(t_width * speed_of(i), s_width * speed_of(j));
    contacts.largest_radius = std::max(contacts.largest_radius, r);
    events.emplace_back(i, t, p, r, false);
    events.emplace_back(j, s, p, r, false);
    same.emplace_back(events.size() - 2, events.size() - 1);
  };
  for (const path::PathContact& c : found.intersections) {
    const core::Intersection& x = c.intersection;
    add_pair(c.segment_t, x.t, x.t_interval.width(), c.segment_s, x.s, x.s_interval.width(),
             x.point);
  }
  const auto add_overlap = [&](std::size_t i, std::size_t j, const core::Overlap& o) {
    const double s_at_lo = o.reversed ? o.s_interval.hi : o.s_interval.lo;
    const double s_at_hi = o.reversed ? o.s_interval.lo : o.s_interval.hi;
    add_pair(i, o.t_interval.lo, 0.0, j, s_at_lo, 0.0,
             core::evaluate(all.segments[i], o.t_interval.lo));
    add_pair(i, o.t_interval.hi, 0.0, j, s_at_hi, 0.0,
             core::evaluate(all.segments[i], o.t_interval.hi));
  };
  for (const path::PathOverlap& o : found.overlaps)
    add_overlap(o.segment_t, o.segment_s, o.overlap);
  for (const path::SegmentSelfIntersections& w : found.within_segments) {
    for (const core::SelfIntersection& p : w.result.pairs) {
      add_pair(w.segment, p.t, 0.0, w.segment, p.s, 0.0, p.point);
    }
    for (const core::Overlap& o : w.result.overlaps) add_overlap(w.segment, w.segment, o);
  }

  return contacts;
}

/// Joins the events that are one vertex: the pairs of `same`, and every two events within
/// the sum of their radii (a sweep over x; the largest radius, max_radius, bounds how far
/// to look).
///
/// An event with the same point (by value) and the same radius as the event before it (a
/// joint's two segment ends, a contact's two events) is joined to it and left out of the
/// sweep: whether an event f is within reach of it is computed from the points' coordinate
/// differences and the radii alone, so f is within reach of it exactly when f is within
/// reach of the event before it, which the sweep tests; the clusters are the same.
Clusters close_events(const std::vector<Event>& events,
                      const std::vector<std::pair<std::size_t, std::size_t>>& same,
                      double max_radius) {
  Clusters clusters(events.size());
  for (const auto& [i, j] : same) clusters.join(i, j);
  // The swept events by x (ties by index), each with its x beside it so that the sort
  // compares in place. Which pairs are joined, and so the clusters, do not depend on the
  // order of ties: each pair within reach is met from whichever of its two comes first.
  std::vector<std::pair<double, std::size_t>> by_x(events.size());
  std::size_t swept = 0;
  for (std::size_t i = 0; i < events.size(); ++i) {
    if (i > 0 && events[i].point == events[i - 1].point &&
        events[i].radius == events[i - 1].radius) {
      clusters.join(i - 1, i);
      continue;
    }
    by_x[swept++] = {events[i].point.x, i};
  }
  by_x.resize(swept);
  // By x, then index (finite coordinates: the order std::sort of the pairs gives).
  core::sort_by_key_then_index(by_x);
  for (std::size_t k = 0; k < by_x.size(); ++k) {
    const Event& e = events[by_x[k].second];
    // by_x holds each event's x as it is: f.point.x - e.point.x read from it.
    const double x = by_x[k].first, farthest = e.radius + max_radius;
    for (std::size_t l = k + 1; l < by_x.size(); ++l) {
      if (by_x[l].first - x > farthest) break;
      const Event& f = events[by_x[l].second];
      const double reach = e.radius + f.radius;
      const Point2 d = f.point - e.point;
      // A zero difference is within every reach (radii are not negative) without hypot.
      if (std::fabs(d.x) <= reach && std::fabs(d.y) <= reach &&
          ((d.x == 0.0 && d.y == 0.0) || core::length(d) <= reach)) {
        clusters.join(by_x[k].second, by_x[l].second);
      }
    }
  }

  return clusters;
}

/// Each event's vertex (numbered by the cluster's first event; a segment end's point is the
/// vertex's point where the cluster holds one) and each vertex's largest radius; the points
/// are appended to `vertices`.
struct VertexAssignment {
  std::vector<std::size_t> vertex_of;
  std::vector<double> vertex_radius;
};

VertexAssignment assign_vertices(const std::vector<Event>& events, Clusters& clusters,
                                 std::vector<Point2>& vertices) {
  VertexAssignment assigned;
  std::vector<std::size_t>& vertex_of = assigned.vertex_of;
  std::vector<double>& vertex_radius = assigned.vertex_radius;
  const std::size_t n = events.size();
  // At most one vertex per event: room for that many, written in place, cut to the count.
  const std::size_t first_vertex = vertices.size();
  vertex_of.resize(n);
  vertices.resize(first_vertex + n);
  vertex_radius.resize(n);
  std::vector<char> from_end(n);  // bytes, not bits: read and written once per event
  std::size_t* const vertex_of_event = vertex_of.data();
  Point2* const point = vertices.data() + first_vertex;
  double* const radius = vertex_radius.data();
  std::size_t count = 0;
  for (std::size_t e = 0; e < n; ++e) {
    const Event& event = events[e];
    // A cluster's root is its least event (Clusters::join keeps the lower root), so it is
    // the cluster's first event here: it opens the vertex, and every later event of the
    // cluster finds the vertex at vertex_of[root].
    const std::size_t root = clusters.find(e);
    if (root == e) {
      vertex_of_event[e] = first_vertex + count;
      point[count] = event.point;
      from_end[count] = event.segment_end ? 1 : 0;
      radius[count] = event.radius;
      ++count;
    }
    const std::size_t v = vertex_of_event[root];
    vertex_of_event[e] = v;
    const std::size_t k = v - first_vertex;
    radius[k] = std::max(radius[k], event.radius);
    if (event.segment_end && !from_end[k]) {
      point[k] = event.point;
      from_end[k] = 1;
    }
  }
  vertices.resize(first_vertex + count);
  vertex_radius.resize(count);

  return assigned;
}

/// The edges: each segment cut at its events' parameters, consecutive cuts at one vertex
/// merged where the piece between them is within 4 vertex radii (an exact end parameter, 0
/// or 1, kept), each piece between consecutive cuts an edge from vertex to vertex (its
/// exact piece, and its snapped copy ending at the vertices' points). Returns each
/// segment's edges, [first, end) of `arrangement.edges`, in order of t. A segment that is
/// its own one edge's exact piece is moved there (left empty in `both`).
std::vector<std::pair<std::size_t, std::size_t>> cut_into_edges(Combined& both,
                                                                const std::vector<Event>& events,
                                                                const VertexAssignment& assigned,
                                                                Arrangement& arrangement) {
  path::Path& all = both.path;
  const std::size_t segment_count = all.segments.size();
  const std::vector<std::size_t>& vertex_of = assigned.vertex_of;
  const std::vector<double>& vertex_radius = assigned.vertex_radius;
  // The contacts' events (after the 2 segment_count ends, contact_events' order) by segment,
  // then event.
  std::vector<std::pair<std::size_t, std::size_t>> contacts_by_segment;
  contacts_by_segment.reserve(events.size() - 2 * segment_count);
  for (std::size_t e = 2 * segment_count; e < events.size(); ++e) {
    contacts_by_segment.emplace_back(events[e].segment, e);
  }
  std::sort(contacts_by_segment.begin(), contacts_by_segment.end());

  // An edge of segment i from its piece `exact` (segment_piece(segment i, t0, t1)).
  const auto add_piece = [&](std::size_t i, double t0, double t1, std::size_t from,
                             std::size_t to, core::Curve exact) {
    const Point2 front = arrangement.vertices[from], back = arrangement.vertices[to];
    // Every member given and built in place, so that no default curve is built and thrown
    // away.
    if (same_bits(exact.front(), front) && same_bits(exact.back(), back)) {
      arrangement.edges.emplace_back(both.origin[i].first, both.origin[i].second, t0, t1, from,
                                     to, std::move(exact), ArrangementEdge::kNotSnapped,
                                     arrangement.edges.size());
      return;
    }
    core::Curve::Points pts(exact.points());
    pts.front() = front;
    pts.back() = back;
    arrangement.edges.emplace_back(both.origin[i].first, both.origin[i].second, t0, t1, from, to,
                                   core::Curve(std::move(pts)), arrangement.snapped_exacts.size(),
                                   arrangement.edges.size());
    arrangement.snapped_exacts.push_back(std::move(exact));
  };
  const auto add_edge = [&](std::size_t i, double t0, double t1, std::size_t from,
                            std::size_t to, bool whole_cut) {
    // A segment cut nowhere inside is not needed any more: its one piece may take it.
    add_piece(i, t0, t1, from, to,
              whole_cut ? segment_piece(std::move(all.segments[i]), t0, t1)
                        : segment_piece(all.segments[i], t0, t1));
  };

  // Edges of one segment in order, for the overlap groups below: [first, end) of arrangement.edges.
  std::vector<std::pair<std::size_t, std::size_t>> edges_of(segment_count);
  // At most one edge fewer than a segment's cuts (its two ends and its contacts' events).
  arrangement.edges.reserve(events.size() - segment_count);
  // A segment's cuts (parameter, vertex), and those kept.
  std::vector<std::pair<double, std::size_t>> cuts;
  std::vector<std::pair<double, std::size_t>> kept;
  std::size_t next_contact = 0;
  for (std::size_t i = 0; i < segment_count; ++i) {
    const std::size_t start_vertex = vertex_of[2 * i], end_vertex = vertex_of[2 * i + 1];
    const bool has_contacts = next_contact < contacts_by_segment.size() &&
                              contacts_by_segment[next_contact].first == i;
    edges_of[i].first = arrangement.edges.size();
    if (!has_contacts && start_vertex != end_vertex) {
      // Cut at its two ends only, at two vertices: what the general case below gives.
      add_edge(i, 0.0, 1.0, start_vertex, end_vertex, true);
      edges_of[i].second = arrangement.edges.size();
      continue;
    }
    // The cuts by parameter, then vertex: cuts that compare equal are equal, so any sort
    // gives the same list; the few cuts of a segment by insertion.
    cuts.clear();
    cuts.emplace_back(0.0, start_vertex);
    for (; next_contact < contacts_by_segment.size() &&
           contacts_by_segment[next_contact].first == i;
         ++next_contact) {
      const std::size_t e = contacts_by_segment[next_contact].second;
      cuts.emplace_back(events[e].t, vertex_of[e]);
    }
    cuts.emplace_back(1.0, end_vertex);
    for (std::size_t k = 1; k < cuts.size(); ++k) {
      const std::pair<double, std::size_t> moving = cuts[k];
      std::size_t j = k;
      for (; j > 0 && moving < cuts[j - 1]; --j) cuts[j] = cuts[j - 1];
      cuts[j] = moving;
    }
    const core::Curve& seg = all.segments[i];
    // Merge consecutive cuts at one vertex, keeping an exact end parameter (0 or 1).
    kept.clear();
    for (const std::pair<double, std::size_t>& cut : cuts) {
      if (!kept.empty() && kept.back().second == cut.second) {
        const double lo = kept.back().first;
        const core::Curve between = core::portion(seg, lo, cut.first);
        if (diameter_bound(between) <= 4.0 * vertex_radius[cut.second]) {
          if (cut.first == 1.0) kept.back().first = 1.0;
          continue;
        }
      }
      if (!kept.empty() && kept.back().first == cut.first) continue;
      kept.push_back(cut);
    }
    if (kept.size() == 3) {
      // Cut once inside (0 < t < 1): both pieces from one halving where it gives them.
      const double t = kept[1].first;
      auto [before, after] = segment_pieces_at(seg, t);
      add_piece(i, 0.0, t, kept[0].second, kept[1].second, std::move(before));
      add_piece(i, t, 1.0, kept[1].second, kept[2].second, std::move(after));
      edges_of[i].second = arrangement.edges.size();
      continue;
    }
    for (std::size_t k = 0; k + 1 < kept.size(); ++k) {
      add_edge(i, kept[k].first, kept[k + 1].first, kept[k].second, kept[k + 1].second,
               kept.size() == 2);
    }
    edges_of[i].second = arrangement.edges.size();
  }

  return edges_of;
}

/// Joins in `groups` the edges that are the same piece of an overlap's shared curve.
void join_overlap_pieces(const path::PathSelfIntersectionResult& found,
                         const std::vector<std::pair<std::size_t, std::size_t>>& edges_of,
                         const Arrangement& arrangement, Clusters& groups) {
  // Coincident groups: within each overlap, the pieces of both segments that are the same
  // piece of the shared curve. Both segments run through the overlap monotonically (the
  // second backwards when it is reversed), so their pieces inside it, listed in that order,
  // are the same pieces in the same order when their cuts are at the same vertices: then the
  // k-th piece of one is the k-th of the other. Matching by end vertices alone is not enough
  // where the shared curve passes a vertex twice (a loop cut once: its two pieces both run
  // between the same two vertices, one each way). When the cuts differ (a cut on one segment
  // only), a piece is matched only with the one piece of the other that runs between the
  // same vertices the same way, and never when it is a loop.
  std::vector<std::size_t> along_t, along_s;
  const auto join_overlap = [&](std::size_t i, std::size_t j, const core::Overlap& o) {
    const double slack = 2.0 * kIntersectionTolerance;
    along_t.clear();
    along_s.clear();
    for (std::size_t p = edges_of[i].first; p < edges_of[i].second; ++p) {
      const ArrangementEdge& ep = arrangement.edges[p];
      if (ep.t0 < o.t_interval.lo - slack || ep.t1 > o.t_interval.hi + slack) continue;
      along_t.push_back(p);
    }
    for (std::size_t q = edges_of[j].first; q < edges_of[j].second; ++q) {
      const ArrangementEdge& eq = arrangement.edges[q];
      if (eq.t0 < o.s_interval.lo - slack || eq.t1 > o.s_interval.hi + slack) continue;
      along_s.push_back(q);
    }
    if (o.reversed) std::reverse(along_s.begin(), along_s.end());
    // Where a piece of j starts and ends, in the direction it runs along the overlap.
    const auto start = [&](const ArrangementEdge& e) { return o.reversed ? e.to : e.from; };
    const auto end = [&](const ArrangementEdge& e) { return o.reversed ? e.from : e.to; };
    bool same_cuts = along_t.size() == along_s.size();
    for (std::size_t k = 0; same_cuts && k < along_t.size(); ++k) {
      const ArrangementEdge& ep = arrangement.edges[along_t[k]];
      const ArrangementEdge& eq = arrangement.edges[along_s[k]];
      same_cuts = ep.from == start(eq) && ep.to == end(eq);
    }
    if (same_cuts) {
      for (std::size_t k = 0; k < along_t.size(); ++k) {
        if (along_t[k] != along_s[k]) groups.join(along_t[k], along_s[k]);
      }
      return;
    }
    for (const std::size_t p : along_t) {
      const ArrangementEdge& ep = arrangement.edges[p];
      if (ep.from == ep.to) continue;
      std::size_t match = SIZE_MAX;
      int count = 0;
      for (const std::size_t q : along_s) {
        const ArrangementEdge& eq = arrangement.edges[q];
        if (q != p && ep.from == start(eq) && ep.to == end(eq)) {
          match = q;
          ++count;
        }
      }
      if (count == 1) groups.join(p, match);
    }
  };
  for (const path::PathOverlap& o : found.overlaps)
    join_overlap(o.segment_t, o.segment_s, o.overlap);
  for (const path::SegmentSelfIntersections& w : found.within_segments) {
    for (const core::Overlap& o : w.result.overlaps) join_overlap(w.segment, w.segment, o);
  }
}

/// Joins in `groups` the edges between the same two vertices that stay within the ray
/// clearance of each other.
void join_thin_lenses(const Arrangement& arrangement, Clusters& groups) {
  // Edges between the same two vertices that stay within the ray clearance of each other
  // (a lens thinner than rounding, e.g. between two crossings of curves that touch to within
  // a few ulps) are one edge for every later decision: no ray can tell their sides apart.
  const double clearance = kRayClearanceRel * arrangement.scale;
  // The edges by their two vertices (lower first), each run of equal ends in edge order.
  struct Ends {
    std::size_t lo, hi, edge;
  };
  // Placed by lower vertex (a counting sort, each vertex's edges in edge order), then each
  // vertex's few edges sorted by upper vertex.
  const std::size_t vertex_count = arrangement.vertices.size();
  std::vector<std::size_t> start(vertex_count + 1, 0);
  for (const ArrangementEdge& edge : arrangement.edges) {
    if (edge.from != edge.to) ++start[std::min(edge.from, edge.to) + 1];
  }
  for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
  std::vector<Ends> by_ends(start[vertex_count]);
  {
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (std::size_t e = 0; e < arrangement.edges.size(); ++e) {
      const ArrangementEdge& edge = arrangement.edges[e];
      if (edge.from == edge.to) continue;
      const std::size_t lo = std::min(edge.from, edge.to);
      by_ends[next[lo]++] = {lo, std::max(edge.from, edge.to), e};
    }
  }
  for (std::size_t v = 0; v < vertex_count; ++v) {
    if (start[v + 1] - start[v] < 2) continue;
    std::sort(by_ends.begin() + static_cast<std::ptrdiff_t>(start[v]),
              by_ends.begin() + static_cast<std::ptrdiff_t>(start[v + 1]),
              [](const Ends& p, const Ends& q) { return std::tie(p.hi, p.edge) < std::tie(q.hi, q.edge); });
  }
  for (std::size_t first = 0, end = 0; first < by_ends.size(); first = end) {
    end = first + 1;
    while (end < by_ends.size() && by_ends[end].lo == by_ends[first].lo &&
           by_ends[end].hi == by_ends[first].hi) {
      ++end;
    }
    for (std::size_t x = first; x < end; ++x) {
      for (std::size_t y = x + 1; y < end; ++y) {
        const ArrangementEdge& p = arrangement.edges[by_ends[x].edge];
        const ArrangementEdge& q = arrangement.edges[by_ends[y].edge];
        const bool flip = p.from != q.from;
        bool near = true;
        for (const double t : {0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875}) {
          const Point2 at_p = core::evaluate(arrangement.exact(p), t);
          const Point2 at_q = core::evaluate(arrangement.exact(q), flip ? 1.0 - t : t);
          near = near && core::length(at_p - at_q) <= clearance;
        }
        if (near) groups.join(by_ends[x].edge, by_ends[y].edge);
      }
    }
  }
}

/// The coincident groups from the joined edges: numbered in edge order (the first edge of
/// each is its representative), each edge's group, and each group's multiplicity per
/// operand (+1 for a member along the representative, -1 against it).
void number_groups(Clusters& groups, Arrangement& arrangement) {
  // At most one group per edge: room for that many, written in place, cut to the count.
  const std::size_t edge_count = arrangement.edges.size();
  arrangement.groups.resize(edge_count);
  CoincidentGroup* const opened = arrangement.groups.data();
  ArrangementEdge* const edges = arrangement.edges.data();
  std::size_t count = 0;
  for (std::size_t e = 0; e < edge_count; ++e) {
    // A root is its cluster's least edge (Clusters::join keeps the lower root): the first of
    // its group here, which opens the group; the later ones read it off the root's edge.
    const std::size_t root = groups.find(e);
    if (root == e) {
      edges[e].group = count;
      opened[count++] = {e, 0, 0, {0, 0}};
    }
    const std::size_t group = edges[root].group;
    edges[e].group = group;
    ++opened[group].member_count;
    // Edges are in segment order, a before b: the group's first edge of a comes first.
  }
  arrangement.groups.resize(count);
  // Each group's edges in one list, group by group, each group's in edge order.
  std::size_t next = 0;
  for (CoincidentGroup& g : arrangement.groups) {
    g.first_member = next;
    next += g.member_count;
  }
  arrangement.group_members.resize(arrangement.edges.size());
  std::vector<std::size_t> filled(arrangement.groups.size(), 0);
  for (std::size_t e = 0; e < arrangement.edges.size(); ++e) {
    const std::size_t g = arrangement.edges[e].group;
    arrangement.group_members[arrangement.groups[g].first_member + filled[g]++] = e;
  }
  for (std::size_t h = 0; h < arrangement.groups.size(); ++h) {
    CoincidentGroup& g = arrangement.groups[h];
    const ArrangementEdge& r = arrangement.edges[g.representative];
    for (const std::size_t e : arrangement.group_edges(h)) {
      const ArrangementEdge& x = arrangement.edges[e];
      // Along the representative when it leaves the same vertex; for a loop (both ends at
      // one vertex) when its tangent at the middle points the same way.
      const bool along =
          (x.from != x.to && r.from != r.to)
              ? x.from == r.from
              : core::dot(core::derivatives_at(arrangement.exact(x), 0.5, 1).front(),
                          core::derivatives_at(arrangement.exact(r), 0.5, 1).front()) > 0.0;
      g.multiplicity[static_cast<std::size_t>(x.source)] += along ? 1 : -1;
    }
  }
}

}  // namespace

Arrangement build_arrangement(const path::Path& a, const path::Path* b, core::WorkBudget& budget) {
  Arrangement out;
  Combined both = combined(a, b);
  const path::Path& all = both.path;
  const double scale = largest_coordinate(all.segments);
  out.scale = scale > 0.0 ? scale : 1.0;
  const double base_radius = kVertexMergeRel * out.scale;

  core::IntersectOptions options;
  options.tolerance = kIntersectionTolerance;
  const path::PathSelfIntersectionResult found = path::self_intersections(all, options, budget);
  out.work = found.stats.work;
  out.status = budget.exhausted() ? core::IntersectStatus::work_cap_reached : found.status;
  if (out.status != core::IntersectStatus::ok) return out;

  const ContactEvents contacts = contact_events(all, found, base_radius);
  Clusters clusters = close_events(contacts.events, contacts.same, contacts.largest_radius);
  const VertexAssignment assigned = assign_vertices(contacts.events, clusters, out.vertices);
  const auto edges_of = cut_into_edges(both, contacts.events, assigned, out);
  Clusters groups(out.edges.size());
  join_overlap_pieces(found, edges_of, out, groups);
  join_thin_lenses(out, groups);
  number_groups(groups, out);
  return out;
}

}  // namespace bezier::region
