#include "core/intersect/fat_line.hpp"

#include <cmath>

#include "core/intersect/bernstein1d.hpp"

namespace bezier::core {

namespace {

constexpr double kU = bernstein::kU;

/// Largest |coordinate - origin| over a piece's control points.
double reach(const Piece& p, Point2 origin) noexcept {
  const double* x = p.x.data();
  const double* y = p.y.data();
  double r = 0.0;
  for (std::size_t i = 0, n = p.x.size(); i < n; ++i) {
    r = bernstein::max2(r, bernstein::max2(std::fabs(x[i] - origin.x), std::fabs(y[i] - origin.y)));
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
  // The bounds for m = 2 and 3 below hold only for a line through both end points.
  bool through_ends = true;
  if (bernstein::max2(std::fabs(d.x), std::fabs(d.y)) <= limit) {
    through_ends = false;
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
  double lo = 0.0, hi = 0.0;
  const double* gx = g.x.data();
  const double* gy = g.y.data();
  const auto distance = [&](std::size_t j) {
    return line.normal.x * (gx[j] - origin.x) + line.normal.y * (gy[j] - origin.y);
  };
  if (m == 3 && through_ends) {
    // The exact end distances are within e of 0 (the line passes through the computed end
    // points), which adds e; the interior ones are within e of d_j, scaled by c <= 1.
    const double d1 = distance(1), d2 = distance(2);
    const bool opposite = (d1 - e > 0 && d2 + e < 0) || (d1 + e < 0 && d2 - e > 0);
    const double c = opposite ? 4.0 / 9.0 : 0.75;
    lo = bernstein::min2(bernstein::min2(lo, c * (d1 - e)), c * (d2 - e));
    hi = bernstein::max2(bernstein::max2(hi, c * (d1 + e)), c * (d2 + e));
  } else if (m == 2 && through_ends) {
    const double d1 = distance(1);
    lo = bernstein::min2(lo, 0.5 * (d1 - e));
    hi = bernstein::max2(hi, 0.5 * (d1 + e));
  } else {
    for (std::size_t j = 0; j <= m; ++j) {
      const double dj = distance(j);
      lo = bernstein::min2(lo, dj);
      hi = bernstein::max2(hi, dj);
    }
  }
  lo -= e;
  hi += e;
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
  out.a = Coeffs(n, Coeffs::Uninitialized{});
  double* a = out.a.data();
  const double* x = f.x.data();
  const double* y = f.y.data();
  for (std::size_t i = 0; i < n; ++i) {
    a[i] = line.normal.x * (x[i] - line.origin.x) + line.normal.y * (y[i] - line.origin.y);
  }
  const double n1 = std::fabs(line.normal.x) + std::fabs(line.normal.y);
  out.error = n1 * (f.error + 3.01 * kU * reach(f, line.origin));
  return out;
}

}  // namespace bezier::core
