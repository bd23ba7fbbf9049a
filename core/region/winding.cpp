#include "core/region/winding.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "core/intersect/work_cost.hpp"
#include "core/numeric/double_double.hpp"
#include "core/numeric/power_of_two.hpp"
#include "core/numeric/small_array.hpp"
#include "core/numeric/unit_roundoff.hpp"
#include "core/region/tuning.hpp"

namespace bezier::region {

namespace {

using core::Point2;
namespace dd = core::dd;

constexpr double u = core::kUnitRoundoff;
/// The band's half-width as a multiple of the scale: 8 u = 2^-50.
constexpr double kBandFactor = 0x1p-50;
/// An absolute slack for underflow: scaling by a power of two may round a coordinate far
/// below the scale (at most 2^-1075 in the scaled units), and products of tiny values may
/// be subnormal. It is far below every band (at least 2^-50 in scaled units).
constexpr double kTiny = 0x1p-1000;
/// Targets farther than this (scaled units, where the region lies within |coordinate| < 2)
/// are outside the region's box by far more than the band: winding 0.
constexpr double kFar = 0x1p500;
/// A piece's rounding error per level of subdivision and per unit of degree, in scaled
/// units: a midpoint (a + b) / 2 of double-doubles of magnitude below 2 is within
/// 3 u^2 |a + b| <= 12 u^2 < 2^-102 (dd::add), and a point of the triangle at level j takes
/// j <= n of them; twice that covers the roundings of the tests' own subtractions.
constexpr double kLevelError = 0x1p-101;

struct DdPoint {
  dd::Real x, y;
};

/// Whether the exact value of `y` (a normalised double-double) is <= `target_y`: the
/// half-open rule's "below or on the ray".
bool at_or_below(const dd::Real& y, double target_y) {
  return y.hi < target_y || (y.hi == target_y && y.lo <= 0.0);
}

/// The contribution of a chord from `a` to `b`, lying wholly right of the target, to the
/// crossings of the ray: +1 upwards, -1 downwards, 0 when both ends are on one side.
int chord_crossing(bool a_below, bool b_below) {
  if (a_below && !b_below) return 1;
  if (!a_below && b_below) return -1;
  return 0;
}

/// c, a difference of exact values rounded once, certainly exceeds m >= 0.
bool certainly_above(double c, double m) {
  return c > m * (1.0 + 4.0 * u) + kTiny;
}

/// de Casteljau's subdivision of `parent` at t = 1/2 in double-double: `left` takes the
/// first half, `right` the second; left's last point and right's first are the same value.
void halve(std::span<const DdPoint> parent, std::span<DdPoint> left, std::span<DdPoint> right,
           std::span<DdPoint> row) {
  const std::size_t n = parent.size() - 1;
  std::copy(parent.begin(), parent.end(), row.begin());
  left[0] = row[0];
  right[n] = row[n];
  for (std::size_t level = 1; level <= n; ++level) {
    for (std::size_t i = 0; i + level <= n; ++i) {
      const dd::Real x = dd::add(row[i].x, row[i + 1].x);
      const dd::Real y = dd::add(row[i].y, row[i + 1].y);
      row[i] = {{x.hi * 0.5, x.lo * 0.5}, {y.hi * 0.5, y.lo * 0.5}};
    }
    left[level] = row[0];
    right[n - level] = row[n - level];
  }
  right[0] = left[n];
}

/// The point at `t` of the curve with control points `w` (doubles), and its derivative, by
/// de Casteljau's algorithm. Each of its n levels of (1 - t) a + t b, with 1 - t rounded,
/// rounds by at most about 3 u max|w_i| (the convex combinations never exceed max|w_i|).
struct PointAndTangent {
  Point2 point, tangent;
};

PointAndTangent casteljau(std::span<const Point2> w, double t) {
  core::SmallArray<Point2> row(std::span<const Point2>(w.data(), w.size()));
  const std::size_t n = w.size() - 1;
  const double r = 1.0 - t;
  Point2 a = row[0], b = row[0];
  for (std::size_t level = 1; level <= n; ++level) {
    if (level == n) {
      a = row[0];
      b = row[1];
    }
    for (std::size_t i = 0; i + level <= n; ++i) {
      row[i] = {r * row[i].x + t * row[i + 1].x, r * row[i].y + t * row[i + 1].y};
    }
  }
  const double d = static_cast<double>(n);
  return {row[0], {d * (b.x - a.x), d * (b.y - a.y)}};
}

/// Whether a point of the piece is certainly within the band of the target: the foot of
/// the target on the piece, estimated from `t` (the chord's nearest parameter) by a few
/// Gauss-Newton steps on (B(t) - target) · B'(t), then B(t) - target evaluated from the
/// differences `w` (each within `e_max` of the exact piece's) with its rounding bound.
bool foot_within_band(std::span<const Point2> w, double t, double w_max, double e_max,
                      double band) {
  constexpr int kSteps = 3;
  for (int step = 0; step < kSteps; ++step) {
    const PointAndTangent at = casteljau(w, t);
    const double speed2 = at.tangent.x * at.tangent.x + at.tangent.y * at.tangent.y;
    if (!(speed2 > 0.0)) break;
    const double next = t - (at.point.x * at.tangent.x + at.point.y * at.tangent.y) / speed2;
    t = std::clamp(next, 0.0, 1.0);
  }
  const Point2 p = casteljau(w, t).point;
  const double n = static_cast<double>(w.size() - 1);
  const double error = e_max + 4.0 * n * u * w_max + kTiny;
  return (std::hypot(p.x, p.y) * (1.0 + 4.0 * u) + 2.0 * error) * (1.0 + 4.0 * u) <= band;
}

enum class PieceOutcome { settled, boundary, subdivide };

struct PieceTest {
  PieceOutcome outcome = PieceOutcome::subdivide;
  int crossing = 0;
  bool far = false;
};

/// The smaller and the larger of two values that are not NaN, by a comparison: std::fmin and
/// std::fmax compile to library calls. The pieces' values are finite (control points below 2
/// in magnitude after scaling, targets within kFar), and where the two differ only in a zero's
/// sign the result is only compared or added to a positive bound, so the tests decide the same.
double smaller(double a, double b) { return b < a ? b : a; }
double larger(double a, double b) { return b > a ? b : a; }

/// The tests of winding.hpp on one piece `q` (control points, within `error` of the exact
/// piece in each coordinate) against `target` and the band; `far` when an ancestor showed
/// the piece beyond the band.
PieceTest test_piece(std::span<const DdPoint> q, Point2 target, double band, double error,
                     bool far) {
  const std::size_t n = q.size() - 1;
  // w_i = q_i - target rounded to doubles, e_i its error bound (with the piece's error).
  double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
  core::SmallArray<Point2> w(n + 1, core::SmallArray<Point2>::Uninitialized{});
  core::SmallArray<double> e(n + 1, core::SmallArray<double>::Uninitialized{});
  for (std::size_t i = 0; i <= n; ++i) {
    w[i] = {dd::to_double(dd::sub(q[i].x, dd::from(target.x))),
            dd::to_double(dd::sub(q[i].y, dd::from(target.y)))};
    e[i] = 4.0 * u * larger(std::fabs(w[i].x), std::fabs(w[i].y)) + error + kTiny;
    x_lo = smaller(x_lo, w[i].x - e[i]);
    x_hi = larger(x_hi, w[i].x + e[i]);
    y_lo = smaller(y_lo, w[i].y - e[i]);
    y_hi = larger(y_hi, w[i].y + e[i]);
  }
  PieceTest out;
  out.far = far;
  bool crossing_known = false;
  if (x_hi < 0.0 || y_lo > 0.0 || y_hi < 0.0) {
    crossing_known = true;
  } else if (x_lo > 0.0) {
    crossing_known = true;
    out.crossing = chord_crossing(at_or_below(q[0].y, target.y), at_or_below(q[n].y, target.y));
  }
  if (!out.far) {
    out.far = x_lo > band || x_hi < -band || y_lo > band || y_hi < -band;
  }
  // The chord's nearest point to the target, at t on the chord.
  const Point2 a = w[0], d = {w[n].x - w[0].x, w[n].y - w[0].y};
  const double dd_len = d.x * d.x + d.y * d.y;
  const double t = std::clamp(dd_len > 0.0 ? -(a.x * d.x + a.y * d.y) / dd_len : 0.0, 0.0, 1.0);
  if (!out.far) {
    // The direction from the target to the nearest point of the chord: every widened
    // control point beyond the band along it puts the whole hull beyond the band.
    const Point2 v = {a.x + t * d.x, a.y + t * d.y};
    if (v.x != 0.0 || v.y != 0.0) {
      const double norm = std::hypot(v.x, v.y) * (1.0 + 4.0 * u);
      const double needed = band * norm * (1.0 + 4.0 * u) + kTiny;
      bool beyond = true;
      for (std::size_t i = 0; i <= n && beyond; ++i) {
        const double projection = v.x * w[i].x + v.y * w[i].y;
        const double rounding = (std::fabs(v.x) + std::fabs(v.y)) * e[i] +
                                3.0 * u * (std::fabs(v.x * w[i].x) + std::fabs(v.y * w[i].y));
        beyond = projection - rounding * (1.0 + 4.0 * u) > needed;
      }
      out.far = beyond;
    }
  }
  if (!out.far) {
    // An end point of the piece is a point of the path: within the band, so is the target.
    for (const std::size_t i : {std::size_t{0}, n}) {
      const double reach = std::hypot(w[i].x, w[i].y) * (1.0 + 4.0 * u) + 2.0 * e[i];
      if (reach * (1.0 + 4.0 * u) <= band) {
        out.outcome = PieceOutcome::boundary;
        return out;
      }
    }
    // So is the piece's point nearest to the target, when found well enough: a target on
    // the path is shown so after a few levels, where the rounding of the piece's points
    // relative to the target has fallen below the band.
    double w_max = 0.0, e_max = 0.0;
    for (std::size_t i = 0; i <= n; ++i) {
      w_max = larger(w_max, larger(std::fabs(w[i].x), std::fabs(w[i].y)));
      e_max = larger(e_max, e[i]);
    }
    if (foot_within_band(std::span<const Point2>(w.data(), n + 1), t, w_max, e_max, band)) {
      out.outcome = PieceOutcome::boundary;
      return out;
    }
  }
  out.outcome = crossing_known && out.far ? PieceOutcome::settled : PieceOutcome::subdivide;
  return out;
}

struct SegmentOutcome {
  long crossings = 0;
  bool boundary = false;
};

/// The crossings of one segment (scaled control points) with the ray from `target`, by
/// subdivision (winding.hpp); stops where `budget` runs out (budget.exhausted()).
SegmentOutcome refine_segment(std::span<const Point2> points, Point2 target, double band,
                              core::WorkBudget& budget) {
  const std::size_t size = points.size();
  const int n = static_cast<int>(size) - 1;
  const std::int64_t piece_cost = core::kCompensatedFactor * (n + 1) * (n + 1);
  struct Piece {
    int depth;
    bool far;
  };
  std::vector<DdPoint> store;
  std::vector<Piece> pieces;
  std::vector<DdPoint> row(size), left(size);
  store.reserve(size * (region_tuning::kMaxDepth + 2));
  for (const Point2 p : points) store.push_back({dd::from(p.x), dd::from(p.y)});
  pieces.push_back({0, false});
  SegmentOutcome out;
  while (!pieces.empty()) {
    if (!budget.spend(piece_cost)) return out;
    const Piece piece = pieces.back();
    const std::size_t at = (pieces.size() - 1) * size;
    const std::span<const DdPoint> q(store.data() + at, size);
    const double error = piece.depth * (n * kLevelError + kTiny) + kTiny;
    const PieceTest test = test_piece(q, target, band, error, piece.far);
    if (test.outcome == PieceOutcome::boundary) {
      out.boundary = true;
      return out;
    }
    if (test.outcome == PieceOutcome::settled) {
      out.crossings += test.crossing;
      pieces.pop_back();
      store.resize(at);
      continue;
    }
    if (piece.depth >= region_tuning::kMaxDepth) {
      // Neither side of the band's edge could be shown (winding.hpp).
      out.boundary = true;
      return out;
    }
    // The piece is replaced by its second half, and its first half goes on top.
    store.resize(at + 2 * size);
    const std::span<DdPoint> parent(store.data() + at, size);
    const std::span<DdPoint> right(store.data() + at + size, size);
    halve(parent, left, right, row);
    std::copy(right.begin(), right.end(), parent.begin());
    std::copy(left.begin(), left.end(), right.begin());
    pieces.back() = {piece.depth + 1, test.far};
    pieces.push_back({piece.depth + 1, test.far});
  }
  return out;
}

}  // namespace

RegionWinding::RegionWinding(const Region& region) {
  double scale = 0.0;
  for (const core::Curve& segment : region.path.segments)
    scale = std::fmax(scale, core::scale(segment));
  exponent_ = scale > 0.0 ? core::exponent_of(scale) : 0;
  const core::PowerOfTwo factor(-exponent_);
  offsets_.reserve(region.path.segments.size() + 1);
  offsets_.push_back(0);
  for (const core::Curve& segment : region.path.segments) {
    Box box{INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (const Point2 p : segment.points()) {
      const Point2 scaled = factor.times(p);
      points_.push_back(scaled);
      box = {std::fmin(box.x_min, scaled.x), std::fmax(box.x_max, scaled.x),
             std::fmin(box.y_min, scaled.y), std::fmax(box.y_max, scaled.y)};
    }
    boxes_.push_back(box);
    offsets_.push_back(points_.size());
  }
  scale_ = factor.times(scale);
}

std::optional<Winding> RegionWinding::at(Point2 target, core::WorkBudget& budget) const {
  const std::size_t count = boxes_.size();
  if (!budget.spend(static_cast<std::int64_t>(count) * region_tuning::kBoxTestCost)) {
    return std::nullopt;
  }
  const Point2 q = core::PowerOfTwo(-exponent_).times(target);
  if (scale_ == 0.0) {
    // Every control point is the origin (or there is none): the path is that point.
    return Winding{count > 0 && q.x == 0.0 && q.y == 0.0, 0};
  }
  const double target_scale = std::fmax(std::fabs(q.x), std::fabs(q.y));
  if (!(target_scale <= kFar)) return Winding{false, 0};
  const double band = std::fmax(scale_, target_scale) * kBandFactor;
  long crossings = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const Box& box = boxes_[k];
    if (certainly_above(q.x - box.x_max, band) || certainly_above(box.y_min - q.y, band) ||
        certainly_above(q.y - box.y_max, band)) {
      continue;
    }
    const std::span<const Point2> points(points_.data() + offsets_[k],
                                         offsets_[k + 1] - offsets_[k]);
    if (certainly_above(box.x_min - q.x, band)) {
      crossings += chord_crossing(points.front().y <= q.y, points.back().y <= q.y);
      continue;
    }
    const SegmentOutcome outcome = refine_segment(points, q, band, budget);
    if (budget.exhausted()) return std::nullopt;
    if (outcome.boundary) return Winding{true, 0};
    crossings += outcome.crossings;
  }
  return Winding{false, crossings};
}

std::optional<Winding> winding(const Region& region, core::Point2 target, std::int64_t max_work) {
  core::WorkBudget budget(max_work);
  return RegionWinding(region).at(target, budget);
}

}  // namespace bezier::region
