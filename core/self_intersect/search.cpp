#include "core/self_intersect/search.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <optional>

#include "core/self_intersect/tuning.hpp"
#include "core/self_intersect/work_cost.hpp"

namespace bezier::core {

namespace {

using self_intersect_tuning::kConeMargin;
using self_intersect_tuning::kRootSlack;

enum class BoxKind : std::uint8_t {
  diagonal,  ///< I = J
  adjacent,  ///< I = [a, b], J = [b, d]
  seam,      ///< closed curve, I = [0, b], J = [c, 1]: neighbours through P_0 = P_n
  apart,     ///< b < c
};

/// A box of the parameter square: u in I = [a, b], v in J = [c, d]. The control points of
/// the two pieces live in the arena: I at `offset`, J right after it.
struct Box {
  double a, b, c, d;
  std::size_t offset;
  BoxKind kind;
  int depth;
};

/// The directions of a set of vectors, when they fit in an open half-plane: the cone from
/// `cw` counter-clockwise to `ccw`, of angle < pi.
struct Cone {
  Point2 cw;
  Point2 ccw;
};

/// The smallest cone holding every non-zero vector, or nullopt when no open half-plane
/// holds them all (or all are zero). Zero vectors (repeated control points) are skipped:
/// B' = Σ h_i b_i(t) with b_i(t) > 0 inside the interval still points into the cone.
/// Invariant: the angle from cw to ccw is in [0, pi). A new vector w is inside when it is
/// counter-clockwise of cw and clockwise of ccw (both crosses >= 0, not both zero, or both
/// zero and w along cw); otherwise it extends the cone on the side that keeps it < pi, and
/// at most one side can.
class ConeBuilder {
 public:
  void add(Point2 w) {
    if (failed_ || (w.x == 0.0 && w.y == 0.0)) return;
    if (!cone_) {
      cone_ = Cone{w, w};
      return;
    }
    const double c1 = cross(cone_->cw, w);
    const double c2 = cross(w, cone_->ccw);
    if (c1 >= 0.0 && c2 >= 0.0 && (c1 > 0.0 || c2 > 0.0 || dot(w, cone_->cw) > 0.0)) return;
    if (c2 > 0.0) {
      cone_->cw = w;  // the angle from w to ccw is in (0, pi) and spans the old cone
    } else if (c1 > 0.0) {
      cone_->ccw = w;
    } else {
      failed_ = true;
    }
  }
  [[nodiscard]] std::optional<Cone> cone() const {
    if (failed_) return std::nullopt;
    return cone_;
  }

 private:
  std::optional<Cone> cone_;
  bool failed_ = false;
};

void add_hodograph(ConeBuilder& builder, const Point2* p, std::size_t m) {
  for (std::size_t i = 0; i + 1 < m; ++i) builder.add(p[i + 1] - p[i]);
}

/// Whether two cones, taken as sets of lines (directions up to sign), are disjoint with
/// a margin: then no direction is a chord direction of both pieces.
bool lines_disjoint(const Cone& x, const Cone& y) {
  const auto mid_and_half = [](const Cone& k) {
    const double start = std::atan2(k.cw.y, k.cw.x);
    // In [0, pi) by the invariant; fabs keeps a rounded-negative cross of a thin cone thin.
    const double span = std::atan2(std::fabs(cross(k.cw, k.ccw)), dot(k.cw, k.ccw));
    return std::pair{start + 0.5 * span, 0.5 * span};
  };
  const auto [mx, hx] = mid_and_half(x);
  const auto [my, hy] = mid_and_half(y);
  return std::fabs(std::remainder(mx - my, std::numbers::pi)) > hx + hy + kConeMargin;
}

/// Whether the convex hulls of the two control polygons are apart by more than `margin`
/// along one of: the chord of either piece, the chords' normals, x and y.
bool separated(const Point2* p, const Point2* q, std::size_t m, double margin) {
  const Point2 cp = p[m - 1] - p[0];
  const Point2 cq = q[m - 1] - q[0];
  const Point2 axes[] = {cp, {-cp.y, cp.x}, cq, {-cq.y, cq.x}, {1.0, 0.0}, {0.0, 1.0}};
  for (const Point2 axis : axes) {
    if (axis.x == 0.0 && axis.y == 0.0) continue;
    double p_lo = dot(p[0], axis), p_hi = p_lo, q_lo = dot(q[0], axis), q_hi = q_lo;
    for (std::size_t i = 1; i < m; ++i) {
      const double sp = dot(p[i], axis), sq = dot(q[i], axis);
      p_lo = std::min(p_lo, sp);
      p_hi = std::max(p_hi, sp);
      q_lo = std::min(q_lo, sq);
      q_hi = std::max(q_hi, sq);
    }
    const double gap = margin * norm(axis);
    if (p_hi + gap < q_lo || q_hi + gap < p_lo) return true;
  }
  return false;
}

/// Largest distance of a control point from the piece's chord (from P_0 when the chord is
/// zero): below the distance tolerance the piece is a segment as far as we can tell.
double flatness(const Point2* p, std::size_t m) {
  const Point2 chord = p[m - 1] - p[0];
  const double len = norm(chord);
  double worst = 0.0;
  for (std::size_t i = 1; i + 1 < m; ++i) {
    const Point2 r = p[i] - p[0];
    worst = std::max(worst, len > 0.0 ? std::fabs(cross(r, chord)) / len : norm(r));
  }
  return len > 0.0 ? worst : std::max(worst, norm(p[m - 1] - p[0]));
}

/// Extent of the control points of one or two pieces: max over x and y of (max - min).
double extent(const Point2* p, std::size_t count) {
  double x_lo = p[0].x, x_hi = p[0].x, y_lo = p[0].y, y_hi = p[0].y;
  for (std::size_t i = 1; i < count; ++i) {
    x_lo = std::min(x_lo, p[i].x);
    x_hi = std::max(x_hi, p[i].x);
    y_lo = std::min(y_lo, p[i].y);
    y_hi = std::max(y_hi, p[i].y);
  }
  return std::max(x_hi - x_lo, y_hi - y_lo);
}

/// de Casteljau at t = 1/2, in place: `right` receives a copy of src and ends as the right
/// half (entry n - k of round k is never touched again), `left` collects the first entries.
/// Halving is exact in binary floating point except for one rounding per sum.
void split_half(const Point2* src, Point2* left, Point2* right, std::size_t m) {
  std::copy(src, src + m, right);
  left[0] = right[0];
  for (std::size_t k = 1; k < m; ++k) {
    for (std::size_t i = 0; i + k < m; ++i) right[i] = 0.5 * right[i] + 0.5 * right[i + 1];
    left[k] = right[0];
  }
}

class Search {
 public:
  Search(std::span<const Point2> points, const SelfIntersectionSearchSettings& settings,
         WorkBudget& budget)
      : points_(points),
        m_(points.size()),
        settings_(settings),
        budget_(budget),
        box_cost_(self_intersection_box_cost(static_cast<int>(points.size()) - 1)),
        newton_cost_(self_intersection_newton_cost(static_cast<int>(points.size()) - 1)),
        scratch_(4 * points.size()) {
    // Depth-first, the stack holds about three boxes per level: room for a typical search
    // without regrowing.
    constexpr std::size_t kTypicalBoxes = 64;
    stack_.reserve(kTypicalBoxes);
    arena_.reserve(kTypicalBoxes * 2 * m_);
  }

  SelfIntersectionSearchOutcome run() {
    push({0.0, 1.0, 0.0, 1.0, 0, BoxKind::diagonal, 0}, points_.data(), points_.data());
    while (!stack_.empty()) {
      if (!budget_.reserve(box_cost_)) break;
      charge(box_cost_);
      const Box box = stack_.back();
      stack_.pop_back();
      process(box);
    }
    return std::move(out_);
  }

 private:
  void charge(std::int64_t units) {
    budget_.charge(units);
    out_.stats.work += units;
  }

  /// Appends a box with copies of its pieces; boxes are processed last in, first out, so
  /// the arena is a stack too and a popped box's pieces are always on top.
  void push(Box box, const Point2* piece_i, const Point2* piece_j) {
    box.offset = arena_.size();
    arena_.insert(arena_.end(), piece_i, piece_i + m_);
    arena_.insert(arena_.end(), piece_j, piece_j + m_);
    stack_.push_back(box);
  }

  void process(const Box& box) {
    out_.stats.max_depth = std::max(out_.stats.max_depth, box.depth);
    // Work on copies: children are pushed where this box's pieces were.
    Point2* const i_half = scratch_.data();           // I0, I1
    Point2* const j_half = scratch_.data() + 2 * m_;  // J0, J1
    const Point2* const pi = arena_.data() + box.offset;
    const Point2* const pj = pi + m_;
    if (box.kind == BoxKind::apart) {
      if (!resolve_apart(box, pi, pj)) {
        split_half(pi, i_half, i_half + m_, m_);
        split_half(pj, j_half, j_half + m_, m_);
        arena_.resize(box.offset);
        push_children(box, i_half, j_half);
      } else {
        arena_.resize(box.offset);
      }
      return;
    }
    // Diagonal, adjacent and seam boxes: no pair inside if the piece (or the union of the
    // two neighbouring pieces) is strictly monotone along some direction.
    ConeBuilder builder;
    add_hodograph(builder, pi, m_);
    if (box.kind != BoxKind::diagonal) add_hodograph(builder, pj, m_);
    const bool monotone = builder.cone().has_value();
    const bool tiny = box.depth >= settings_.max_depth ||
                      extent(pi, box.kind == BoxKind::diagonal ? m_ : 2 * m_) <= settings_.dist_tol;
    if (!monotone && !tiny) {
      split_half(pi, i_half, i_half + m_, m_);
      if (box.kind != BoxKind::diagonal) split_half(pj, j_half, j_half + m_, m_);
      arena_.resize(box.offset);
      push_children(box, i_half, box.kind == BoxKind::diagonal ? i_half : j_half);
      return;
    }
    // A neighbourhood of the diagonal (or of the seam) that shrank below the tolerance
    // without becoming monotone holds a cusp, or a loop too small to tell from one.
    if (!monotone) ++out_.stats.cusp_regions;
    arena_.resize(box.offset);
  }

  /// Apart box: true when it is finished (discarded, its one pair found, or recorded as a
  /// contact candidate), false when it must be split.
  bool resolve_apart(const Box& box, const Point2* pi, const Point2* pj) {
    if (separated(pi, pj, m_, settings_.dist_tol)) return true;
    ConeBuilder cone_i, cone_j;
    add_hodograph(cone_i, pi, m_);
    add_hodograph(cone_j, pj, m_);
    const auto ki = cone_i.cone();
    const auto kj = cone_j.cone();
    if (ki && kj && lines_disjoint(*ki, *kj)) {
      // At most one pair in the box: if Newton lands inside, that is it.
      if (try_newton(box, pi, pj)) return true;
    }
    const bool flat =
        flatness(pi, m_) <= settings_.dist_tol && flatness(pj, m_) <= settings_.dist_tol;
    if (flat || box.depth >= settings_.max_depth) {
      out_.contact_boxes.push_back({{box.a, box.b}, {box.c, box.d}});
      ++out_.stats.contact_candidates;
      return true;
    }
    return false;
  }

  bool try_newton(const Box& box, const Point2* pi, const Point2* pj) {
    // Start where the chords cross, mapped linearly to the parameters; else the centre.
    const Point2 r = pi[m_ - 1] - pi[0], s = pj[m_ - 1] - pj[0], w = pj[0] - pi[0];
    const double denom = cross(r, s);
    double alpha = cross(w, s) / denom, beta = cross(w, r) / denom;
    if (!(0.0 <= alpha && alpha <= 1.0 && 0.0 <= beta && beta <= 1.0)) alpha = beta = 0.5;
    const double u0 = box.a + alpha * (box.b - box.a), v0 = box.c + beta * (box.d - box.c);
    // Iterates may wander one box width beyond the box; the root must be inside it.
    const double wu = box.b - box.a, wv = box.d - box.c;
    const ParameterBox region{{box.a - wu, box.b + wu}, {box.c - wv, box.d + wv}};
    const PairRefinement root = refine_double_point(points_, u0, v0, region, settings_.rounding);
    ++out_.stats.newton_runs;
    out_.stats.newton_iterations += root.iterations;
    charge(root.iterations * newton_cost_);
    if (!root.converged || root.u < box.a - kRootSlack || root.u > box.b + kRootSlack ||
        root.v < box.c - kRootSlack || root.v > box.d + kRootSlack) {
      return false;
    }
    // The box holds at most one pair and Newton found it, unless rounding could move it
    // onto the diagonal: then it is a cusp seen through rounding errors, or two branches
    // meeting at so small an angle that the pair is a tangential contact in all but
    // rounding; on a closed curve, likewise onto the seam's trivial pair (0, 1). Either way
    // the box is split on until its pieces are flat, and the contact stage decides.
    if (!is_resolved_double_point(points_, root.u, root.v, settings_.rounding, settings_.closed)) {
      return false;
    }
    out_.crossings.push_back(root);
    return true;
  }

  void push_children(const Box& box, const Point2* i_half, const Point2* j_half) {
    const Point2* i0 = i_half;
    const Point2* i1 = i_half + m_;
    const Point2* j0 = j_half;
    const Point2* j1 = j_half + m_;
    const double mi = 0.5 * (box.a + box.b), mj = 0.5 * (box.c + box.d);
    const int depth = box.depth + 1;
    const auto kind_of = [&](double a, double d, BoxKind otherwise) {
      return settings_.closed && a == 0.0 && d == 1.0 ? BoxKind::seam : otherwise;
    };
    switch (box.kind) {
      case BoxKind::diagonal:
        push({box.a, mi, mi, box.b, 0, BoxKind::adjacent, depth}, i0, i1);
        push({box.a, mi, box.a, mi, 0, BoxKind::diagonal, depth}, i0, i0);
        push({mi, box.b, mi, box.b, 0, BoxKind::diagonal, depth}, i1, i1);
        return;
      case BoxKind::adjacent:
        push({box.a, mi, box.c, mj, 0, BoxKind::apart, depth}, i0, j0);
        push({mi, box.b, mj, box.d, 0, BoxKind::apart, depth}, i1, j1);
        push({box.a, mi, mj, box.d, 0, kind_of(box.a, box.d, BoxKind::apart), depth}, i0, j1);
        push({mi, box.b, box.c, mj, 0, BoxKind::adjacent, depth}, i1, j0);
        return;
      case BoxKind::seam:
        push({box.a, mi, box.c, mj, 0, BoxKind::apart, depth}, i0, j0);
        push({mi, box.b, mj, box.d, 0, BoxKind::apart, depth}, i1, j1);
        push({mi, box.b, box.c, mj, 0, BoxKind::apart, depth}, i1, j0);
        push({box.a, mi, mj, box.d, 0, BoxKind::seam, depth}, i0, j1);
        return;
      case BoxKind::apart:
        push({box.a, mi, box.c, mj, 0, BoxKind::apart, depth}, i0, j0);
        push({box.a, mi, mj, box.d, 0, BoxKind::apart, depth}, i0, j1);
        push({mi, box.b, box.c, mj, 0, BoxKind::apart, depth}, i1, j0);
        push({mi, box.b, mj, box.d, 0, BoxKind::apart, depth}, i1, j1);
        return;
    }
  }

  std::span<const Point2> points_;
  std::size_t m_;
  SelfIntersectionSearchSettings settings_;
  WorkBudget& budget_;
  std::int64_t box_cost_;
  std::int64_t newton_cost_;
  std::vector<Point2> arena_;
  std::vector<Box> stack_;
  std::vector<Point2> scratch_;
  SelfIntersectionSearchOutcome out_;
};

}  // namespace

SelfIntersectionSearchOutcome search_self_intersections(
    std::span<const Point2> points, const SelfIntersectionSearchSettings& settings,
    WorkBudget& budget) {
  assert(points.size() >= 2);
  return Search(points, settings, budget).run();
}

}  // namespace bezier::core
