#pragma once

#include "core/numeric/small_array.hpp"
#include "core/intersect/working_curve.hpp"

namespace bezier::core {

/// The fat line of a piece G (Sederberg & Nishita, "Curve intersection using Bézier
/// clipping", CAD 22(9), 1990, §3): the band {p : d_min <= N · (p - O) <= d_max} around the
/// line through O = G_0 with normal N ⟂ G_m - G_0 (N not normalised: every distance here is
/// measured in the same units, so the scale of N cancels). The band contains the exact
/// piece: it is widened by the piece's error bound and by the rounding of the distances.
/// For cubics and quadratics the band is the tight one of the paper: with interior
/// distances d1, d2 it is [min(0, c d1, c d2), max(0, c d1, c d2)], c = 3/4 when d1 d2 > 0
/// and 4/9 when their signs differ (the maxima of 3t(1-t)^2 + 3t^2(1-t) and of 3t(1-t)^2);
/// for quadratics [min(0, d1/2), max(0, d1/2)]; otherwise the hull of all d_j.
struct FatLine {
  Point2 origin;
  Point2 normal;
  double d_min = 0.0;
  double d_max = 0.0;
  double margin = 0.0;  ///< how much of the band's width is error margin (each side)
};

/// Which line to draw through a piece that is a point to within its error bound (a curve
/// collapsed to a point, or a piece at the end of the search): perpendicular to the other
/// piece's chord (so the other's distance runs along it) or parallel to it (so the
/// distance measures how far the other passes beside the point).
enum class PointLineDirection { across_other, along_other };

/// The fat line of g. When g's chord is shorter than its error bound, the line goes through
/// g_0 and its farthest control point; when g is a point to within its error bound, the
/// direction comes from the other piece (see PointLineDirection).
[[nodiscard]] FatLine fat_line(const Piece& g, const Piece& other,
                               PointLineDirection direction = PointLineDirection::across_other);

/// Bernstein coefficients of the signed distance N · (F(t) - O) of a piece F from the fat
/// line's line, and a bound on how far the exact piece's coefficients can be from them.
struct DistanceCoefficients {
  Coeffs a;
  double error = 0.0;
};

[[nodiscard]] DistanceCoefficients distance_coefficients(const FatLine& line, const Piece& f);

/// True when the piece lies within a box of its own error bound: a point for the search.
[[nodiscard]] bool is_point_like(const Piece& p) noexcept;

}  // namespace bezier::core
