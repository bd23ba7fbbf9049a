#include "core/intersect/clip/fat_line.hpp"

#include <cmath>

#include "core/numeric/min_max.hpp"
#include "core/numeric/fixed_extent.hpp"
#include "core/base/multiversion.hpp"
#include "core/numeric/unit_roundoff.hpp"
#include "core/intersect/tuning.hpp"

namespace bezier::core {

namespace {

/// Largest |coordinate - origin| over a piece's control points x, y.
template <std::size_t E>
double reach(std::span<const double, E> x, std::span<const double, E> y, Point2 origin) noexcept {
  double r = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    r = max2(r, max2(std::fabs(x[i] - origin.x), std::fabs(y[i] - origin.y)));
  }
  return r;
}

Point2 chord(const Piece& p) noexcept {
  return {p.x.back() - p.x[0], p.y.back() - p.y[0]};
}

}  // namespace

bool is_point_like(const Piece& p) noexcept {
  const double limit = intersect_tuning::kPointLikeErrors * p.error;
  for (std::size_t i = 1; i < p.x.size(); ++i) {
    if (std::fabs(p.x[i] - p.x[0]) > limit || std::fabs(p.y[i] - p.y[0]) > limit) return false;
  }
  return true;
}

namespace {

/// fat_line for g's coordinates gx, gy of E = m + 1 entries (with_fixed_extent).
template <std::size_t E>
FatLine fat_line_of(std::span<const double, E> gx, std::span<const double, E> gy, double g_error,
                    const Piece& other, PointLineDirection direction) {
  const std::size_t m = gx.size() - 1;
  const Point2 origin = {gx[0], gy[0]};
  Point2 d = {gx[m] - gx[0], gy[m] - gy[0]};
  const double limit = intersect_tuning::kPointLikeErrors * g_error;
  // The bounds for m = 2 and 3 below hold only for a line through both end points.
  bool through_ends = true;
  if (max2(std::fabs(d.x), std::fabs(d.y)) <= limit) {
    through_ends = false;
    // Closed or nearly closed piece: use the farthest control point instead.
    double best = 0.0;
    for (std::size_t j = 1; j <= m; ++j) {
      const Point2 v = {gx[j] - origin.x, gy[j] - origin.y};
      const double size = max2(std::fabs(v.x), std::fabs(v.y));
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
  const double e = n1 * (g_error + 3.01 * kUnitRoundoff * reach(gx, gy, origin));
  double lo = 0.0, hi = 0.0;
  const auto distance = [&](std::size_t j) {
    return line.normal.x * (gx[j] - origin.x) + line.normal.y * (gy[j] - origin.y);
  };
  if (m == 3 && through_ends) {
    // The exact end distances are within e of 0 (the line passes through the computed end
    // points), which adds e; the interior ones are within e of d_j, scaled by c <= 1.
    const double d1 = distance(1), d2 = distance(2);
    // Bitwise, not short-circuit: a select instead of branches the data decides.
    const bool opposite = ((d1 - e > 0) & (d2 + e < 0)) | ((d1 + e < 0) & (d2 - e > 0));
    const double c = opposite ? 4.0 / 9.0 : 0.75;
    lo = min2(min2(lo, c * (d1 - e)), c * (d2 - e));
    hi = max2(max2(hi, c * (d1 + e)), c * (d2 + e));
  } else if (m == 2 && through_ends) {
    const double d1 = distance(1);
    lo = min2(lo, 0.5 * (d1 - e));
    hi = max2(hi, 0.5 * (d1 + e));
  } else {
    for (std::size_t j = 0; j <= m; ++j) {
      const double dj = distance(j);
      lo = min2(lo, dj);
      hi = max2(hi, dj);
    }
  }
  lo -= e;
  hi += e;
  // The products c (d +- e) and the sums above round too: a relative hair more.
  const double slack = 4 * kUnitRoundoff * (std::fabs(lo) + std::fabs(hi));
  line.d_min = lo - slack;
  line.d_max = hi + slack;
  line.margin = e + slack;
  return line;
}

/// distance_coefficients for f's coordinates x, y of E entries (with_fixed_extent).
template <std::size_t E>
DistanceCoefficients distance_coefficients_of(const FatLine& line, std::span<const double, E> x,
                                              std::span<const double, E> y, double f_error) {
  DistanceCoefficients out;
  out.a.resize(x.size());  // zeros: a few stores for a constant size, nothing moved
  double* a = out.a.data();
  for (std::size_t i = 0; i < x.size(); ++i) {
    a[i] = line.normal.x * (x[i] - line.origin.x) + line.normal.y * (y[i] - line.origin.y);
  }
  const double n1 = std::fabs(line.normal.x) + std::fabs(line.normal.y);
  out.error = n1 * (f_error + 3.01 * kUnitRoundoff * reach(x, y, line.origin));
  return out;
}

}  // namespace

BEZIER_FMA_CLONES FatLine fat_line(const Piece& g, const Piece& other,
                                   PointLineDirection direction) {
  const std::size_t size = g.x.size();
  return with_fixed_extent(size, [&](auto e) {
    constexpr std::size_t E = decltype(e)::value;
    return fat_line_of(fixed_span<E>(g.x.data(), size), fixed_span<E>(g.y.data(), size), g.error,
                       other, direction);
  });
}

BEZIER_FMA_CLONES DistanceCoefficients distance_coefficients(const FatLine& line, const Piece& f) {
  const std::size_t size = f.x.size();
  return with_fixed_extent(size, [&](auto e) {
    constexpr std::size_t E = decltype(e)::value;
    return distance_coefficients_of(line, fixed_span<E>(f.x.data(), size),
                                    fixed_span<E>(f.y.data(), size), f.error);
  });
}

}  // namespace bezier::core
