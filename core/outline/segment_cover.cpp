#include "core/outline/segment_cover.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/curve/evaluate.hpp"
#include "core/curve/polar.hpp"
#include "core/measure/bernstein_product.hpp"
#include "core/measure/frame.hpp"
#include "core/outline/offset.hpp"
#include "core/outline/offset_cusps.hpp"
#include "core/outline/stroke_shapes.hpp"
#include "core/outline/tangent_limits.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

constexpr int kMostHalvings = 64;

std::vector<Point2> hodograph(std::span<const Point2> p) {
  const double n = static_cast<double>(p.size() - 1);
  std::vector<Point2> h;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) h.push_back(n * (p[i + 1] - p[i]));
  return h;
}

/// An upper bound of the radius of curvature on the curve q where it turns to `side` (+1
/// left, -1 right) throughout: M1^3 / min(side cross(B', B'')), the minimum over the
/// Bernstein coefficients of cross(B', B'') (degree 2n - 3, products of the first and second
/// hodographs' control points). Infinity when a coefficient is not of the side's sign.
double radius_of_curvature_bound(std::span<const Point2> q, double side) {
  const std::vector<Point2> h1 = hodograph(q);
  if (h1.size() < 2) return std::numeric_limits<double>::infinity();
  const std::vector<Point2> h2 = hodograph(h1);
  const int m = static_cast<int>(h1.size()) - 1, k = static_cast<int>(h2.size()) - 1;
  std::vector<double> c(static_cast<std::size_t>(m + k + 1), 0.0);
  for (int i = 0; i <= m; ++i) {
    for (int j = 0; j <= k; ++j) {
      const double weight = core::choose(m, i) * core::choose(k, j) / core::choose(m + k, i + j);
      c[static_cast<std::size_t>(i + j)] +=
          weight * core::cross(h1[static_cast<std::size_t>(i)], h2[static_cast<std::size_t>(j)]);
    }
  }
  double least = std::numeric_limits<double>::infinity();
  for (const double v : c) least = std::min(least, side * v);
  // Rounding of the coefficients: each is a sum of (m + 1)(k + 1) products, within
  // 4 (m + k + 2) u of the sum of their magnitudes.
  double magnitude = 0.0;
  for (const Point2 a : h1)
    for (const Point2 b : h2) magnitude = std::max(magnitude, core::length(a) * core::length(b));
  least -= 4.0 * (m + k + 2) * std::numeric_limits<double>::epsilon() * magnitude;
  if (!(least > 0.0)) return std::numeric_limits<double>::infinity();
  double speed = 0.0;
  for (const Point2 p : h1) speed = std::max(speed, core::length(p));
  return speed * speed * speed / least;
}

/// The disks of radius R that cover the tight side `side` of the piece q (segment_cover.hpp).
/// A disk already drawn (about a zero of B', or for an earlier part) is reused when it holds
/// the part by the same test, so that parts crowding towards a zero of B' add no nearly
/// coincident circles; `centres` are the centres of the segment's disks of radius R so far.
void cover_tight_side(const core::Curve& q, double side, const CoverSizes& sizes,
                      OutlineSink& sink, std::vector<Point2>& centres) {
  struct Part {
    double a, b;
    int depth;
  };
  const auto n = static_cast<std::int64_t>(q.degree());
  const double margin = 64.0 * std::numeric_limits<double>::epsilon() *
                        (core::scale(q) + sizes.reach);
  std::vector<Part> stack{{0.0, 1.0, 0}};
  while (!stack.empty()) {
    const Part part = stack.back();
    stack.pop_back();
    if (!sink.charge(16 * (n + 1) * (n + 1))) return;
    const core::Curve piece = core::portion(q, part.a, part.b);
    const Point2 centre = core::evaluate(piece, 0.5);
    const double depth =
        std::min(radius_of_curvature_bound(piece.points(), side), sizes.radius) + margin;
    auto holds = [&](Point2 c) {
      double spread = 0.0;
      for (const Point2 p : piece.points()) spread = std::max(spread, core::length(p - c));
      return depth + spread < sizes.reach;
    };
    if (!sink.charge(static_cast<std::int64_t>(centres.size()) * (n + 1))) return;
    if (std::any_of(centres.begin(), centres.end(), holds)) continue;
    if (holds(centre)) {
      if (!sink.charge(16 * static_cast<std::int64_t>(sizes.circle_pieces))) return;
      sink.add(circle(centre, sizes.disk_radius, sizes.circle_pieces));
      centres.push_back(centre);
      continue;
    }
    if (part.depth >= kMostHalvings) {
      sink.fail_work();
      return;
    }
    const double mid = 0.5 * (part.a + part.b);
    stack.push_back({mid, part.b, part.depth + 1});
    stack.push_back({part.a, mid, part.depth + 1});
  }
}

/// The piece q itself as one side's edge when it is at most a cubic, else its fit at distance 0.
bool curve_edge(const core::Curve& q, const CoverSizes& sizes, OutlineSink& sink,
                std::vector<core::Curve>& edge) {
  if (q.degree() <= 3) {
    edge.push_back(q);
    return true;
  }
  const CurveOffset fit = offset_curve(q, 0.0, sizes.fit_tolerance, sink.work_left());
  if (!sink.charge(fit.work) || fit.status != OffsetStatus::ok) {
    sink.fail_work();
    return false;
  }
  for (const OffsetCubic& c : fit.cubics) {
    edge.push_back(core::Curve({c.points[0], c.points[1], c.points[2], c.points[3]}));
  }
  return true;
}

/// The cubics of `offset` (a whole segment's parallel curve) for the parameters [a, b]: those
/// inside it, and the parts of those that straddle a or b (the cubic's sub-curve between the
/// parameters that the fit's linear correspondence u = (t - t0) / (t1 - t0) assigns to a and b,
/// which keeps the cubic's bound for that part).
void offset_edge(const CurveOffset& offset, double a, double b, std::vector<core::Curve>& edge) {
  for (const OffsetCubic& c : offset.cubics) {
    const double lo = std::max(a, c.t0), hi = std::min(b, c.t1);
    if (!(hi > lo)) continue;
    core::Curve cubic({c.points[0], c.points[1], c.points[2], c.points[3]});
    if (lo > c.t0 || hi < c.t1) {
      cubic = core::portion(cubic, (lo - c.t0) / (c.t1 - c.t0), (hi - c.t0) / (c.t1 - c.t0));
    }
    edge.push_back(std::move(cubic));
  }
}

/// Extends an open chain by a line to `point` when its end is farther than `snap` from it.
void pass_through(Contour& chain, Point2 point, double snap) {
  if (chain.empty() || core::length(chain.back().back() - point) <= snap) return;
  chain.push_back(core::Curve({chain.back().back(), point}));
}

}  // namespace

void cover_segment(const core::Curve& segment, const CoverSizes& sizes, OutlineSink& sink) {
  const auto n = static_cast<std::int64_t>(segment.degree());
  if (!sink.charge(3 * 64 * n * n * n)) return;
  std::vector<double> cuts{0.0, 1.0};
  for (const double t : offset_cusps(segment, sizes.reach)) cuts.push_back(t);
  for (const double t : offset_cusps(segment, -sizes.reach)) cuts.push_back(t);
  const std::vector<double> stationary = stationary_points(segment);
  for (const double t : stationary) cuts.push_back(t);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

  std::vector<Point2> centres;
  for (const double t : stationary) {
    if (!sink.charge(16 * static_cast<std::int64_t>(sizes.circle_pieces))) return;
    centres.push_back(core::evaluate(segment, t));
    if (!sink.add(circle(centres.back(), sizes.disk_radius, sizes.circle_pieces))) return;
  }

  // The parallel curves at ±R of the whole segment, fitted once (offset.hpp cuts them at the
  // same cusps and zeros of B' as above), each side's cubics taken by the pieces where that
  // side is loose.
  std::optional<CurveOffset> parallel[2];
  auto loose_edge = [&](int side, double a, double b, std::vector<core::Curve>& edge) {
    if (!parallel[side]) {
      parallel[side] = offset_curve(segment, side == 0 ? sizes.reach : -sizes.reach,
                                    sizes.fit_tolerance, sink.work_left());
      if (!sink.charge(parallel[side]->work) || parallel[side]->status != OffsetStatus::ok) {
        sink.fail_work();
        return false;
      }
    }
    offset_edge(*parallel[side], a, b, edge);
    return true;
  };

  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    if (!(cuts[k + 1] > cuts[k])) continue;
    const core::Curve q = core::portion(segment, cuts[k], cuts[k + 1]);
    const std::optional<core::Frame<Point2>> middle = core::frame(q, 0.5);
    const double kappa = middle ? middle->curvature : 0.0;
    const bool tight_left = kappa * sizes.reach > 1.0;
    const bool tight_right = -kappa * sizes.reach > 1.0;

    std::vector<core::Curve> left, right;
    if (!(tight_left ? curve_edge(q, sizes, sink, left)
                     : loose_edge(0, cuts[k], cuts[k + 1], left))) {
      return;
    }
    if (!(tight_right ? curve_edge(q, sizes, sink, right)
                      : loose_edge(1, cuts[k], cuts[k + 1], right))) {
      return;
    }
    // Counter-clockwise (y up): the right edge forward, the left edge backward, joined by the
    // normal segments at the piece's ends. At a cut inside the segment each normal segment
    // passes through B there (q's end point, the same double for both pieces at the cut,
    // core::portion), so that the neighbouring piece's normal segment at that cut, or its half
    // from B to one side where that piece's side is tight (its edge is the curve itself), is
    // the same line run backwards, an exact overlap: unsplit, the two would be distinct lines
    // a few ulps apart along their common length, which the boolean simplify cannot tell
    // apart. At the segment's ends the neighbour is a disk or a join's polygon, and the
    // normal segment stays one line.
    Contour chain;
    for (core::Curve& c : right) append_to_chain(chain, std::move(c), sizes.snap);
    if (cuts[k + 1] < 1.0) pass_through(chain, q.back(), sizes.snap);
    for (auto it = left.rbegin(); it != left.rend(); ++it) {
      append_to_chain(chain, core::reversed(*it), sizes.snap);
    }
    if (cuts[k] > 0.0) pass_through(chain, q.front(), sizes.snap);
    close_chain(chain, sizes.snap);
    if (!sink.add(std::move(chain))) return;

    if (tight_left) cover_tight_side(q, 1.0, sizes, sink, centres);
    if (tight_right) cover_tight_side(q, -1.0, sizes, sink, centres);
    if (!sink.ok()) return;
  }
}

}  // namespace bezier::outline
