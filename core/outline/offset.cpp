#include "core/outline/offset.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/curve/evaluate.hpp"
#include "core/curve/polar.hpp"
#include "core/outline/offset_cusps.hpp"
#include "core/outline/tangent_limits.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

constexpr int kFitSamples = 16;
constexpr int kMaxSamples = 4096;
constexpr int kMaxDepth = 40;

std::vector<Point2> hodograph(std::span<const Point2> p) {
  const double n = static_cast<double>(p.size() - 1);
  std::vector<Point2> h;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) h.push_back(n * (p[i + 1] - p[i]));
  return h;
}

Point2 plain_point(std::vector<Point2> q, double t) {
  for (std::size_t k = q.size() - 1; k > 0; --k)
    for (std::size_t i = 0; i < k; ++i) q[i] = core::lerp(q[i], q[i + 1], t);
  return q.front();
}

double largest_norm(const std::vector<Point2>& q) {
  double m = 0.0;
  for (const Point2 p : q) m = std::max(m, core::length(p));
  return m;
}

Point2 left_normal(Point2 unit) {
  return {-unit.y, unit.x};
}

struct PieceBound {
  double bound = std::numeric_limits<double>::infinity();
  std::int64_t work = 0;
};

/// The certified bound of offset.hpp for the piece with control points q (local parameter u)
/// and the cubic c.
PieceBound bound_piece(const std::vector<Point2>& q, const std::array<Point2, 4>& c, double d,
                       double tolerance, Point2 start_normal, Point2 end_normal) {
  PieceBound result;
  const auto n = static_cast<std::int64_t>(q.size()) - 1;
  const std::vector<Point2> h1 = hodograph(q);
  const std::vector<Point2> h2 = h1.size() > 1 ? hodograph(h1) : std::vector<Point2>{{0, 0}};
  const std::vector<Point2> h3 = h2.size() > 1 ? hodograph(h2) : std::vector<Point2>{{0, 0}};
  const double M1 = largest_norm(h1), M2 = largest_norm(h2), M3 = largest_norm(h3);
  const Point2 mid = plain_point(h1, 0.5);
  const double mid_len = core::length(mid);
  double m = 0.0;
  if (mid_len > 0.0) {
    m = std::numeric_limits<double>::infinity();
    for (const Point2 p : h1) m = std::min(m, core::dot(p, mid / mid_len));
  }
  const double c2 = 6.0 * std::max({core::length(c[2] - 2.0 * c[1] + c[0]),
                                    core::length(c[3] - 2.0 * c[2] + c[1])});
  result.work = 8 * (n + 1) * (n + 1);
  if (m > 0.0) {
    const double w = M1 * M2 / (m * m);
    const double w1 = M1 * M3 / (m * m) + 2.0 * w * w;
    const double o2 = M2 + std::fabs(d) * (w1 + w * w);
    const double second = c2 + o2;
    const int samples = static_cast<int>(
        std::clamp(std::ceil(std::sqrt(second / (2.0 * tolerance))), 1.0, double{kMaxSamples}));
    const double h = 1.0 / samples;
    double largest = 0.0;
    const std::vector<Point2> cubic(c.begin(), c.end());
    for (int j = 0; j <= samples; ++j) {
      const double u = j == samples ? 1.0 : j * h;
      Point2 normal;
      if (j == 0) {
        normal = start_normal;
      } else if (j == samples) {
        normal = end_normal;
      } else {
        const Point2 v = plain_point(h1, u);
        const double len = core::length(v);
        if (!(len > 0.0)) {
          largest = std::numeric_limits<double>::infinity();
          break;
        }
        normal = left_normal(v / len);
      }
      const Point2 o = plain_point(q, u) + d * normal;
      largest = std::max(largest, core::length(plain_point(cubic, u) - o));
    }
    result.work += static_cast<std::int64_t>(samples + 1) * (n * (n + 1) + 12);
    result.bound = largest + h * h / 8.0 * second;
  }
  // The two balls about O(0).
  Point2 reference{0, 0};
  for (const Point2 p : h1)
    if (core::length(p) > 0.0) reference = reference + p / core::length(p);
  const double reference_len = core::length(reference);
  if (reference_len > 0.0) {
    const Point2 r = reference / reference_len;
    double lo = 0.0, hi = 0.0;
    for (const Point2 p : h1) {
      if (core::length(p) == 0.0) continue;
      const double angle = std::atan2(core::cross(r, p), core::dot(r, p));
      lo = std::min(lo, angle);
      hi = std::max(hi, angle);
    }
    if (hi - lo < std::numbers::pi) {
      const Point2 origin = q.front() + d * start_normal;
      double r_curve = 0.0, r_cubic = 0.0;
      for (const Point2 p : q) r_curve = std::max(r_curve, core::length(p - q.front()));
      for (const Point2 p : c) r_cubic = std::max(r_cubic, core::length(p - origin));
      result.bound = std::min(result.bound, r_curve + std::fabs(d) * (hi - lo) + r_cubic);
    }
  }
  return result;
}

/// The cubic of offset.hpp for the piece q: ends O(0), O(1), tangents ±T, handles by least
/// squares.
std::array<Point2, 4> fit(const std::vector<Point2>& q, double d, Point2 t0, Point2 t1,
                          double direction) {
  const Point2 p0 = q.front() + d * left_normal(t0);
  const Point2 p3 = q.back() + d * left_normal(t1);
  const Point2 d0 = direction * t0, d3 = direction * t1;
  const std::vector<Point2> h1 = hodograph(q);
  double a11 = 0, a12 = 0, a22 = 0, r1 = 0, r2 = 0;
  for (int j = 1; j < kFitSamples; ++j) {
    const double u = static_cast<double>(j) / kFitSamples, v = 1.0 - u;
    const Point2 tangent = plain_point(h1, u);
    const double len = core::length(tangent);
    if (!(len > 0.0)) continue;
    const Point2 o = plain_point(q, u) + d * left_normal(tangent / len);
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
  const double chord = core::length(p3 - p0);
  double alpha = chord / 3, beta = chord / 3;
  if (std::fabs(det) > 1e-12 * a11 * a22) {
    alpha = (r1 * a22 - r2 * a12) / det;
    beta = (a11 * r2 - a12 * r1) / det;
  }
  return {p0, p0 + alpha * d0, p3 - beta * d3, p3};
}

}  // namespace

CurveOffset offset_curve(const core::Curve& curve, double d, double tolerance,
                         std::int64_t work_left) {
  CurveOffset result;
  std::vector<double> cuts{0.0, 1.0};
  for (const double t : offset_cusps(curve, d)) cuts.push_back(t);
  for (const double t : stationary_points(curve)) cuts.push_back(t);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  const auto n = static_cast<std::int64_t>(curve.degree());
  result.work += 64 * n * n * n;
  const double margin = 64.0 * static_cast<double>(n) * std::numeric_limits<double>::epsilon() *
                        (core::scale(curve) + std::fabs(d));

  struct Pending {
    double a, b;
    int depth;
  };
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    if (!(cuts[k + 1] > cuts[k])) continue;
    std::vector<Pending> stack{{cuts[k], cuts[k + 1], 0}};
    // The direction of O on this piece: the sign of 1 - d κ at its middle.
    const core::Curve around = core::portion(curve, cuts[k], cuts[k + 1]);
    const std::vector<Point2> h1 = hodograph(around.points());
    const std::vector<Point2> h2 = h1.size() > 1 ? hodograph(h1) : std::vector<Point2>{{0, 0}};
    const Point2 v = plain_point(h1, 0.5), acc = plain_point(h2, 0.5);
    const double speed = core::length(v);
    const double direction =
        speed > 0.0 && d * core::cross(v, acc) / (speed * speed * speed) > 1.0 ? -1.0 : 1.0;
    while (!stack.empty()) {
      const Pending piece = stack.back();
      stack.pop_back();
      const core::Curve part = core::portion(curve, piece.a, piece.b);
      const std::vector<Point2> q(part.points().begin(), part.points().end());
      const Point2 t0 = end_tangent(q, true), t1 = end_tangent(q, false);
      const std::array<Point2, 4> c = fit(q, d, t0, t1, direction);
      const PieceBound bound = bound_piece(q, c, d, tolerance, left_normal(t0), left_normal(t1));
      result.work += bound.work + 16 * (n + 1) * (n + 1) * 4;
      if (result.work > work_left) {
        result.status = OffsetStatus::work_cap_reached;
        result.cubics.clear();
        return result;
      }
      if (bound.bound + margin <= tolerance || piece.depth >= kMaxDepth) {
        if (!(bound.bound + margin <= tolerance)) {
          result.status = OffsetStatus::work_cap_reached;
          result.cubics.clear();
          return result;
        }
        result.cubics.push_back({piece.a, piece.b, c, bound.bound + margin});
        continue;
      }
      const double mid = 0.5 * (piece.a + piece.b);
      stack.push_back({mid, piece.b, piece.depth + 1});
      stack.push_back({piece.a, mid, piece.depth + 1});
    }
  }
  return result;
}

}  // namespace bezier::outline
