#pragma once

#include <memory>
#include <span>
#include <vector>

#include "core/intersect/result.hpp"
#include "core/intersect/tuning.hpp"
#include "core/intersect/working_curve.hpp"

namespace bezier::core {

/// A linear reparametrisation under which two curves are the same polynomial:
/// g(s) = f(alpha + beta s) for every real s.
struct CoincidenceMap {
  double alpha = 0.0;
  double beta = 1.0;
};

/// One overlap and the map that produced it.
struct CommonArc;

/// One overlap and the map that produced it: linear (map), or, when `arc` is set, the
/// polynomial reparametrisations of a common arc (common_arc.hpp; map is then unused).
struct OverlapFinding {
  Overlap overlap;
  CoincidenceMap map;
  std::shared_ptr<const CommonArc> arc;
};

/// A necessary condition for two curves to overlap, far cheaper than any overlap test:
/// each end of an overlap is an end of f or of g, where the other curve passes, so at least
/// two of the four end points lie within 2 overlap_tolerance (plus rounding) of the other
/// curve's hull (its control points' bounding box and fat line).
[[nodiscard]] bool ends_may_overlap(const WorkingCurve& f, const WorkingCurve& g) noexcept;

/// The overlap tolerance: two pieces coincide when their control points (written with the
/// same degree) agree to within 2^-42 n of the curves' working scale (about 256 n ulps of
/// the largest coordinate): above the rounding of a portion and of the end points' Newton
/// refinement, far below any visible gap.
[[nodiscard]] double overlap_tolerance(int degree) noexcept;

/// The larger side of the bounding box of the control points (x_i, y_i): a curve's or a
/// piece's size in its frame.
[[nodiscard]] double extent(std::span<const double> x, std::span<const double> y) noexcept;

/// How far two pieces may be apart and still coincide: overlap_tolerance of the smaller
/// curve's size (at most the frame's, about 1), plus the rounding of pieces and
/// evaluations in doubles (64 n u of the magnitude) and of the frame. Relative to the frame
/// alone, a curve 2^-27 the size of the other would pass as an overlap of a piece of it
/// (Overlap.ACurveTheSizeOfAnotherCurvesRoundingIsNoOverlap).
[[nodiscard]] double coincidence_tolerance(const WorkingCurve& f, const WorkingCurve& g) noexcept;

/// At least coincidence_tolerance(f, g): its value with the smaller curve's size taken as 1,
/// the most it can be, without the two curves' extents, for quick necessary tests that
/// most pairs fail.
[[nodiscard]] double coincidence_tolerance_bound(const WorkingCurve& f,
                                                 const WorkingCurve& g) noexcept;

/// Overlaps of two curves that are not both collinear, by linear reparametrisation: if f
/// and g share a piece, both proper, then g(s) = f(alpha + beta s) (a polynomial curve's
/// proper parametrisations differ by affine maps). This covers identical, reversed
/// (beta < 0), sub-piece, extension and degree-elevated copies. From the monomial
/// coefficients a_k of f and b_k of g, of true degree d (degree-elevated copies have
/// vanishing top coefficients): beta^d = b_d / a_d and
/// b_{d-1} = beta^(d-1) (a_{d-1} + d alpha a_d). The candidate's overlap in [0,1]^2 is then
/// pinned down by Newton's method at its ends (each end is an end of f or of g) and
/// verified: f on [t_a, t_b] and g on [s_a, s_b] must have the same control points to
/// within coincidence_tolerance. Overlaps shorter than 2^-30 in s are left to the search, which
/// reports them as contacts. Improper parametrisations (g(s) = f(q(s)) with q of degree
/// >= 2) are find_arc_overlaps' (common_arc.hpp).
[[nodiscard]] std::vector<OverlapFinding> find_overlaps(const WorkingCurve& f,
                                                        const WorkingCurve& g);

/// True when the curve with control points (x, y) is injective on [lo, hi] (which may reach
/// outside [0, 1]): the hodograph's control vectors of that piece lie in an open half-plane,
/// with a margin for the rounding of the portion, so the curve is strictly monotone along a
/// direction there.
[[nodiscard]] bool injective_on(std::span<const double> x, std::span<const double> y,
                                double magnitude, double lo, double hi);

/// True when every intersection inside the box t x s lies on the overlap's diagonal
/// t = alpha + beta s (o.map), so the box holds nothing but overlap points and can be
/// dropped: the box meets the diagonal, and f is injective on the hull U of t and
/// alpha + beta s (its hodograph's control vectors on U lie in an open half-plane, so f is
/// strictly monotone along a direction). Then f(t) = g(s) = f(alpha + beta s) forces
/// t = alpha + beta s. Near a cusp of f the test fails and the box is kept (the search
/// subdivides it further). (find_overlaps reports no overlap whose two pieces both lie
/// within the tolerance of a point, whose map would be verified on nothing more.)
[[nodiscard]] bool covered_by_overlap(const WorkingCurve& f, const OverlapFinding& o,
                                      ParamInterval t, ParamInterval s);

/// True when (t, s) lies on the overlap's diagonal to within 2^-30 in t.
[[nodiscard]] bool on_overlap(const OverlapFinding& o, double t, double s);

/// True when f on t lies on g to within the rounding of the box's compensated pieces: f at
/// five points of t, projected onto g (Gauss-Newton with double-double residuals, starting
/// from the matching points of s), is everywhere within 16 n (u size + error) of g, where
/// size and error are those of f's compensated piece in the frame centred at `center`. Then
/// no clip in double-precision local coordinates can separate the curves inside the box (a
/// contact of order >= 3, where they stay within c d^3 of each other), and the search stops
/// refining the box: it is reported, unresolved. Sampling is enough for that decision,
/// because it never drops a box.
struct CoincidenceTest {
  bool coincide = false;
  int evaluations = 0;  ///< compensated evaluations of either curve (the test's cost)
};
[[nodiscard]] CoincidenceTest coincide_at_precision(const WorkingCurve& f, const WorkingCurve& g,
                                                    ParamInterval t, ParamInterval s,
                                                    Point2 center);

/// Solves f(t) = p for t near `start` (Gauss-Newton on |f(t) - p|^2 with double-double
/// residuals, gauss_newton.hpp): the parameter of a point known to lie on f, refined from a
/// close guess, until a step is at most `converged` (or after kProjectionSteps steps). Steps
/// larger than kGaussNewtonLargestStep end the iteration (f' nearly zero: the guess is
/// kept). Result clamped to [0, 1]. (Constants: intersect_tuning.)
[[nodiscard]] double locate_on_curve(
    const WorkingCurve& f, PointDD p, double start,
    double converged = intersect_tuning::kProjectionConverged);

}  // namespace bezier::core
