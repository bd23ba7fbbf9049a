#include "core/outline/offset.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <tuple>

#include "core/base/multiversion.hpp"
#include "core/numeric/power_of_two.hpp"
#include "core/outline/area_moment_fit.hpp"
#include "core/outline/control_points.hpp"
#include "core/outline/normal_turning.hpp"
#include "core/outline/offset_cusps.hpp"
#include "core/outline/straight_curve.hpp"
#include "core/outline/tangent_limits.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

// The fewest samples of a fit's bound (three interior samples for the least squares' two
// handles), and the samples of the least squares where m is not positive (no bound of
// |d N''| to choose them from).
constexpr int kFitSamples = 4;
constexpr int kBallSamples = 8;
constexpr int kMaxSamples = 4096;
// The deepest split: next to a zero of B' that is one only to within a few units of
// rounding (a hairpin whose turn spans 1e-12 of the parameter), the halving towards it takes
// about 40 levels before the turn itself is reached.
constexpr int kMaxDepth = 60;
constexpr int kMostParts = 8;
// The first K: the remainder h^2 / 8 |e''| within kFirstRemainder of the tolerance with
// |e''| estimated at kSecondEstimate times the bound of |d N''| (the sampled term of |e''|,
// |s^2 C'' - B_p''|, is about a third of that bound where the fit follows O).
constexpr double kFirstRemainder = 0.9;
constexpr double kSecondEstimate = 1.4;
// A denser K is tried while the samples stay below kDenserBelow of the tolerance, for the
// remainder within kDenserRoom of the room they leave, with |e''| estimated at
// kDenserEstimate times the sampled one (denser samples find more of s^2 C''); at most
// kDenserTries times, each later one at least a quarter denser than the one before.
constexpr double kDenserBelow = 0.995;
constexpr double kDenserRoom = 0.9;
constexpr double kDenserEstimate = 1.3;
constexpr int kDenserTries = 2;
// foot_bound's further Gauss-Newton steps at a sample whose distance exceeds this share of
// the tolerance (at most kFootSteps, while each at least halves the distance).
constexpr double kFootRefine = 0.25;
constexpr int kFootSteps = 4;

/// The buffer of one thread's samples of O, reused from fit to fit.
std::vector<Point2>& sample_buffer() {
  thread_local std::vector<Point2> buffer;
  return buffer;
}

/// The buffer of one thread's denser samples of O for a bound that needs more of them.
std::vector<Point2>& dense_buffer() {
  thread_local std::vector<Point2> buffer;
  return buffer;
}

/// The buffer of one thread's samples of the other side of a piece (offset_interval_sides).
std::vector<Point2>& side_buffer() {
  thread_local std::vector<Point2> buffer;
  return buffer;
}

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
  bool straight = false;  // the control points are collinear (straight_curve.hpp)
  bool point = false;     // the control points are all equal (core::is_point)
  // For a straight curve, the unit direction of its line: from P_0 to the control point
  // farthest from it (one direction for every interval, so that the normals of two runs that
  // go opposite ways are exact negatives of each other, and the stroke's edges along the
  // line coincide bit for bit).
  Point2 line{1.0, 0.0};
  // For a straight curve of degree 2 or more, B at its ends and at its zeros of B' (where it
  // turns back), computed as the intervals' ends are: straight_interval splits each run's
  // segment where it passes one of them, so that the runs' segments along one side overlap
  // in whole pieces with the same ends.
  std::vector<Point2> turns;

  ScaledCurve(const core::Curve& curve, double distance, double tol) {
    const double size = std::max(largest_abs_coordinate(curve.points()), std::fabs(distance));
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
    const double largest = std::sqrt(largest_squared_length(points));
    least_speed = 1e-12 * n * largest;
    margin = 64.0 * n * std::numeric_limits<double>::epsilon() * (largest + std::fabs(d));
    straight = control_points_collinear(points);
    point = core::is_point(curve);
    if (straight && !point) {
      Point2 farthest = points[0];
      for (const Point2 p : points)
        if (squared_length(p - points[0]) > squared_length(farthest - points[0])) farthest = p;
      line = (farthest - points[0]) / std::sqrt(squared_length(farthest - points[0]));
      if (points.size() > 2) {
        turns.push_back(point_at(points, 0.0));
        for (const double t : stationary_points(curve)) turns.push_back(point_at(points, t));
        turns.push_back(point_at(points, 1.0));
      }
    }
  }

  /// B'(t) (zero for a curve of one point).
  [[nodiscard]] Point2 velocity(double t) const {
    return first.empty() ? Point2{0, 0} : point_at(first, t);
  }

  /// Whether |B'(t)| is below the threshold, so that frame() takes the limit tangent at t
  /// (v = velocity(t)).
  [[nodiscard]] bool stationary_at(Point2 v) const {
    return !(squared_length(v) > least_speed * least_speed);
  }
  [[nodiscard]] bool stationary(double t) const { return stationary_at(velocity(t)); }

  /// B(t) and its unit tangent, computed from the whole curve so that two intervals meeting
  /// at t share them; where |B'(t)| is below the threshold, the limit from the piece
  /// [a, b] at its start (at_start) or end.
  [[nodiscard]] EndFrame frame(double t, double a, double b, bool at_start) const {
    return frame_at(t, velocity(t), a, b, at_start);
  }

  /// frame() with v = velocity(t) given.
  [[nodiscard]] EndFrame frame_at(double t, Point2 v, double a, double b, bool at_start) const {
    const double speed_squared = squared_length(v);
    if (speed_squared > least_speed * least_speed) {
      return {point_at(points, t), v / std::sqrt(speed_squared)};
    }
    ControlPoints piece;
    piece_into(points, a, b, piece);
    return {point_at(points, t), end_tangent(piece, at_start)};
  }
};

/// The least projection of the control points g on the direction of their curve at 1/2 (0
/// when not positive, or when that point is zero).
double least_projection(const ControlPoints& g) {
  const Point2 mid = g.empty() ? Point2{0, 0} : point_at(g, 0.5);
  const double mid_squared = squared_length(mid);
  if (!(mid_squared > 0.0)) return 0.0;
  const Point2 direction = mid / std::sqrt(mid_squared);
  double least = std::numeric_limits<double>::infinity();
  for (const Point2 p : g) least = std::min(least, core::dot(p, direction));
  return std::max(least, 0.0);
}

/// The control points of Q with g = (1 - t) Q (g's last control point taken as zero; g of
/// degree k >= 1): q_i = g_i k / (k - i), since C(k, i) / C(k - 1, i) = k / (k - i).
void divide_at_end(ControlPoints& g) {
  const std::size_t k = g.size() - 1;
  for (std::size_t i = 0; i < k; ++i)
    g[i] = (static_cast<double>(k) / static_cast<double>(k - i)) * g[i];
  g.resize(k, ControlPoints::Uninitialized{});
}

/// The control points of Q with g = t Q (g's first control point taken as zero): q_i =
/// g_{i+1} k / (i + 1), since C(k, i + 1) / C(k - 1, i) = k / (i + 1).
void divide_at_start(ControlPoints& g) {
  const std::size_t k = g.size() - 1;
  for (std::size_t i = 0; i < k; ++i)
    g[i] = (static_cast<double>(k) / static_cast<double>(i + 1)) * g[i + 1];
  g.resize(k, ControlPoints::Uninitialized{});
}

/// The piece's derivatives' control points and the bounds offset.hpp takes from them.
struct PieceShape {
  ControlPoints h1, h2, h3;
  double M2 = 0.0, M3 = 0.0;
  double m = 0.0;  // least projection of h1 on the direction of B'(1/2); 0 when not positive
  // The bounds of the normal's turning (offset.hpp): those of B_p' itself (W = M, w = m), or
  // where B' vanishes at an end of the piece, those of the reduced hodograph Q with B_p' =
  // t^i (1 - t)^j Q, whose direction is B_p''s inside the piece.
  double W2 = 0.0, W3 = 0.0;
  double w = 0.0;  // least projection of Q on the direction of Q(1/2); 0 when not positive
  bool reduced_start = false, reduced_end = false;
  Point2 start_direction{0, 0}, end_direction{0, 0};  // Q(0), Q(1) as unit vectors, if reduced

  /// The piece [a, b] of the scaled curve s: its first and second hodographs are (b - a)
  /// and (b - a)^2 times the pieces of B' and B'' on [a, b], taken from B' and B'' rather
  /// than by differencing the piece's own control points. Those carry rounding of about u
  /// times the curve's size, which is not small against the differences of a short piece
  /// (next to a cusp of O the parts grow very short): from B' the direction of B_p' at each
  /// sample keeps the relative accuracy of B' itself, however short the piece.
  /// zero_start, zero_end: the piece's end is an end of the interval being fitted (a cut of
  /// offset_curve, or of the caller of offset_interval) where B' is below the threshold.
  PieceShape(const ScaledCurve& s, double a, double b, bool zero_start, bool zero_end) {
    const double length = b - a;
    // (Times a length of 1, the whole curve's: the points as they are.)
    piece_into(s.first, a, b, h1);
    if (length != 1.0)
      for (Point2& p : h1) p = length * p;
    if (!s.second.empty()) {
      piece_into(s.second, a, b, h2);
      if (length != 1.0)
        for (Point2& p : h2) p = (length * length) * p;
    }
    hodograph_into(h2, h3);
    M2 = std::sqrt(largest_squared_length(h2));
    M3 = std::sqrt(largest_squared_length(h3));
    m = least_projection(h1);
    W2 = M2;
    W3 = M3;
    w = m;
    // Where an end of the interval is a zero of B' (B' below the threshold there, so that
    // the frame takes the limit tangent), B' is taken to vanish there exactly and the factor
    // t (or 1 - t) is divided out, again while the reduced hodograph's end point stays below
    // 1e-9 of its largest (a zero of higher order, stationary_points' relative threshold).
    reduced_start = h1.size() >= 2 && zero_start;
    reduced_end = h1.size() >= 2 && zero_end;
    if (!reduced_start && !reduced_end) return;
    ControlPoints q = h1, q1, q2;
    auto negligible = [](const ControlPoints& g, Point2 p) {
      return !(squared_length(p) > 1e-18 * largest_squared_length(g));
    };
    if (reduced_start) {
      do divide_at_start(q);
      while (q.size() >= 2 && negligible(q, q[0]));
    }
    if (reduced_end && q.size() >= 2) {
      do divide_at_end(q);
      while (q.size() >= 2 && negligible(q, q[q.size() - 1]));
    }
    hodograph_into(q, q1);
    hodograph_into(q1, q2);
    W2 = std::sqrt(largest_squared_length(q1));
    W3 = std::sqrt(largest_squared_length(q2));
    w = least_projection(q);
    if (w > 0.0) {
      start_direction = q[0] / std::sqrt(squared_length(q[0]));
      end_direction = q[q.size() - 1] / std::sqrt(squared_length(q[q.size() - 1]));
    }
  }

  /// offset.hpp's bound of |d N''| on the piece (needs w > 0; normal_turning.hpp).
  [[nodiscard]] double normal_second(double d) const { return normal_second_bound(W2, W3, w, d); }

  /// The estimate of |e''| the first sample count is chosen for (offset.hpp): the bound of
  /// |d N''| times kSecondEstimate.
  [[nodiscard]] double sample_estimate(double d) const {
    return kSecondEstimate * normal_second(d);
  }

  /// The distance |d| |T - Q/|Q|| at the reduced ends between the end frames' tangents
  /// (end_tangent's, from the first derivative that is not zero) and the limit direction Q
  /// gives (offset.hpp): added to the bound, 0 where no end is reduced.
  [[nodiscard]] double end_slack(const EndFrame& start, const EndFrame& end, double d) const {
    double slack = 0.0;
    if (reduced_start)
      slack = std::max(slack, std::sqrt(squared_length(start.tangent - start_direction)));
    if (reduced_end)
      slack = std::max(slack, std::sqrt(squared_length(end.tangent - end_direction)));
    return std::fabs(d) * slack;
  }
};

/// The uniform parameters u_j = j / K (j = 0..K) and the cubic Bernstein weights there, with
/// the sums the least squares of fit() needs, per K: built once per thread for K up to
/// kTabledCounts (when first used: at most about 40 (K + 1) bytes each, 1.3 MB for all),
/// and for a larger K whenever it differs from the last one.
struct CubicWeights {
  int count = 0;
  std::vector<double> u, b0, b1, b2, b3;
  double s11 = 0.0, s22 = 0.0, s12 = 0.0;  // over the interior j: Σ b1^2, Σ b2^2, Σ b1 b2

  void build(int k) {
    count = k;
    const auto size = static_cast<std::size_t>(k) + 1;
    u.resize(size);
    b0.resize(size);
    b1.resize(size);
    b2.resize(size);
    b3.resize(size);
    s11 = s22 = s12 = 0.0;
    for (std::size_t j = 0; j < size; ++j) {
      const double x = j == size - 1 ? 1.0 : static_cast<double>(j) / k, y = 1.0 - x;
      u[j] = x;
      b0[j] = y * y * y;
      b1[j] = 3.0 * x * y * y;
      b2[j] = 3.0 * x * x * y;
      b3[j] = x * x * x;
      if (j > 0 && j + 1 < size) {
        s11 += b1[j] * b1[j];
        s22 += b2[j] * b2[j];
        s12 += b1[j] * b2[j];
      }
    }
  }
};

constexpr int kTabledCounts = 256;

const CubicWeights& cubic_weights(int count) {
  thread_local std::array<CubicWeights, kTabledCounts + 1> tabled;
  thread_local CubicWeights last;
  CubicWeights& w = count <= kTabledCounts ? tabled[static_cast<std::size_t>(count)] : last;
  if (w.count != count) w.build(count);
  return w;
}

/// The piece's point B_p(u_j) and derivative B_p'(u_j) at the interior samples u_j = j / K
/// (j = 1..K-1) of a cubic piece q with hodograph h1, from the Bernstein weights inline, each
/// handed to at(j, B_p, B_p'): the loop sample_parallel and sample_both_sides share.
template <class At>
void cubic_interior_samples(const ControlPoints& q, const ControlPoints& h1,
                            const CubicWeights& weights, At at) {
  const Point2 q0 = q[0], q1 = q[1], q2 = q[2], q3 = q[3];
  const Point2 g0 = h1[0], g1 = h1[1], g2 = h1[2];
  for (int j = 1; j < weights.count; ++j) {
    const auto i = static_cast<std::size_t>(j);
    const double u = weights.u[i], w = 1.0 - u;
    const Point2 v = (w * w) * g0 + (2.0 * u * w) * g1 + (u * u) * g2;
    const Point2 b = weights.b0[i] * q0 + weights.b1[i] * q1 + weights.b2[i] * q2 +
                     weights.b3[i] * q3;
    at(j, b, v);
  }
}

/// O on the piece at u_j = j / K, j = 0..K: the ends given (from the end frames), the others
/// from the piece's point and hodograph; a sample where B' evaluates to zero is NaN (the fit
/// leaves it out). Returns whether every sample is a number.
bool sample_parallel(const ControlPoints& q, const ControlPoints& h1, double d, Point2 start,
                     Point2 end, const CubicWeights& weights, std::vector<Point2>& out) {
  const int count = weights.count;
  out.resize(static_cast<std::size_t>(count) + 1);
  out.front() = start;
  out.back() = end;
  bool all = true;
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (q.size() == 4) {
    // A cubic (the common case).
    Point2* o = out.data();
    cubic_interior_samples(q, h1, weights, [&](int j, Point2 b, Point2 v) {
      const double speed_squared = squared_length(v);
      if (!(speed_squared > 0.0)) {
        o[j] = {kNaN, kNaN};
        all = false;
        return;
      }
      const double scale = d / std::sqrt(speed_squared);
      o[j] = {b.x - scale * v.y, b.y + scale * v.x};
    });
    return all;
  }
  for (int j = 1; j < count; ++j) {
    const double u = weights.u[static_cast<std::size_t>(j)];
    const Point2 v = point_at(h1, u);
    const double speed_squared = squared_length(v);
    if (!(speed_squared > 0.0)) {
      out[static_cast<std::size_t>(j)] = {kNaN, kNaN};
      all = false;
      continue;
    }
    out[static_cast<std::size_t>(j)] = point_at(q, u) + d * left_normal(v / std::sqrt(speed_squared));
  }
  return all;
}

/// Both sides' samples O = B_p ± d N at once (as sample_parallel at d and at -d, bit for
/// bit): B_p and B_p' are evaluated once per sample. The ends are the end frames' points
/// moved by ±d along their normals. Returns whether every sample is a number.
BEZIER_FMA_CLONES bool sample_both_sides(const ControlPoints& q, const ControlPoints& h1,
                                         double d, const EndFrame& start, const EndFrame& end,
                                         const CubicWeights& weights, std::vector<Point2>& plus,
                                         std::vector<Point2>& minus) {
  const Point2 n0 = left_normal(start.tangent), n1 = left_normal(end.tangent);
  if (q.size() != 4) {
    const bool all = sample_parallel(q, h1, d, start.point + d * n0, end.point + d * n1,
                                     weights, plus);
    sample_parallel(q, h1, -d, start.point + (-d) * n0, end.point + (-d) * n1, weights, minus);
    return all;
  }
  const int count = weights.count;
  plus.resize(static_cast<std::size_t>(count) + 1);
  minus.resize(static_cast<std::size_t>(count) + 1);
  plus.front() = start.point + d * n0;
  plus.back() = end.point + d * n1;
  minus.front() = start.point + (-d) * n0;
  minus.back() = end.point + (-d) * n1;
  bool all = true;
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  Point2* o = plus.data();
  Point2* r = minus.data();
  cubic_interior_samples(q, h1, weights, [&](int j, Point2 b, Point2 v) {
    const double speed_squared = squared_length(v);
    if (!(speed_squared > 0.0)) {
      o[j] = r[j] = {kNaN, kNaN};
      all = false;
      return;
    }
    // (-d) / x is -(d / x) exactly: the other side's samples are those of sample_parallel.
    const double scale = d / std::sqrt(speed_squared), other = -scale;
    o[j] = {b.x - scale * v.y, b.y + scale * v.x};
    r[j] = {b.x - other * v.y, b.y + other * v.x};
  });
  return all;
}

/// The signed area ∫ y dx and moment ∫ x y dx of O on the piece in the frame of its chord
/// (area_moment_fit.hpp: O(0) at (0, 0), O(1) at (1, 0)), by Gauss-Legendre quadrature on
/// six nodes, with O' = B_p' (1 - d κ), κ = cross(B_p', B_p'') / |B_p'|^3. Only
/// proposes a cubic (the bound decides), so the quadrature's error needs no bound; not valid
/// where B_p' vanishes at a node or the chord is empty.
struct ChordMoments {
  double area = 0.0, moment = 0.0;
  bool valid = false;
};

/// The moments of N parallel curves of one piece, at the distances ds with the ends starts,
/// ends: B_p, B_p' and B_p'' once per node for all of them, each curve's sums as alone.
template <std::size_t N>
std::array<ChordMoments, N> chord_moments_of(const ControlPoints& q, const ControlPoints& h1,
                                             const ControlPoints& h2,
                                             const std::array<double, N>& ds,
                                             const std::array<Point2, N>& starts,
                                             const std::array<Point2, N>& ends) {
  // The 6-point Gauss-Legendre rule on [-1, 1] (Abramowitz and Stegun, table 25.4): the
  // three positive nodes, then their negatives, in the order the sums are taken.
  static constexpr double kNode0 = 0.2386191860831969, kNode1 = 0.6612093864662645,
                          kNode2 = 0.9324695142031521;
  static constexpr double kWeight0 = 0.4679139345726910, kWeight1 = 0.3607615730481386,
                          kWeight2 = 0.1713244923791704;
  static constexpr std::array<double, 6> kNodes{kNode0, kNode1, kNode2, -kNode0, -kNode1, -kNode2};
  static constexpr std::array<double, 6> kWeights{kWeight0, kWeight1, kWeight2,
                                                  kWeight0, kWeight1, kWeight2};
  std::array<ChordMoments, N> results{};
  std::array<Point2, N> axes{};
  std::array<bool, N> open{};
  bool any = false;
  for (std::size_t c = 0; c < N; ++c) {
    const Point2 chord = ends[c] - starts[c];
    const double chord_squared = squared_length(chord);
    open[c] = chord_squared > 0.0;
    if (open[c]) axes[c] = chord / chord_squared;
    any = any || open[c];
  }
  if (!any) return results;
  std::array<double, N> area{}, moment{};
  const bool cubic = q.size() == 4;
  for (std::size_t i = 0; i < kNodes.size(); ++i) {
    const double u = 0.5 + 0.5 * kNodes[i], w = 1.0 - u, weight = kWeights[i];
    // A cubic's point and derivatives from its control points and hodographs inline.
    const Point2 v = cubic ? (w * w) * h1[0] + (2.0 * u * w) * h1[1] + (u * u) * h1[2]
                           : point_at(h1, u);
    const double speed_squared = squared_length(v);
    if (!(speed_squared > 0.0)) return std::array<ChordMoments, N>{};
    const Point2 acc = cubic ? w * h2[0] + u * h2[1]
                             : (h2.empty() ? Point2{0, 0} : point_at(h2, u));
    const Point2 b = cubic ? (w * w * w) * q[0] + (3.0 * u * w * w) * q[1] +
                                 (3.0 * u * u * w) * q[2] + (u * u * u) * q[3]
                           : point_at(q, u);
    const double inverse = 1.0 / std::sqrt(speed_squared);
    for (std::size_t c = 0; c < N; ++c) {
      if (!open[c]) continue;
      const double d = ds[c];
      const Point2 axis = axes[c];
      const Point2 at = b + (d * inverse) * left_normal(v);
      const double rate = 1.0 - d * core::cross(v, acc) * (inverse * inverse * inverse);
      const Point2 r = at - starts[c];
      const double x = core::dot(r, axis), y = core::cross(axis, r);
      const double dx = weight * rate * core::dot(v, axis);
      area[c] += y * dx;
      moment[c] += x * y * dx;
    }
  }
  for (std::size_t c = 0; c < N; ++c) {
    if (!open[c]) continue;
    // The rule's weights sum to 2 on [-1, 1]: half of that on [0, 1].
    results[c].area = 0.5 * area[c];
    results[c].moment = 0.5 * moment[c];
    results[c].valid = std::isfinite(results[c].area) && std::isfinite(results[c].moment);
  }
  return results;
}

/// chord_moments_of for both sides of a piece (the FMA clones: the same roundings).
BEZIER_FMA_CLONES std::array<ChordMoments, 2> chord_moments_of_sides(
    const ControlPoints& q, const ControlPoints& h1, const ControlPoints& h2, double d,
    const std::array<Point2, 2>& starts, const std::array<Point2, 2>& ends) {
  return chord_moments_of<2>(q, h1, h2, {d, -d}, starts, ends);
}

ChordMoments chord_moments(const ControlPoints& q, const ControlPoints& h1,
                           const ControlPoints& h2, double d, Point2 start, Point2 end) {
  return chord_moments_of<1>(q, h1, h2, {d}, {start}, {end})[0];
}

/// The cubic of offset.hpp with ends p0, p3 and unit end directions d0, d3 (the direction of
/// travel of O): the handle lengths α, β minimising Σ |C(u_j) - O(u_j)|^2 over the interior
/// samples of `o` (u_j = j / K).
std::array<Point2, 4> fit(const std::vector<Point2>& o, const CubicWeights& w, bool all_numbers,
                          Point2 d0, Point2 d3) {
  const Point2 p0 = o.front(), p3 = o.back();
  const double d03 = core::dot(d0, d3);
  double a11 = 0, a12 = 0, a22 = 0, r1 = 0, r2 = 0;
  if (all_numbers) {
    a11 = w.s11;
    a22 = w.s22;
    a12 = -w.s12 * d03;
  }
  for (std::size_t j = 1; j + 1 < o.size(); ++j) {
    const Point2 sample = o[j];
    if (!all_numbers) {
      if (std::isnan(sample.x)) continue;
      a11 += w.b1[j] * w.b1[j];
      a22 += w.b2[j] * w.b2[j];
      a12 -= w.b1[j] * w.b2[j] * d03;
    }
    // r ≈ α b1 d0 - β b2 d3
    const Point2 r = sample - ((w.b0[j] + w.b1[j]) * p0 + (w.b2[j] + w.b3[j]) * p3);
    r1 += w.b1[j] * core::dot(r, d0);
    r2 -= w.b2[j] * core::dot(r, d3);
  }
  const double det = a11 * a22 - a12 * a12;
  const double chord = std::sqrt(squared_length(p3 - p0));
  double alpha = chord / 3, beta = chord / 3;
  if (std::fabs(det) > 1e-12 * a11 * a22) {
    alpha = (r1 * a22 - r2 * a12) / det;
    beta = (a11 * r2 - a12 * r1) / det;
  }
  // A negative handle would start the cubic backwards, against O's direction of travel on
  // the piece, and fold it back next to its end (a hook beside a cusp of O, where O's speed
  // vanishes and the least squares can prefer it): the handle is 0 instead, and the other
  // one the least squares with it fixed.
  if (alpha < 0.0) {
    alpha = 0.0;
    beta = a22 > 0.0 ? std::max(r2 / a22, 0.0) : 0.0;
  }
  if (beta < 0.0) {
    beta = 0.0;
    alpha = a11 > 0.0 ? std::max(r1 / a11, 0.0) : 0.0;
  }
  return {p0, p0 + alpha * d0, p3 - beta * d3, p3};
}

/// The direction u in the frame of the unit chord direction `axis`: (u · axis, axis × u).
/// Kept out of line: in an FMA clone, GCC's vectorizer takes the pair for a complex product
/// and fuses its multiplications and additions (vfmsubadd) in spite of -ffp-contract=off,
/// which would change the bits against the plain x86-64 copy.
__attribute__((noinline)) Point2 in_chord_frame(Point2 u, Point2 axis) {
  return {core::dot(u, axis), core::cross(axis, u)};
}

/// The sampled part of offset.hpp's bound for the cubic c against the samples o_j = O(t_j),
/// t_j = j / K, under the correspondence t -> u = ψ(t) that is linear between the u_j, each
/// u_j near the foot of o_j on c: a Gauss-Newton step of (C(u) - o_j) · C'(u) = 0 from the
/// linear extrapolation of the previous two, then more steps (at most kFootSteps) while
/// |C(u_j) - o_j| exceeds kFootRefine of `reach` and each step at least halves it (where the
/// extrapolation lands far from the foot: next to an end, where ψ' differs most from 1),
/// each kept in [0, 1]; u_0 = 0, u_K = 1. Any u_j in [0, 1] gives a valid bound; the nearer
/// the foot, the smaller it is.
struct SampledBound {
  double largest = 0.0;  // max_j |C(u_j) - o_j|, or the first one beyond `reach`
  double second = 0.0;   // the bound of |(C o ψ)'' - B_p''| between samples
  bool within = true;    // no sample beyond `reach`
};

/// L doubles, one per curve that foot_walk bounds at once (the two sides of a stroke's
/// segment): each operation is the scalar one on each in turn, so that every curve's
/// arithmetic is that of its walk alone.
template <int L>
struct Lanes {
  double v[L];

  static Lanes all(double x) {
    Lanes out;
    for (int i = 0; i < L; ++i) out.v[i] = x;
    return out;
  }
};
template <int L, class Op>
Lanes<L> each(Lanes<L> a, Lanes<L> b, Op op) {
  for (int i = 0; i < L; ++i) a.v[i] = op(a.v[i], b.v[i]);
  return a;
}
template <int L>
Lanes<L> operator+(Lanes<L> a, Lanes<L> b) { return each(a, b, std::plus<>{}); }
template <int L>
Lanes<L> operator-(Lanes<L> a, Lanes<L> b) { return each(a, b, std::minus<>{}); }
template <int L>
Lanes<L> operator*(Lanes<L> a, Lanes<L> b) { return each(a, b, std::multiplies<>{}); }
template <int L>
Lanes<L> operator/(Lanes<L> a, Lanes<L> b) { return each(a, b, std::divides<>{}); }

/// Points of L curves, coordinate by coordinate.
template <int L>
struct LanePoints {
  Lanes<L> x, y;

  static LanePoints all(Point2 p) { return {Lanes<L>::all(p.x), Lanes<L>::all(p.y)}; }
};
template <int L>
LanePoints<L> operator+(LanePoints<L> a, LanePoints<L> b) { return {a.x + b.x, a.y + b.y}; }
template <int L>
LanePoints<L> operator-(LanePoints<L> a, LanePoints<L> b) { return {a.x - b.x, a.y - b.y}; }
template <int L>
LanePoints<L> operator*(Lanes<L> s, LanePoints<L> a) { return {s * a.x, s * a.y}; }
template <int L>
Lanes<L> squared_lengths(LanePoints<L> a) { return a.x * a.x + a.y * a.y; }
template <int L>
Lanes<L> dots(LanePoints<L> a, LanePoints<L> b) { return a.x * b.x + a.y * b.y; }

/// foot_bound's loop for L cubics c[i] against their samples o[i] at once (the same sample
/// count), with B_p'' linear in t (Linear: degree <= 3, from the first and last control
/// points k0, k1 of its hodograph h2) or not (point_at(h2, t)): each curve's result is the
/// one foot_bound states, bit for bit (every operation is foot_bound's, on each curve). Where
/// a curve's sample is beyond `reach`, the walk stops there for all of them: each is then
/// `within` = false, with its largest distance so far (for L = 1, foot_bound's answer; for
/// L > 1 the others' are cut short, and the caller bounds them alone). The loop over the
/// interior samples and the last node (u = 1 at t = 1) are written apart only so that no test
/// of the last index is made per sample.
template <int L, bool Linear>
void foot_walk(const std::array<const std::array<Point2, 4>*, L>& c,
               const std::array<const std::vector<Point2>*, L>& o, const ControlPoints& h2,
               double reach, std::array<SampledBound, L>& out, int& taken) {
  using Real = Lanes<L>;
  using Point = LanePoints<L>;
  auto gather = [&](std::size_t k) {
    Point p;
    for (int i = 0; i < L; ++i) {
      p.x.v[i] = (*c[static_cast<std::size_t>(i)])[k].x;
      p.y.v[i] = (*c[static_cast<std::size_t>(i)])[k].y;
    }
    return p;
  };
  const auto count = static_cast<int>(o[0]->size()) - 1;
  const double h = 1.0 / count;
  const Real two = Real::all(2.0), three = Real::all(3.0), six = Real::all(6.0),
             one = Real::all(1.0);
  const Point p0 = gather(0), p1 = gather(1), p2 = gather(2), p3 = gather(3);
  // C'(u) = a1 + u (2 a2 + 3 u a3) (the power form C(u) = c[0] + u (a1 + u (a2 + u a3))).
  const Point a1 = three * (p1 - p0), a2 = three * (p2 - two * p1 + p0),
              a3 = p3 - p0 + three * (p1 - p2);
  const Point c0 = two * a2, c1 = two * a2 + six * a3;  // C''(0), C''(1)
  const Point twice_a2 = two * a2, thrice_a3 = three * a3;
  const Point2 k0 = h2.empty() ? Point2{0, 0} : h2[0];
  const Point2 k1 = h2.empty() ? Point2{0, 0} : h2[h2.size() - 1];
  auto second_of_b = [&](double t) {
    if constexpr (Linear) {
      return (1.0 - t) * k0 + t * k1;
    } else {
      return point_at(h2, t);
    }
  };
  // C(u) - target with C in Bernstein form (positive weights: within a few units of rounding
  // of the coordinates, as offset.hpp's margin assumes).
  auto off = [&](Real u, Point target) {
    const Real w = one - u;
    return (w * w * w) * p0 + (three * u * w * w) * p1 + (three * u * u * w) * p2 +
           (u * u * u) * p3 - target;
  };
  // One Gauss-Newton step from u for the residual r = C(u) - target, kept in [0, 1].
  auto step_from = [&](Real u, Point r) {
    const Point v = a1 + u * (twice_a2 + u * thrice_a3);
    const Real speed_squared = squared_lengths(v);
    const Real next = u - dots(r, v) / speed_squared;
    for (int i = 0; i < L; ++i) {
      if (speed_squared.v[i] > 0.0) u.v[i] = std::clamp(next.v[i], 0.0, 1.0);
    }
    return u;
  };
  const double reach_squared = reach > 0.0 ? reach * reach : 0.0;
  const double refine_squared = (kFootRefine * kFootRefine) * reach_squared;
  Real largest = Real::all(0.0), second = Real::all(0.0);
  Real u_prev = Real::all(0.0), u_before = Real::all(-h);
  Point c2_prev = c0;
  Point2 b2_prev = second_of_b(0.0);
  // Between t_prev and t: ψ' = s, (C o ψ)'' = s^2 C''(ψ), linear in t as C'' is (and B_p''
  // too for n <= 3): its largest distance from B_p'' is at an end.
  auto bend_to = [&](Real u, double t) {
    const Real s = (u - u_prev) / Real::all(h), s2 = s * s;
    const Point c2 = (one - u) * c0 + u * c1;
    const Point2 b2 = second_of_b(t);
    const Real before = squared_lengths(s2 * c2_prev - Point::all(b2_prev));
    const Real after = squared_lengths(s2 * c2 - Point::all(b2));
    for (int i = 0; i < L; ++i) {
      second.v[i] = std::max(std::max(second.v[i], before.v[i]), after.v[i]);
    }
    u_before = u_prev;
    u_prev = u;
    c2_prev = c2;
    b2_prev = b2;
  };
  bool within = true;
  int j = 1;
  for (; j < count; ++j) {
    const double t = j * h;
    Point target;
    for (int i = 0; i < L; ++i) {
      const Point2 sample = (*o[static_cast<std::size_t>(i)])[static_cast<std::size_t>(j)];
      target.x.v[i] = sample.x;
      target.y.v[i] = sample.y;
    }
    Real guess = u_prev + (u_prev - u_before);
    for (int i = 0; i < L; ++i) guess.v[i] = std::clamp(guess.v[i], 0.0, 1.0);
    Real u = step_from(guess, off(guess, target));
    Point r = off(u, target);
    Real distance_squared = squared_lengths(r);
    // Further steps on each curve while its distance exceeds the refinement share and each
    // step at least halves it.
    bool refine[L];
    bool any = false;
    for (int i = 0; i < L; ++i) any |= refine[i] = distance_squared.v[i] > refine_squared;
    for (int more = 0; more < kFootSteps && any; ++more) {
      const Real next = step_from(u, r);
      const Point next_r = off(next, target);
      const Real next_squared = squared_lengths(next_r);
      any = false;
      for (int i = 0; i < L; ++i) {
        if (!refine[i]) continue;
        refine[i] = next_squared.v[i] < distance_squared.v[i];
        if (!refine[i]) continue;
        const bool slow = !(next_squared.v[i] < 0.25 * distance_squared.v[i]);
        u.v[i] = next.v[i];
        r.x.v[i] = next_r.x.v[i];
        r.y.v[i] = next_r.y.v[i];
        distance_squared.v[i] = next_squared.v[i];
        refine[i] = !slow && distance_squared.v[i] > refine_squared;
        any |= refine[i];
      }
    }
    bool beyond = false;
    for (int i = 0; i < L; ++i) {
      largest.v[i] = std::max(largest.v[i], distance_squared.v[i]);
      beyond |= largest.v[i] > reach_squared;
    }
    if (beyond) {
      within = false;
      break;
    }
    bend_to(u, t);
  }
  taken = j;
  if (within) bend_to(one, 1.0);
  for (int i = 0; i < L; ++i) {
    SampledBound& result = out[static_cast<std::size_t>(i)];
    result.largest = std::sqrt(largest.v[i]);
    result.second = std::sqrt(second.v[i]);
    result.within = within;
  }
}

BEZIER_FMA_CLONES SampledBound foot_bound(const std::array<Point2, 4>& c,
                                          const std::vector<Point2>& o, const ControlPoints& h2,
                                          double reach, int& taken) {
  std::array<SampledBound, 1> out;
  if (h2.size() <= 2) {
    foot_walk<1, true>({&c}, {&o}, h2, reach, out, taken);
  } else {
    foot_walk<1, false>({&c}, {&o}, h2, reach, out, taken);
  }
  return out[0];
}

/// foot_bound for the two sides of a piece of degree at most 3 at once (B_p'' linear): the
/// cubics `plus` and `minus` against their samples (the same count), each side's result
/// foot_bound's for it. False when a side's sample is beyond `reach` (the caller then judges
/// each side alone).
BEZIER_FMA_CLONES bool foot_bound_sides(const std::array<Point2, 4>& plus,
                                        const std::array<Point2, 4>& minus,
                                        const std::vector<Point2>& o_plus,
                                        const std::vector<Point2>& o_minus,
                                        const ControlPoints& h2, double reach,
                                        std::array<SampledBound, 2>& out, int& taken) {
  foot_walk<2, true>({&plus, &minus}, {&o_plus, &o_minus}, h2, reach, out, taken);
  return out[0].within;
}

/// The bound of offset.hpp where m is not positive: two balls about O(0), the cubic within
/// its control points' largest distance from O(0), O within max |B_p(u) - B_p(0)| + |d| θ
/// (θ the angle the nonzero first-hodograph control points span, when below π).
double ball_bound(const ControlPoints& q, const ControlPoints& h1, const std::array<Point2, 4>& c,
                  double d, Point2 start_normal) {
  Point2 reference{0, 0};
  for (const Point2 p : h1)
    if (squared_length(p) > 0.0) reference = reference + p / std::sqrt(squared_length(p));
  const double reference_squared = squared_length(reference);
  if (!(reference_squared > 0.0)) return std::numeric_limits<double>::infinity();
  const Point2 r = reference / std::sqrt(reference_squared);
  double lo = 0.0, hi = 0.0;
  for (const Point2 p : h1) {
    if (squared_length(p) == 0.0) continue;
    const double angle = std::atan2(core::cross(r, p), core::dot(r, p));
    lo = std::min(lo, angle);
    hi = std::max(hi, angle);
  }
  if (!(hi - lo < std::numbers::pi)) return std::numeric_limits<double>::infinity();
  const Point2 origin = q[0] + d * start_normal;
  double r_curve = 0.0, r_cubic = 0.0;
  for (const Point2 p : q) r_curve = std::max(r_curve, squared_length(p - q[0]));
  for (const Point2 p : c) r_cubic = std::max(r_cubic, squared_length(p - origin));
  return std::sqrt(r_curve) + std::fabs(d) * (hi - lo) + std::sqrt(r_cubic);
}

/// The K for which the remainder h^2 / 8 second is within `budget`.
int samples_for(double second, double budget) {
  return static_cast<int>(
      std::clamp(std::ceil(std::sqrt(second / (8.0 * budget))), 1.0, double{kMaxSamples}));
}

/// fit_piece's first K: the remainder within kFirstRemainder of the tolerance with |e''|
/// estimated at `estimate` (PieceShape::sample_estimate), at least kFitSamples. It depends on
/// |d| only: both sides of a piece share it.
int first_sample_count(double estimate, double tolerance) {
  return std::max(samples_for(estimate, kFirstRemainder * tolerance), kFitSamples);
}

/// A candidate's bound from its samples (offset.hpp): the largest sampled distance plus the
/// remainder h^2 / 8 |e''| (|e''| the sampled term, bend / K for degree above 3 and the bound
/// of |d N''|) and the end slack; how many times the room the remainder leaves the largest
/// sample is (to choose a split); and the bound of |e''|.
struct JudgedFit {
  double bound = std::numeric_limits<double>::infinity();
  double second = 0.0;
  double excess = std::numeric_limits<double>::infinity();
};

JudgedFit judged_fit(const SampledBound& sampled, double bend, double turning, int k,
                     double slack, double tolerance) {
  JudgedFit judged;
  judged.second = sampled.second + bend / k + turning;
  const double remainder = judged.second / (8.0 * k * k) + slack;
  if (sampled.within) {
    judged.excess = sampled.largest / std::max(tolerance - remainder, 0.25 * tolerance);
    judged.bound = sampled.largest + remainder;
  } else {
    judged.excess = sampled.largest / tolerance;
  }
  return judged;
}

/// The work of one candidate's bound on `taken` samples: per sample two evaluations of the
/// cubic and a step (further steps, at most kFootSteps at a sample, are rare: within a
/// constant of this).
std::int64_t judge_work(int taken) { return 36 * static_cast<std::int64_t>(taken); }

/// The chord frame of a fit with ends p0, p3 and end directions d0, d3 (offset.hpp) where the
/// moments are valid, and the area and moment cubic nearest an arc when they give one
/// (fit_piece's first candidate, found by the caller: arc_started_handles).
struct ChordFrame {
  Point2 p0{0, 0}, p3{0, 0}, d0{0, 0}, d3{0, 0};
  Point2 t0{0, 0}, t3{0, 0};  // d0, d3 in the frame of the chord
  double chord_length = 0.0;
  HandleLengths arc{-1.0, -1.0};
  bool arc_found = false;

  [[nodiscard]] std::array<Point2, 4> cubic_of(HandleLengths h) const {
    return {p0, p0 + (h.start * chord_length) * d0, p3 - (h.end * chord_length) * d3, p3};
  }
};

ChordFrame chord_frame(Point2 p0, Point2 p3, Point2 d0, Point2 d3, const ChordMoments& moments) {
  ChordFrame frame;
  frame.p0 = p0;
  frame.p3 = p3;
  frame.d0 = d0;
  frame.d3 = d3;
  if (moments.valid) {
    const Point2 chord = p3 - p0;
    frame.chord_length = std::sqrt(squared_length(chord));
    const Point2 axis = chord / frame.chord_length;
    frame.t0 = in_chord_frame(d0, axis);
    frame.t3 = in_chord_frame(d3, axis);
  }
  return frame;
}

/// The work fit_piece charges, n the degree: its ends and frames; `count` samples of O; the
/// chord moments and the first candidate's handles.
std::int64_t fit_setup_work(std::int64_t n) { return 8 * (n + 1) * (n + 1); }
std::int64_t sampling_work(std::int64_t n, int count) {
  return static_cast<std::int64_t>(count) * (n * (n + 1) + 12);
}
std::int64_t proposal_work(std::int64_t n) { return 8 * (n * (n + 1) + 24) + 100; }

/// The work fit_piece charges for a piece fitted at the first candidate on `count` samples
/// that took `taken` of them.
std::int64_t first_fit_work(std::int64_t n, int count, int taken) {
  return fit_setup_work(n) + sampling_work(n, count) + proposal_work(n) + judge_work(taken);
}

/// A fitted piece: its cubic and its certified bound (infinite when not certified), and how
/// many times the tolerance its largest sampled error was (to choose the split).
struct PieceFit {
  std::array<Point2, 4> cubic;
  double bound = std::numeric_limits<double>::infinity();
  double excess = 2.0;
  std::int64_t work = 0;
};

/// Fits the piece q ([a, b] of s) between the end frames and bounds the fit (offset.hpp).
/// O is sampled once, at K + 1 uniform t (K from the bound of |d N''|, at least
/// kFitSamples); the area and moment cubics are tried first, then the least squares on the
/// same samples, each bounded on them (and on denser ones where the remainder alone fails),
/// the first within the tolerance kept.
PieceFit fit_piece(const ScaledCurve& s, double a, double b, const ControlPoints& q,
                   const EndFrame& start, const EndFrame& end, double d, double tolerance,
                   double direction, std::vector<Point2>& o, bool zero_start, bool zero_end,
                   const PieceShape* given = nullptr,
                   bool presampled = false, const ChordMoments* given_moments = nullptr) {
  PieceFit result;
  if (q.size() == 2 || s.point) {
    // A line's parallel curve is the line through the offset ends: the cubic with its
    // handles a third of the chord along the line from each end, exact. (A curve that is
    // one point, of any degree, is taken as the line of zero length it is, its normal
    // end_tangent's convention: one point.)
    const Point2 n0 = left_normal(start.tangent);
    const Point2 p0 = start.point + d * n0, p3 = end.point + d * n0;
    const double third = std::sqrt(squared_length(p3 - p0)) / 3.0;
    result.cubic = {p0, p0 + third * start.tangent, p3 - third * start.tangent, p3};
    result.bound = 0.0;
    result.work = 16;
    return result;
  }
  if (given == nullptr) {
    // The piece's shape on the stack (not in a std::optional, whose payload would be
    // zero-filled at every call).
    const PieceShape own(s, a, b, zero_start, zero_end);
    return fit_piece(s, a, b, q, start, end, d, tolerance, direction, o, zero_start, zero_end,
                     &own, presampled, given_moments);
  }
  const auto n = static_cast<std::int64_t>(q.size()) - 1;
  const PieceShape& shape = *given;
  const Point2 n0 = left_normal(start.tangent), n1 = left_normal(end.tangent);
  const Point2 p0 = start.point + d * n0, p3 = end.point + d * n1;
  const Point2 d0 = direction * start.tangent, d3 = direction * end.tangent;
  result.work = fit_setup_work(n);
  // Where B' vanishes at an end, the end frame's normal against the limit Q gives.
  const double slack = shape.end_slack(start, end, d);
  if (shape.w > 0.0) {
    const double turning = shape.normal_second(d);
    // Between samples, |B_p'' - its linear interpolant| <= M3 h / 2 (zero when n <= 3).
    const double bend = q.size() > 4 ? 0.5 * shape.M3 : 0.0;
    // K for a remainder within kFirstRemainder of the tolerance with |e''| estimated from
    // the hodographs (first_sample_count).
    const int count = first_sample_count(shape.sample_estimate(d), tolerance);
    const CubicWeights& weights = cubic_weights(count);
    if (!presampled && !sample_parallel(q, shape.h1, d, p0, p3, weights, o)) return result;
    result.work += sampling_work(n, count);
    // The candidates: the area and moment cubic nearest an arc, then the others of
    // area_moment_fit.hpp, then the least squares.
    // Each candidate's handle lengths (its cubic built when it is judged), the least squares
    // cubic, always last, apart: no array of cubics to fill at every call.
    std::array<HandleLengths, 5> candidates;
    std::array<Point2, 4> least_squares_cubic;
    std::size_t candidate_count = 0;
    const ChordMoments moments = given_moments != nullptr
                                     ? *given_moments
                                     : chord_moments(q, shape.h1, shape.h2, d, p0, p3);
    result.work += proposal_work(n);
    ChordFrame frame = chord_frame(p0, p3, d0, d3, moments);
    frame.arc_found = moments.valid && arc_started_handles(frame.t0, frame.t3, moments.area,
                                                           moments.moment, frame.arc);
    const Point2 t0 = frame.t0, t3 = frame.t3;
    const HandleLengths arc = frame.arc;
    auto cubic_of = [&](HandleLengths h) { return frame.cubic_of(h); };
    if (frame.arc_found) candidates[candidate_count++] = arc;
    bool searched = !moments.valid, least_squares = false;
    // The bound of offset.hpp for the cubic c on K samples of O.
    auto judge = [&](const std::array<Point2, 4>& c, const std::vector<Point2>& samples,
                     int k, double& largest) {
      int taken = 0;
      const SampledBound sampled = foot_bound(c, samples, shape.h2, tolerance, taken);
      result.work += judge_work(taken);
      largest = sampled.largest;
      const JudgedFit judged = judged_fit(sampled, bend, turning, k, slack, tolerance);
      result.excess = std::min(result.excess, judged.excess);
      return std::pair{judged.bound, judged.second};
    };
    result.excess = std::numeric_limits<double>::infinity();
    for (std::size_t tried = 0;; ++tried) {
      if (tried == candidate_count && !searched) {
        searched = true;
        result.work += 400;
        const HandleCandidates handles =
            area_moment_handles(t0, t3, moments.area, moments.moment);
        for (std::size_t i = 0; i < handles.count; ++i) {
          const HandleLengths h = handles.pairs[i];
          if (std::fabs(h.start - arc.start) + std::fabs(h.end - arc.end) > 1e-9)
            candidates[candidate_count++] = h;
        }
      }
      if (tried == candidate_count) {
        if (least_squares) break;
        least_squares_cubic = fit(o, weights, true, d0, d3);
        least_squares = true;
        ++candidate_count;
      }
      const std::array<Point2, 4> c = least_squares && tried + 1 == candidate_count
                                          ? least_squares_cubic
                                          : cubic_of(candidates[tried]);
      double largest = 0.0;
      auto [bound, second] = judge(c, o, count, largest);
      // The samples are within the tolerance and the remainder alone fails: K for the
      // remainder to fit in kDenserRoom of the room the samples leave, with |e''| estimated
      // at kDenserEstimate times the sampled one, and the bound again on those samples; once
      // more if that fails too and the next K is a quarter denser.
      int judged = count;
      for (int denser = 0; denser < kDenserTries; ++denser) {
        const double room = kDenserRoom * (tolerance - largest);
        if (!(std::isfinite(bound) && bound > tolerance && largest < kDenserBelow * tolerance))
          break;
        const int more = samples_for(kDenserEstimate * second, room);
        if (!(more > (denser == 0 ? judged : judged + judged / 4))) break;
        std::vector<Point2>& dense = dense_buffer();
        if (!sample_parallel(q, shape.h1, d, p0, p3, cubic_weights(more), dense)) return result;
        result.work += sampling_work(n, more);
        std::tie(bound, second) = judge(c, dense, more, largest);
        judged = more;
      }
      if (tried == 0 || bound < result.bound) {
        result.bound = std::min(result.bound, bound);
        result.cubic = c;
      }
      if (result.bound <= tolerance) return result;
    }
  } else {
    const CubicWeights& weights = cubic_weights(kBallSamples);
    const bool all_numbers = sample_parallel(q, shape.h1, d, p0, p3, weights, o);
    result.work += sampling_work(n, kBallSamples);
    result.cubic = fit(o, weights, all_numbers, d0, d3);
  }
  result.bound = std::min(result.bound, ball_bound(q, shape.h1, result.cubic, d, n0) + slack);
  return result;
}

/// The directions of O at the distances ds (scaled) on [a, b]: the sign of 1 - d κ at its
/// middle, for each d.
template <std::size_t N>
std::array<double, N> travel_directions(const ScaledCurve& s, const std::array<double, N>& ds,
                                        double a, double b) {
  const double middle = 0.5 * (a + b);
  const Point2 v = s.first.empty() ? Point2{0, 0} : point_at(s.first, middle);
  const Point2 acc = s.second.empty() ? Point2{0, 0} : point_at(s.second, middle);
  const double speed = std::sqrt(squared_length(v));
  std::array<double, N> out{};
  for (std::size_t c = 0; c < N; ++c) {
    out[c] = speed > 0.0 && ds[c] * core::cross(v, acc) / (speed * speed * speed) > 1.0 ? -1.0
                                                                                        : 1.0;
  }
  return out;
}

double travel_direction(const ScaledCurve& s, double d, double a, double b) {
  return travel_directions<1>(s, {d}, a, b)[0];
}

/// The parallel curve of [a, b] of a straight curve (offset.hpp): B([a, b]) is the segment
/// from B(a) to B(b) on the line (B' keeps its direction inside, no zero of B' being inside),
/// moved by d N with N the left normal of the direction of travel T, constant on [a, b]; the
/// cubics are that segment cut where it passes B at another turn of the curve (s.turns; t
/// there by bisection, B being monotone along the line on [a, b]), each with its handles a
/// third of the way along it. T is ± the line's direction (ScaledCurve::line), the sign of
/// the chord's projection on it where the chord is longer than 1e-12 of the curve's size
/// (beyond the rounding of B(a) and B(b)), else that of the start frame's tangent (the limit
/// one where B' vanishes there). Each cubic's bound is the largest distance of its part's
/// control points from its segment [W_i, W_{i+1}] and of B at the part's ends from W_i and
/// W_{i+1}: O on the part lies within it of the cubic (B's values lie in the control points'
/// hull, and the distance to a segment is convex), and the cubic within it of O (B takes
/// every value between its ends). False (nothing appended) where a bound exceeds the
/// tolerance (a cut at a zero of B' rounded so far that B turns back inside [a, b]): the
/// general fit then decides. Work: the bisections' evaluations, charged to `budget`.
bool straight_interval(const ScaledCurve& s, double d, double a, double b, double tolerance,
                       core::WorkBudget& budget, std::vector<OffsetCubic>& out) {
  const Point2 start = point_at(s.points, a), end = point_at(s.points, b);
  const Point2 chord = end - start;
  const double chord_squared = squared_length(chord);
  const double size = std::sqrt(largest_squared_length(s.points));
  const Point2 travel =
      chord_squared > 1e-24 * size * size ? chord : s.frame(a, a, b, true).tangent;
  const Point2 tangent = core::dot(travel, s.line) < 0.0 ? -s.line : s.line;
  // The parts' ends W_i and their parameters: the turns strictly between B(a) and B(b) along
  // the direction of travel, in that order.
  auto along = [&](Point2 p) { return core::dot(p - s.points[0], tangent); };
  const double from = along(start), to = along(end);
  struct Cut {
    double position;
    Point2 point;
    double t;
  };
  std::vector<Cut> cuts{{from, start, a}};
  for (const Point2 v : s.turns) {
    const double x = along(v);
    if (x > from && x < to) cuts.push_back({x, v, 0.0});
  }
  std::sort(cuts.begin() + 1, cuts.end(), [](const Cut& l, const Cut& r) { return l.position < r.position; });
  cuts.erase(std::unique(cuts.begin() + 1, cuts.end(),
                         [](const Cut& l, const Cut& r) { return l.point == r.point; }),
             cuts.end());
  cuts.push_back({to, end, b});
  const auto n = static_cast<std::int64_t>(s.points.size()) - 1;
  for (std::size_t i = 1; i + 1 < cuts.size(); ++i) {
    double lo = a, hi = b;
    for (int k = 0; k < 64 && lo < hi; ++k) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      (along(point_at(s.points, mid)) < cuts[i].position ? lo : hi) = mid;
    }
    cuts[i].t = std::max(hi, cuts[i - 1].t);
    if (!budget.spend(64 * (n + 1) * (n + 1))) return false;
  }
  const Point2 shift = d * left_normal(tangent);
  const std::size_t kept = out.size();
  ControlPoints q;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const Cut& c0 = cuts[i];
    const Cut& c1 = cuts[i + 1];
    const Point2 w = c1.point - c0.point;
    const double w_squared = squared_length(w);
    double farthest = std::max(squared_length(point_at(s.points, c0.t) - c0.point),
                               squared_length(point_at(s.points, c1.t) - c1.point));
    if (c1.t > c0.t) {
      piece_into(s.points, c0.t, c1.t, q);
      for (const Point2 p : q) {
        const Point2 r = p - c0.point;
        const double share =
            w_squared > 0.0 ? std::clamp(core::dot(r, w) / w_squared, 0.0, 1.0) : 0.0;
        farthest = std::max(farthest, squared_length(r - share * w));
      }
    }
    const double bound = std::sqrt(farthest);
    if (!(bound <= tolerance)) {
      out.resize(kept);
      return false;
    }
    const Point2 p0 = c0.point + shift, p3 = c1.point + shift;
    OffsetCubic cubic{c0.t, c1.t, {}, 0.0};
    const std::array<Point2, 4> points{p0, p0 + (1.0 / 3.0) * (p3 - p0),
                                       p3 - (1.0 / 3.0) * (p3 - p0), p3};
    for (std::size_t k = 0; k < 4; ++k) cubic.points[k] = s.back.times(points[k]);
    cubic.error_bound = s.back.times(bound + s.margin);
    out.push_back(cubic);
  }
  return true;
}

/// What the caller of fit_interval already has for the whole [a, b] at d: the end frames,
/// O's direction there, and fit_piece's fit of [a, b].
struct FirstPiece {
  EndFrame start, end;
  double direction = 1.0;
  PieceFit fit;
  bool zero_start = false, zero_end = false;  // |B'| below the threshold at a, at b
};

/// Fits [a, b] of the scaled curve at the scaled distance d (s.d or -s.d), splitting where
/// the bound fails; appends the cubics (scaled back) to `out`. `first`, when given, is the
/// whole [a, b]'s (FirstPiece).
bool fit_interval(const ScaledCurve& s, double d, double a, double b, core::WorkBudget& budget,
                  std::vector<OffsetCubic>& out, const FirstPiece* first = nullptr) {
  const std::size_t kept = out.size();
  const auto n = static_cast<std::int64_t>(s.points.size()) - 1;
  if (first == nullptr && s.straight && !s.point && n > 1) {
    // The interval's piece and frames, and the curve's turns (stationary_points' root search,
    // as offset_curve charges it).
    if (!budget.spend(16 * (n + 1) * (n + 1) + 64 * n * n * n)) return false;
    if (straight_interval(s, d, a, b, s.tolerance - s.margin, budget, out)) return true;
    if (budget.exhausted()) return false;
  }
  if (first != nullptr && first->fit.bound + s.margin <= s.tolerance) {
    // The whole [a, b] kept at its first fit (the common case), as the loop below keeps it,
    // without stacking it.
    if (!budget.spend(first->fit.work + 16 * (n + 1) * (n + 1))) return false;
    OffsetCubic cubic{a, b, {}, 0.0};
    for (std::size_t i = 0; i < 4; ++i) cubic.points[i] = s.back.times(first->fit.cubic[i]);
    cubic.error_bound = s.back.times(first->fit.bound + s.margin);
    out.push_back(cubic);
    return true;
  }
  const double direction = first != nullptr ? first->direction : travel_direction(s, d, a, b);

  struct Pending {
    double a, b;
    EndFrame start, end;
    int depth;
  };
  // Depth-first, leftmost part on top (one buffer per thread, reused).
  thread_local std::vector<Pending> stack;
  stack.clear();
  if (first != nullptr) {
    stack.push_back({a, b, first->start, first->end, 0});
  } else {
    stack.push_back({a, b, s.frame(a, a, b, true), s.frame(b, a, b, false), 0});
  }
  ControlPoints q;
  std::vector<Point2>& samples = sample_buffer();
  const bool zero_start = first != nullptr ? first->zero_start : s.stationary(a);
  const bool zero_end = first != nullptr ? first->zero_end : s.stationary(b);
  while (!stack.empty()) {
    const Pending piece = stack.back();
    stack.pop_back();
    PieceFit own;
    if (first == nullptr) {
      piece_into(s.points, piece.a, piece.b, q);
      own = fit_piece(s, piece.a, piece.b, q, piece.start, piece.end, d,
                      s.tolerance - s.margin, direction, samples,
                      zero_start && piece.a == a, zero_end && piece.b == b);
    }
    const PieceFit& fitted = first != nullptr ? first->fit : own;
    first = nullptr;
    if (!budget.spend(fitted.work + 16 * (n + 1) * (n + 1))) {
      out.resize(kept);
      return false;
    }
    if (fitted.bound + s.margin <= s.tolerance) {
      OffsetCubic cubic{piece.a, piece.b, {}, 0.0};
      for (std::size_t i = 0; i < 4; ++i) cubic.points[i] = s.back.times(fitted.cubic[i]);
      cubic.error_bound = s.back.times(fitted.bound + s.margin);
      out.push_back(cubic);
      continue;
    }
    if (piece.depth >= kMaxDepth) {
      budget.exhaust();
      out.resize(kept);
      return false;
    }
    // The error of a fit falls about as the fifth power of the piece's length: parts enough
    // for the sampled excess (a lower bound of the error's), at least two.
    const int parts = static_cast<int>(
        std::clamp(std::ceil(std::pow(fitted.excess, 0.2)), 2.0, double{kMostParts}));
    EndFrame right = piece.end;
    for (int k = parts - 1; k >= 0; --k) {
      const double t0 = k == 0 ? piece.a : piece.a + (piece.b - piece.a) * k / parts;
      const double t1 = k == parts - 1 ? piece.b : piece.a + (piece.b - piece.a) * (k + 1) / parts;
      const EndFrame left = k == 0 ? piece.start : s.frame(t0, t0, t1, true);
      stack.push_back({t0, t1, left, right, piece.depth + 1});
      right = left;
    }
  }
  return true;
}

/// fit_piece's fits of both sides of a piece of degree at most 3 at d and -d, where both
/// pass at their first candidate, the area and moment cubic nearest an arc: judged together
/// (foot_bound_sides), each fit (cubic, bound, excess, work) the one fit_piece gives. False,
/// leaving the fits alone, where either side has no such candidate or its bound fails.
bool first_fits_of_sides(const ControlPoints& q, const PieceShape& shape,
                         const EndFrame& start, const EndFrame& end, double d, int count,
                         double tolerance, FirstPiece& plus, FirstPiece& minus,
                         const std::vector<Point2>& plus_samples,
                         const std::vector<Point2>& minus_samples,
                         const std::array<ChordMoments, 2>& moments) {
  const std::array<double, 2> ds{d, -d};
  const std::array<FirstPiece*, 2> pieces{&plus, &minus};
  std::array<ChordFrame, 2> frames;
  const Point2 n0 = left_normal(start.tangent), n1 = left_normal(end.tangent);
  if (!moments[0].valid || !moments[1].valid) return false;
  for (std::size_t i = 0; i < 2; ++i) {
    const double side = ds[i], direction = pieces[i]->direction;
    frames[i] = chord_frame(start.point + side * n0, end.point + side * n1,
                            direction * start.tangent, direction * end.tangent, moments[i]);
  }
  std::array<HandleLengths, 2> arcs{frames[0].arc, frames[1].arc};
  const std::array<bool, 2> found = arc_started_handles_of_two(
      {frames[0].t0, frames[1].t0}, {frames[0].t3, frames[1].t3},
      {moments[0].area, moments[1].area}, {moments[0].moment, moments[1].moment}, arcs);
  if (!found[0] || !found[1]) return false;
  frames[0].arc = arcs[0];
  frames[1].arc = arcs[1];
  const std::array<std::array<Point2, 4>, 2> cubics{frames[0].cubic_of(frames[0].arc),
                                                    frames[1].cubic_of(frames[1].arc)};
  std::array<SampledBound, 2> sampled;
  int taken = 0;
  if (!foot_bound_sides(cubics[0], cubics[1], plus_samples, minus_samples, shape.h2, tolerance,
                        sampled, taken)) {
    return false;
  }
  std::array<JudgedFit, 2> judged;
  for (std::size_t i = 0; i < 2; ++i) {
    judged[i] = judged_fit(sampled[i], 0.0, shape.normal_second(ds[i]), count,
                           shape.end_slack(start, end, ds[i]), tolerance);
    if (!(judged[i].bound <= tolerance)) return false;
  }
  const auto n = static_cast<std::int64_t>(q.size()) - 1;
  for (std::size_t i = 0; i < 2; ++i) {
    PieceFit& fit = pieces[i]->fit;
    fit.cubic = cubics[i];
    fit.bound = judged[i].bound;
    fit.excess = judged[i].excess;
    fit.work = first_fit_work(n, count, taken);
  }
  return true;
}

}  // namespace

bool offset_interval(const core::Curve& curve, double a, double b, double d, double tolerance,
                     core::WorkBudget& budget, std::vector<OffsetCubic>& out) {
  const ScaledCurve scaled(curve, d, tolerance);
  return fit_interval(scaled, scaled.d, a, b, budget, out);
}

BEZIER_FMA_CLONES bool offset_interval_sides(const core::Curve& curve, double a, double b,
                                             double d, double tolerance,
                                             core::WorkBudget& budget,
                                             std::vector<OffsetCubic>& plus,
                                             std::vector<OffsetCubic>& minus) {
  const ScaledCurve s(curve, d, tolerance);
  ControlPoints q;
  piece_into(s.points, a, b, q);
  const Point2 start_velocity = s.velocity(a), end_velocity = s.velocity(b);
  const bool zero_start = s.stationary_at(start_velocity), zero_end = s.stationary_at(end_velocity);
  // A line, or a piece whose fit needs no samples of its own kind: each side alone.
  auto each_side_alone = [&] {
    if (!fit_interval(s, s.d, a, b, budget, plus)) return false;
    return fit_interval(s, -s.d, a, b, budget, minus);
  };
  if (q.size() <= 2 || s.point) return each_side_alone();
  const PieceShape shape(s, a, b, zero_start, zero_end);
  if (!(shape.w > 0.0) || s.straight) return each_side_alone();
  const EndFrame start = s.frame_at(a, start_velocity, a, b, true);
  const EndFrame end = s.frame_at(b, end_velocity, a, b, false);
  const double tolerance_left = s.tolerance - s.margin;
  // The sample count of fit_piece depends on |d| only, so both sides share it.
  const int count = first_sample_count(shape.sample_estimate(s.d), tolerance_left);
  const CubicWeights& weights = cubic_weights(count);
  std::vector<Point2>& plus_samples = sample_buffer();
  std::vector<Point2>& minus_samples = side_buffer();
  const bool sampled = sample_both_sides(q, shape.h1, s.d, start, end, weights, plus_samples,
                                         minus_samples);
  const std::array<double, 2> directions = travel_directions<2>(s, {s.d, -s.d}, a, b);
  FirstPiece plus_first{start, end, directions[0], {}, zero_start, zero_end};
  FirstPiece minus_first{start, end, directions[1], {}, zero_start, zero_end};
  // The chord moments of both sides from one evaluation of B_p, B_p', B_p'' per node; the
  // ends as fit_piece's (the samples' first and last).
  const std::array<ChordMoments, 2> moments =
      chord_moments_of_sides(q, shape.h1, shape.h2, s.d,
                             {plus_samples.front(), minus_samples.front()},
                             {plus_samples.back(), minus_samples.back()});
  // Where B_p'' is linear (degree <= 3), both sides' first candidates are judged at once
  // (foot_bound_sides); when both hold, they are fit_piece's fits; otherwise each side is
  // fitted alone.
  if (!(sampled && q.size() <= 4 && first_fits_of_sides(q, shape, start, end, s.d, count,
                                                        tolerance_left, plus_first,
                                                        minus_first, plus_samples,
                                                        minus_samples, moments))) {
    plus_first.fit = fit_piece(s, a, b, q, start, end, s.d, tolerance_left,
                               plus_first.direction, plus_samples, zero_start, zero_end,
                               &shape, sampled, &moments[0]);
    minus_first.fit = fit_piece(s, a, b, q, start, end, -s.d, tolerance_left,
                                minus_first.direction, minus_samples, zero_start, zero_end,
                                &shape, sampled, &moments[1]);
  }
  if (!fit_interval(s, s.d, a, b, budget, plus, &plus_first)) return false;
  return fit_interval(s, -s.d, a, b, budget, minus, &minus_first);
}

CurveOffset offset_curve(const core::Curve& curve, double d, double tolerance,
                         core::WorkBudget& budget) {
  CurveOffset result;
  std::vector<double> cuts{0.0, 1.0};
  std::int64_t cusp_work = 0;
  for (const double t : offset_cusps(curve, d, &cusp_work)) cuts.push_back(t);
  for (const double t : stationary_points(curve)) cuts.push_back(t);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  const auto n = static_cast<std::int64_t>(curve.degree());
  budget.charge(64 * n * n * n + cusp_work);
  const ScaledCurve scaled(curve, d, tolerance);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    if (!(cuts[k + 1] > cuts[k])) continue;
    if (!fit_interval(scaled, scaled.d, cuts[k], cuts[k + 1], budget, result.cubics)) {
      result.cubics.clear();
      break;
    }
  }
  return result;
}

}  // namespace bezier::outline
