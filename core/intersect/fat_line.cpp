#include "core/intersect/fat_line.hpp"

#include <cmath>

#include "core/intersect/bernstein1d.hpp"

namespace bezier::core {

namespace {

constexpr double kU = bernstein::kU;

/// Largest |coordinate - origin| over a piece's control points.
double reach(const Piece& p, Point2 origin) noexcept {
  double r = 0.0;
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    r = bernstein::max2(
        r, bernstein::max2(std::fabs(p.x[i] - origin.x), std::fabs(p.y[i] - origin.y)));
  }
  return r;
}

Point2 chord(const Piece& p) noexcept {
  return {p.x.back() - p.x[0], p.y.back() - p.y[0]};
}

}  // namespace

bool is_point_like(const Piece& p) noexcept {
  const double limit = 4 * p.error;
  for (std::size_t i = 1; i < p.x.size(); ++i) {
    if (std::fabs(p.x[i] - p.x[0]) > limit || std::fabs(p.y[i] - p.y[0]) > limit) return false;
  }
  return true;
}

FatLine fat_line(const Piece& g, const Piece& other, PointLineDirection direction) {
  const std::size_t m = g.x.size() - 1;
  const Point2 origin = {g.x[0], g.y[0]};
  Point2 d = chord(g);
  const double limit = 4 * g.error;
  if (bernstein::max2(std::fabs(d.x), std::fabs(d.y)) <= limit) {
    // Closed or nearly closed piece: use the farthest control point instead.
    double best = 0.0;
    for (std::size_t j = 1; j <= m; ++j) {
      const Point2 v = {g.x[j] - origin.x, g.y[j] - origin.y};
      const double size = bernstein::max2(std::fabs(v.x), std::fabs(v.y));
      if (size > best) {
        best = size;
        d = v;
      }
    }
    if (best <= limit) {
      // A point: orient by the other piece.
      Point2 c = chord(other);
      if (c.x == 0.0 && c.y == 0.0) c = {1.0, 0.0};
      d = direction == PointLineDirection::across_other ? Point2{-c.y, c.x} : c;
    }
  }
  FatLine line;
  line.origin = origin;
  line.normal = {-d.y, d.x};
  const double n1 = std::fabs(line.normal.x) + std::fabs(line.normal.y);
  // Every exact distance is within e of the computed one: the piece's error moves a point
  // by g.error per coordinate, and the difference, two products and the sum round once each.
  const double e = n1 * (g.error + 3.01 * kU * reach(g, origin));
  Coeffs dist(m + 1);
  for (std::size_t j = 0; j <= m; ++j) {
    dist[j] = line.normal.x * (g.x[j] - origin.x) + line.normal.y * (g.y[j] - origin.y);
  }
  double lo = 0.0, hi = 0.0;
  if (m == 3 || m == 2) {
    // The exact end distances are within e of 0 (the line passes through the computed end
    // points), which adds e; the interior ones are within e of d_j, scaled by c <= 1.
    double c = 0.5;
    if (m == 3) {
      const bool opposite =
          (dist[1] - e > 0 && dist[2] + e < 0) || (dist[1] + e < 0 && dist[2] - e > 0);
      c = opposite ? 4.0 / 9.0 : 0.75;
    }
    for (std::size_t j = 1; j < m; ++j) {
      lo = bernstein::min2(lo, c * (dist[j] - e));
      hi = bernstein::max2(hi, c * (dist[j] + e));
    }
    lo -= e;
    hi += e;
  } else {
    for (std::size_t j = 0; j <= m; ++j) {
      lo = bernstein::min2(lo, dist[j]);
      hi = bernstein::max2(hi, dist[j]);
    }
    lo -= e;
    hi += e;
  }
  // The products c (d +- e) and the sums above round too: a relative hair more.
  const double slack = 4 * kU * (std::fabs(lo) + std::fabs(hi));
  line.d_min = lo - slack;
  line.d_max = hi + slack;
  line.margin = e + slack;
  return line;
}

DistanceCoefficients distance_coefficients(const FatLine& line, const Piece& f) {
  DistanceCoefficients out;
  const std::size_t n = f.x.size();
  out.a.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.a[i] = line.normal.x * (f.x[i] - line.origin.x) + line.normal.y * (f.y[i] - line.origin.y);
  }
  const double n1 = std::fabs(line.normal.x) + std::fabs(line.normal.y);
  out.error = n1 * (f.error + 3.01 * kU * reach(f, line.origin));
  return out;
}

}  // namespace bezier::core
