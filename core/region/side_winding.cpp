#include "core/region/side_winding.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "core/curve/derivative.hpp"
#include "core/curve/evaluate.hpp"
#include "core/curve/subdivide.hpp"
#include "core/region/boolean_tuning.hpp"

namespace bezier::region {

namespace {

using core::Point2;

/// The turns tried from the left normal, radians: alternating sides, none a simple
/// fraction of a right angle so that a ray rarely runs along axis-aligned or diagonal edges.
constexpr double kTurns[] = {0.0, 0.613, -0.613, 1.171, -1.171, 0.307, -0.307,
                             0.919, -0.919, 1.397, -1.397, 0.151, -0.151};

/// Which end of a piece is the ray's origin (the representative's halves).
enum class OriginEnd { none, front, back };

struct Ray {
  Point2 origin;
  Point2 direction;
  double clearance = 0.0;
};

struct Count {
  int crossings = 0;
  bool clear = true;
  /// Unclear at a piece whose control points all lie within twice the clearance of the
  /// ray's origin: the edge passes that close to the origin, so every direction meets it
  /// there and no other ray is tried.
  bool at_origin = false;
};

void count_crossings(const core::Curve& piece, const Ray& ray, OriginEnd origin, bool check_ends,
                     int depth, Count& count, core::WorkBudget& budget) {
  if (!count.clear || budget.exhausted()) return;
  const int n = piece.degree();
  if (!budget.spend(n + 1)) return;
  const auto pts = piece.points();
  double min_c = INFINITY, max_c = -INFINITY, min_r = INFINITY, max_r = -INFINITY;
  bool rising = true, falling = true;
  double previous = 0.0;
  for (int i = 0; i <= n; ++i) {
    const Point2 v = pts[static_cast<std::size_t>(i)] - ray.origin;
    const double c = core::cross(ray.direction, v);
    const double r = core::dot(ray.direction, v);
    // Comparisons rather than std::fmin / std::fmax, which are library calls here: the
    // extremes start infinite and only ever take a compared value, so a NaN c or r (only
    // from a coordinate difference that overflows) is passed over as fmin / fmax pass it
    // over, and a zero's sign does not matter to the tests below.
    if (c < min_c) min_c = c;
    if (c > max_c) max_c = c;
    if (r < min_r) min_r = r;
    if (r > max_r) max_r = r;
    if (i > 0) {
      rising = rising && c >= previous;
      falling = falling && c <= previous;
    }
    previous = c;
  }
  const Point2 v0 = pts.front() - ray.origin, vn = pts.back() - ray.origin;
  const double c0 = core::cross(ray.direction, v0), cn = core::cross(ray.direction, vn);
  const double eps = ray.clearance;
  if (check_ends) {
    // The ray through (or beside) a vertex: which side the edges leave it is not decided here.
    if (std::fabs(c0) <= eps && core::dot(ray.direction, v0) > -eps) count.clear = false;
    if (std::fabs(cn) <= eps && core::dot(ray.direction, vn) > -eps) count.clear = false;
    if (!count.clear) return;
  }
  if (origin == OriginEnd::front || origin == OriginEnd::back) {
    // c is 0 at the origin end; a monotone c has no other zero.
    if ((rising || falling) && max_c - min_c > 0.0) return;
  } else {
    if (min_c > 0.0 || max_c < 0.0) return;
    if (max_r < -eps) return;
    if ((rising || falling) && min_r > eps) {
      if (c0 < 0.0 && cn > 0.0) count.crossings += 1;
      if (c0 > 0.0 && cn < 0.0) count.crossings -= 1;
      if (c0 == 0.0 || cn == 0.0) count.clear = false;  // a zero at a split point
      return;
    }
    if ((rising || falling) && (c0 > 0.0) == (cn > 0.0) && c0 != 0.0 && cn != 0.0) return;
  }
  if (depth >= kRayMaxDepth) {
    count.clear = false;
    bool near = true;
    for (const Point2 p : pts) near = near && core::length(p - ray.origin) <= 2.0 * eps;
    count.at_origin = near;
    return;
  }
  if (!budget.spend(static_cast<std::int64_t>(n + 1) * (n + 1))) return;
  // Halve, away from a point on the ray's line so that no crossing sits at the split.
  double t = 0.5;
  for (const double candidate : {0.5, 0.4375, 0.5625, 0.40625}) {
    t = candidate;
    if (std::fabs(core::cross(ray.direction, core::evaluate(piece, t) - ray.origin)) > eps) break;
  }
  const core::Split<Point2> halves = core::subdivide(piece, t);
  count_crossings(halves.left, ray, origin == OriginEnd::front ? OriginEnd::front : OriginEnd::none,
                  false, depth + 1, count, budget);
  count_crossings(halves.right, ray, origin == OriginEnd::back ? OriginEnd::back : OriginEnd::none,
                  false, depth + 1, count, budget);
}

/// Whether an edge whose control points lie in `box` may change the ray's count: false only
/// when count_crossings' first pass over those points would return at once with no crossing
/// and the ray still clear, i.e. every c_i = cross(d, P_i - m) > clearance, or every
/// c_i < -clearance, or every r_i = dot(d, P_i - m) < -clearance (then no end of the edge is
/// near the ray either). c and r computed in doubles are monotone in each coordinate of P
/// (each subtraction, product by a fixed factor and difference rounds monotonically, and
/// -ffp-contract=off keeps them separate), so their extremes over the box's points are
/// bounded by their values at the box's corners chosen by the signs of d; the margin of
/// twice the clearance leaves room beyond that. Only called when no value can overflow
/// (SideWindingIndex::prune). The corners depend only on the ray, so they are chosen once per ray.
class MayMeet {
 public:
  explicit MayMeet(const Ray& ray)
      : origin_(ray.origin),
        d_(ray.direction),
        margin_(2.0 * ray.clearance),
        c_low_x_(ray.direction.y >= 0.0 ? &EdgeBox::x_hi : &EdgeBox::x_lo),
        c_low_y_(ray.direction.x >= 0.0 ? &EdgeBox::y_lo : &EdgeBox::y_hi),
        c_high_x_(ray.direction.y >= 0.0 ? &EdgeBox::x_lo : &EdgeBox::x_hi),
        c_high_y_(ray.direction.x >= 0.0 ? &EdgeBox::y_hi : &EdgeBox::y_lo),
        r_high_x_(ray.direction.x >= 0.0 ? &EdgeBox::x_hi : &EdgeBox::x_lo),
        r_high_y_(ray.direction.y >= 0.0 ? &EdgeBox::y_hi : &EdgeBox::y_lo) {}

  bool operator()(const EdgeBox& box) const {
    if (core::cross(d_, Point2{box.*c_low_x_, box.*c_low_y_} - origin_) > margin_) return false;
    if (core::cross(d_, Point2{box.*c_high_x_, box.*c_high_y_} - origin_) < -margin_) return false;
    if (core::dot(d_, Point2{box.*r_high_x_, box.*r_high_y_} - origin_) < -margin_) return false;
    return true;
  }

 private:
  using Side = double EdgeBox::*;
  Point2 origin_;
  Point2 d_;
  double margin_;
  // The corners: c_low gives the least c, c_high the largest, r_high the largest r.
  Side c_low_x_, c_low_y_, c_high_x_, c_high_y_, r_high_x_, r_high_y_;
};

/// Charges the first control-point pass (n + 1 units) of every edge in [from, until) outside
/// `group`, as testing them one by one would; false, with the budget spent up to and
/// including the edge that passed the cap, when the cap is reached.
bool charge_skipped(const Arrangement& arrangement, const SideWindingIndex& index,
                    std::size_t group, std::size_t from, std::size_t until, core::WorkBudget& budget) {
  if (from >= until) return true;
  std::int64_t cost = index.pass_cost_before[until] - index.pass_cost_before[from];
  for (const std::size_t e : arrangement.group_edges(group)) {
    if (e >= from && e < until) cost -= arrangement.edges[e].piece.degree() + 1;
  }
  if (cost <= budget.remaining()) {
    budget.charge(cost);
    return true;
  }
  for (std::size_t e = from; e < until; ++e) {
    if (arrangement.edges[e].group == group) continue;
    if (!budget.spend(arrangement.edges[e].piece.degree() + 1)) return false;
  }
  return true;
}

/// The first nonzero derivative of the curve at t (its tangent direction there), given the
/// first derivative there (derivatives_at(curve, t, 1)[0]: the first of the derivatives of any
/// order derivatives_at lists, the same double either way); the higher ones are computed only
/// when it is zero.
Point2 tangent_at(const core::Curve& curve, double t, Point2 first) {
  if (first.x != 0.0 || first.y != 0.0) return first;
  const std::vector<Point2> d = core::derivatives_at(curve, t, curve.degree());
  for (const Point2 v : d) {
    if (v.x != 0.0 || v.y != 0.0) return v;
  }
  return curve.back() - curve.front();
}

/// A parameter of a curve and the curve's first derivative there.
struct ParameterAndSpeed {
  double t = 0.5;
  Point2 first;
};

/// The parameter of `curve` the rays start from: its middle, or else the first of a few
/// other parameters where the curve moves at a speed that is not small against its control
/// polygon (|B'(t)| > 2^-20 n max |P_{i+1} - P_i|). At a cusp (B' = 0) the curve has no two
/// sides: both of its branches leave the point the same way, so every ray from it starts in
/// the one face around the cusp's tip, and the left and right windings read there would be
/// that face's twice over. Near one, the tangent's direction is lost to rounding. A
/// polynomial curve's speed is small near at most a few parameters, so one of these is
/// clear of them unless the curve is a point.
/// Returned with the first derivative there, which the caller needs too.
ParameterAndSpeed ray_origin_parameter(const core::Curve& curve) {
  const int n = curve.degree();
  const auto pts = curve.points();
  double leg = 0.0;
  for (int i = 0; i < n; ++i) {
    leg = std::max(
        leg, core::length(pts[static_cast<std::size_t>(i) + 1] - pts[static_cast<std::size_t>(i)]));
  }
  const double slow = 0x1p-20 * n * leg;
  ParameterAndSpeed middle;
  for (const double t : {0.5, 0.3183, 0.6817, 0.1887, 0.8113}) {
    const Point2 first = core::derivatives_at(curve, t, 1)[0];
    if (t == 0.5) middle.first = first;
    if (core::length(first) > slow) return {t, first};
  }
  return middle;
}

}  // namespace

SideWindingIndex::SideWindingIndex(const Arrangement& arrangement)
    : prune(arrangement.scale <= kPruneScaleLimit) {
  // Sized once and written in place (the loops keep their running values in registers).
  const std::size_t edge_count = arrangement.edges.size();
  boxes.resize(edge_count);
  pass_cost_before.resize(edge_count + 1);
  EdgeBox* const box = boxes.data();
  std::int64_t* const cost = pass_cost_before.data();
  std::int64_t running = 0;
  cost[0] = 0;
  for (std::size_t e = 0; e < edge_count; ++e) {
    const core::Curve& piece = arrangement.edges[e].piece;
    box[e] = control_point_box(piece);
    running += piece.degree() + 1;
    cost[e + 1] = running;
  }
  block_boxes.resize((edge_count + kBlockEdges - 1) / kBlockEdges);
  for (std::size_t b = 0; b < block_boxes.size(); ++b) {
    const std::size_t first = b * kBlockEdges;
    EdgeBox block = box[first];
    for (std::size_t e = first + 1; e < std::min(edge_count, first + kBlockEdges); ++e) {
      block.x_lo = std::min(block.x_lo, box[e].x_lo);
      block.x_hi = std::max(block.x_hi, box[e].x_hi);
      block.y_lo = std::min(block.y_lo, box[e].y_lo);
      block.y_hi = std::max(block.y_hi, box[e].y_hi);
    }
    block_boxes[b] = block;
  }
}

SideWindingResult side_windings(const Arrangement& arrangement, const SideWindingIndex& index,
                                std::size_t group, core::WorkBudget& budget) {
  SideWindingResult result;
  const std::vector<ArrangementEdge>& edges = arrangement.edges;
  std::vector<std::size_t> candidates;
  // Room for the edges a ray usually keeps, so that collecting them rarely grows the list.
  candidates.reserve(std::min<std::size_t>(edges.size(), 64));
  const CoincidentGroup& g = arrangement.groups[group];
  const ArrangementEdge& rep = arrangement.edges[g.representative];
  const ParameterAndSpeed origin = ray_origin_parameter(arrangement.exact(rep));
  const core::Split<Point2> halves = core::subdivide(arrangement.exact(rep), origin.t);
  const Point2 middle = halves.left.back();
  const Point2 tangent = tangent_at(arrangement.exact(rep), origin.t, origin.first);
  const double norm = core::length(tangent);
  if (!(norm > 0.0)) {
    result.status = SideWindingStatus::unclear;
    return result;
  }
  const Point2 normal{-tangent.y / norm, tangent.x / norm};
  for (const double turn : kTurns) {
    const double c = std::cos(turn), s = std::sin(turn);
    const Ray ray{middle, {c * normal.x - s * normal.y, s * normal.x + c * normal.y},
                  kRayClearanceRel * arrangement.scale};
    std::array<int, 2> left{0, 0};
    bool clear = true;
    candidates.clear();
    index.collect(MayMeet(ray), candidates);
    // Edges before `next` not yet charged: the skipped ones are charged what their first
    // control-point pass costs, so the work (and where the cap is met) stays that of
    // testing every edge in order.
    std::size_t next = 0;
    for (std::size_t k = 0; k <= candidates.size() && clear; ++k) {
      const std::size_t until = k < candidates.size() ? candidates[k] : edges.size();
      if (!charge_skipped(arrangement, index, group, next, until, budget)) {
        result.status = SideWindingStatus::work_cap_reached;
        return result;
      }
      if (k == candidates.size()) break;
      next = until + 1;
      const ArrangementEdge& edge = edges[until];
      if (edge.group == group) continue;
      Count count;
      count_crossings(edge.piece, ray, OriginEnd::none, true, 0, count, budget);
      if (budget.exhausted()) {
        result.status = SideWindingStatus::work_cap_reached;
        return result;
      }
      clear = count.clear;
      if (count.at_origin) {
        result.status = SideWindingStatus::unclear;
        return result;
      }
      left[static_cast<std::size_t>(edge.source)] += count.crossings;
    }
    if (!clear) continue;
    Count own;
    count_crossings(halves.left, ray, OriginEnd::back, false, 0, own, budget);
    count_crossings(halves.right, ray, OriginEnd::front, false, 0, own, budget);
    if (budget.exhausted()) {
      result.status = SideWindingStatus::work_cap_reached;
      return result;
    }
    if (!own.clear) continue;
    for (std::size_t k = 0; k < 2; ++k) {
      result.windings.left[k] = left[k] + g.multiplicity[k] * own.crossings;
      result.windings.right[k] = result.windings.left[k] - g.multiplicity[k];
    }
    return result;
  }
  result.status = SideWindingStatus::unclear;
  return result;
}

}  // namespace bezier::region
