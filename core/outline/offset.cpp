#include "core/outline/offset.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/numeric/power_of_two.hpp"
#include "core/outline/control_points.hpp"
#include "core/outline/offset_cusps.hpp"
#include "core/outline/tangent_limits.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

constexpr int kFitSamples = 16;
constexpr int kMaxSamples = 4096;
constexpr int kMaxDepth = 40;

Point2 left_normal(Point2 unit) { return {-unit.y, unit.x}; }

/// A point of B and the unit tangent there (the limit from the piece's side where B' = 0).
struct EndFrame {
  Point2 point;
  Point2 tangent;
};

/// The curve and the distances scaled by 2^e so that the largest of its coordinates and |d|
/// is in [1, 2): exact, and the squares the bound compares stay normal doubles.
struct ScaledCurve {
  ControlPoints points, first, second;  // B, B', B''
  double d = 0.0, tolerance = 0.0;
  double least_speed = 0.0;  // |B'| below this counts as zero (end_tangent's threshold)
  core::PowerOfTwo back{0};
  double margin = 0.0;  // offset.hpp's rounding allowance, scaled

  ScaledCurve(const core::Curve& curve, double distance, double tol) {
    const double size = std::max(core::scale(curve), std::fabs(distance));
    const int e = size > 0.0 ? -core::exponent_of(size) : 0;
    const core::PowerOfTwo factor(e);
    points.resize(curve.points().size(), ControlPoints::Uninitialized{});
    for (std::size_t i = 0; i < points.size(); ++i) points[i] = factor.times(curve.points()[i]);
    d = factor.times(distance);
    tolerance = factor.times(tol);
    back = core::PowerOfTwo(-e);
    hodograph_into(points, first);
    hodograph_into(first, second);
    const auto n = static_cast<double>(curve.degree());
    least_speed = 1e-12 * n * std::sqrt(largest_squared_length(points));
    margin = 64.0 * n * std::numeric_limits<double>::epsilon() *
             (std::sqrt(largest_squared_length(points)) + std::fabs(d));
  }

  /// B(t) and its unit tangent, computed from the whole curve so that two intervals meeting
  /// at t share them; where |B'(t)| is below the threshold, the limit from the piece
  /// [a, b] at its start (at_start) or end.
  [[nodiscard]] EndFrame frame(double t, double a, double b, bool at_start) const {
    const Point2 v = first.empty() ? Point2{0, 0} : point_at(first, t);
    const double speed_squared = squared_length(v);
    if (speed_squared > least_speed * least_speed) {
      return {point_at(points, t), v / std::sqrt(speed_squared)};
    }
    ControlPoints piece;
    piece_into(points, a, b, piece);
    return {point_at(points, t), end_tangent(piece, at_start)};
  }
};

struct PieceBound {
  double bound = std::numeric_limits<double>::infinity();
  std::int64_t work = 0;
};

/// The piece's derivatives' control points.
struct Hodographs {
  ControlPoints h1, h2, h3;
  explicit Hodographs(const ControlPoints& q) {
    hodograph_into(q, h1);
    hodograph_into(h1, h2);
    hodograph_into(h2, h3);
  }
};

/// The certified bound of offset.hpp for the piece with control points q (local parameter
/// u) and the cubic c. The samples stop as soon as one is too far for the tolerance (the
/// bound is then above it and the piece is halved: no bound of it is reported).
PieceBound bound_piece(const ControlPoints& q, const Hodographs& h, const std::array<Point2, 4>& c,
                       double d, double tolerance, Point2 start_normal, Point2 end_normal) {
  PieceBound result;
  const auto n = static_cast<std::int64_t>(q.size()) - 1;
  const double M1 = std::sqrt(largest_squared_length(h.h1));
  const double M2 = std::sqrt(largest_squared_length(h.h2));
  const double M3 = std::sqrt(largest_squared_length(h.h3));
  const Point2 mid = point_at(h.h1, 0.5);
  const double mid_squared = squared_length(mid);
  double m = 0.0;
  if (mid_squared > 0.0) {
    const Point2 direction = mid / std::sqrt(mid_squared);
    m = std::numeric_limits<double>::infinity();
    for (const Point2 p : h.h1) m = std::min(m, core::dot(p, direction));
  }
  const double c2 = 6.0 * std::sqrt(std::max(squared_length(c[2] - 2.0 * c[1] + c[0]),
                                             squared_length(c[3] - 2.0 * c[2] + c[1])));
  result.work = 8 * (n + 1) * (n + 1);
  if (m > 0.0) {
    const double w = M1 * M2 / (m * m);
    const double w1 = M1 * M3 / (m * m) + 2.0 * w * w;
    const double o2 = M2 + std::fabs(d) * (w1 + w * w);
    const double second = c2 + o2;
    const int samples = static_cast<int>(
        std::clamp(std::ceil(std::sqrt(second / (2.0 * tolerance))), 1.0, double{kMaxSamples}));
    const double step = 1.0 / samples;
    const double remainder = step * step / 8.0 * second;
    // A sample farther than this fails the piece.
    const double reach = tolerance - remainder;
    const double reach_squared = reach > 0.0 ? reach * reach : 0.0;
    double largest = 0.0;
    int taken = 0;
    for (int j = 0; j <= samples; ++j, ++taken) {
      const double u = j == samples ? 1.0 : j * step;
      Point2 normal;
      if (j == 0) {
        normal = start_normal;
      } else if (j == samples) {
        normal = end_normal;
      } else {
        const Point2 v = point_at(h.h1, u);
        const double speed_squared = squared_length(v);
        if (!(speed_squared > 0.0)) {
          largest = std::numeric_limits<double>::infinity();
          break;
        }
        normal = left_normal(v / std::sqrt(speed_squared));
      }
      const Point2 o = point_at(q, u) + d * normal;
      const double v = 1.0 - u;
      const Point2 on_cubic = (v * v * v) * c[0] + (3.0 * u * v * v) * c[1] +
                              (3.0 * u * u * v) * c[2] + (u * u * u) * c[3];
      largest = std::max(largest, squared_length(on_cubic - o));
      if (largest > reach_squared) {
        ++taken;
        break;
      }
    }
    result.work += static_cast<std::int64_t>(taken) * (n * (n + 1) + 12);
    result.bound = std::sqrt(largest) + remainder;
  }
  if (result.bound <= tolerance) return result;
  // The two balls about O(0).
  Point2 reference{0, 0};
  for (const Point2 p : h.h1)
    if (squared_length(p) > 0.0) reference = reference + p / std::sqrt(squared_length(p));
  const double reference_squared = squared_length(reference);
  if (reference_squared > 0.0) {
    const Point2 r = reference / std::sqrt(reference_squared);
    double lo = 0.0, hi = 0.0;
    for (const Point2 p : h.h1) {
      if (squared_length(p) == 0.0) continue;
      const double angle = std::atan2(core::cross(r, p), core::dot(r, p));
      lo = std::min(lo, angle);
      hi = std::max(hi, angle);
    }
    if (hi - lo < std::numbers::pi) {
      const Point2 origin = q[0] + d * start_normal;
      double r_curve = 0.0, r_cubic = 0.0;
      for (const Point2 p : q) r_curve = std::max(r_curve, squared_length(p - q[0]));
      for (const Point2 p : c) r_cubic = std::max(r_cubic, squared_length(p - origin));
      result.bound = std::min(result.bound,
                              std::sqrt(r_curve) + std::fabs(d) * (hi - lo) + std::sqrt(r_cubic));
    }
  }
  return result;
}

/// The cubic of offset.hpp for the piece q between the end frames: ends O(0), O(1),
/// tangents ±T, handles by least squares.
std::array<Point2, 4> fit(const ControlPoints& q, const ControlPoints& h1, double d,
                          const EndFrame& start, const EndFrame& end, double direction) {
  const Point2 p0 = start.point + d * left_normal(start.tangent);
  const Point2 p3 = end.point + d * left_normal(end.tangent);
  const Point2 d0 = direction * start.tangent, d3 = direction * end.tangent;
  double a11 = 0, a12 = 0, a22 = 0, r1 = 0, r2 = 0;
  for (int j = 1; j < kFitSamples; ++j) {
    const double u = static_cast<double>(j) / kFitSamples, v = 1.0 - u;
    const Point2 tangent = point_at(h1, u);
    const double speed_squared = squared_length(tangent);
    if (!(speed_squared > 0.0)) continue;
    const Point2 o = point_at(q, u) + d * left_normal(tangent / std::sqrt(speed_squared));
    const double b0 = v * v * v, b1 = 3 * u * v * v, b2 = 3 * u * u * v, b3 = u * u * u;
    const Point2 r = o - ((b0 + b1) * p0 + (b2 + b3) * p3);
    // r ≈ α b1 d0 - β b2 d3
    a11 += b1 * b1;
    a22 += b2 * b2;
    a12 -= b1 * b2 * core::dot(d0, d3);
    r1 += b1 * core::dot(r, d0);
    r2 -= b2 * core::dot(r, d3);
  }
  const double det = a11 * a22 - a12 * a12;
  const double chord = std::sqrt(squared_length(p3 - p0));
  double alpha = chord / 3, beta = chord / 3;
  if (std::fabs(det) > 1e-12 * a11 * a22) {
    alpha = (r1 * a22 - r2 * a12) / det;
    beta = (a11 * r2 - a12 * r1) / det;
  }
  return {p0, p0 + alpha * d0, p3 - beta * d3, p3};
}

/// Fits [a, b] of the scaled curve, halving where the bound fails; appends the cubics
/// (scaled back) to `out`.
bool fit_interval(const ScaledCurve& s, double a, double b, core::WorkBudget& budget,
                  std::vector<OffsetCubic>& out) {
  const std::size_t kept = out.size();
  const auto n = static_cast<std::int64_t>(s.points.size()) - 1;
  // The direction of O on this interval: the sign of 1 - d κ at its middle.
  const double middle = 0.5 * (a + b);
  const Point2 v = s.first.empty() ? Point2{0, 0} : point_at(s.first, middle);
  const Point2 acc = s.second.empty() ? Point2{0, 0} : point_at(s.second, middle);
  const double speed = std::sqrt(squared_length(v));
  const double direction =
      speed > 0.0 && s.d * core::cross(v, acc) / (speed * speed * speed) > 1.0 ? -1.0 : 1.0;

  struct Pending {
    double a, b;
    EndFrame start, end;
    int depth;
  };
  // Depth-first, left half on top: at most one pending right half per level.
  std::array<Pending, kMaxDepth + 2> stack;
  std::size_t top = 0;
  stack[top++] = {a, b, s.frame(a, a, b, true), s.frame(b, a, b, false), 0};
  ControlPoints q;
  while (top > 0) {
    const Pending piece = stack[--top];
    piece_into(s.points, piece.a, piece.b, q);
    const Hodographs h(q);
    const std::array<Point2, 4> c = fit(q, h.h1, s.d, piece.start, piece.end, direction);
    const PieceBound bound = bound_piece(q, h, c, s.d, s.tolerance, left_normal(piece.start.tangent),
                                         left_normal(piece.end.tangent));
    if (!budget.spend(bound.work + 16 * (n + 1) * (n + 1) * 4)) {
      out.resize(kept);
      return false;
    }
    if (bound.bound + s.margin <= s.tolerance) {
      OffsetCubic cubic{piece.a, piece.b, {}, 0.0};
      for (std::size_t i = 0; i < 4; ++i) cubic.points[i] = s.back.times(c[i]);
      cubic.error_bound = s.back.times(bound.bound + s.margin);
      out.push_back(cubic);
      continue;
    }
    if (piece.depth >= kMaxDepth) {
      budget.exhaust();
      out.resize(kept);
      return false;
    }
    const double mid = 0.5 * (piece.a + piece.b);
    const EndFrame at_mid = s.frame(mid, piece.a, mid, false);
    stack[top++] = {mid, piece.b, at_mid, piece.end, piece.depth + 1};
    stack[top++] = {piece.a, mid, piece.start, at_mid, piece.depth + 1};
  }
  return true;
}

}  // namespace

bool offset_interval(const core::Curve& curve, double a, double b, double d, double tolerance,
                     core::WorkBudget& budget, std::vector<OffsetCubic>& out) {
  const ScaledCurve scaled(curve, d, tolerance);
  return fit_interval(scaled, a, b, budget, out);
}

CurveOffset offset_curve(const core::Curve& curve, double d, double tolerance,
                         std::int64_t work_left) {
  CurveOffset result;
  core::WorkBudget budget(work_left);
  std::vector<double> cuts{0.0, 1.0};
  for (const double t : offset_cusps(curve, d)) cuts.push_back(t);
  for (const double t : stationary_points(curve)) cuts.push_back(t);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  const auto n = static_cast<std::int64_t>(curve.degree());
  budget.charge(64 * n * n * n);
  const ScaledCurve scaled(curve, d, tolerance);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    if (!(cuts[k + 1] > cuts[k])) continue;
    if (!fit_interval(scaled, cuts[k], cuts[k + 1], budget, result.cubics)) {
      result.status = OffsetStatus::work_cap_reached;
      result.cubics.clear();
      break;
    }
  }
  result.work = budget.spent();
  return result;
}

}  // namespace bezier::outline
