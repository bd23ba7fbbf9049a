#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/base/curve.hpp"
#include "core/base/work_budget.hpp"
#include "core/path/path.hpp"

namespace bezier::outline {

/// What flatten() may spend and produce.
struct FlattenOptions {
  /// The largest Hausdorff distance allowed between the curve and its polyline, in the
  /// coordinates' units. Precondition: tolerance >= 1e-12 of the largest coordinate (the
  /// certification needs room above the rounding of the pieces, chord_error.hpp); the API
  /// asks for 1e-9.
  double tolerance = 0.0;
  /// Most vertices in all polylines: a request whose estimate exceeds it is refused before
  /// any vertex is placed, and one whose verified polylines exceed it is refused too.
  std::size_t max_vertices = 10000;
};

enum class FlattenStatus {
  ok,
  /// The estimated or the verified vertex count is above max_vertices (no polylines).
  too_many_vertices,
};

/// A polyline vertex: the point B_segment(t) of the path (evaluate(), compensated), with
/// the segment it lies on (0-based, in drawing order; a curve is segment 0) and its t there.
struct PolylineVertex {
  std::size_t segment = 0;
  double t = 0.0;
  core::Point2 point;
};

struct Flattening {
  FlattenStatus status = FlattenStatus::ok;
  /// One polyline per subpath (a curve is one), vertices in drawing order. Every segment's
  /// ends are vertices: a subpath's first vertex is its first segment at t = 0; the joint
  /// of segments k and k + 1 is listed once, as segment k at t = 1 (the same point as
  /// segment k + 1 at t = 0, bit for bit); a closed subpath's last vertex repeats its first
  /// point (as its last segment at t = 1).
  std::vector<std::vector<PolylineVertex>> polylines;
  /// Vertices in all polylines.
  std::size_t count = 0;
  /// The vertex count the density integral predicted (what a refusal is decided on before
  /// building, see flatten()).
  double estimated_count = 0.0;
};

/// The parameters of the vertices of one curve's polyline: 0 = t_0 < t_1 < ... < t_m = 1,
/// each chord [B(t_{j-1}), B(t_j)] certified within `tolerance` of the curve on
/// [t_{j-1}, t_j] both ways (check_chord, chord_error.hpp), so the polyline is within
/// `tolerance` of the curve in the Hausdorff distance.
///
/// How the vertices are chosen. A chord of a smooth curve over a short parameter step Δ at t
/// stands off the curve by about |B''_⊥(t)| Δ^2 / 8, where B''_⊥ = cross(B', B'') / |B'| is
/// the acceleration across the direction of travel (the osculating parabola's sagitta; for a
/// parabola it is exact with B' taken at the middle of the step). The steps that keep it at
/// the tolerance ε are Δ(t) = sqrt(8 ε / |B''_⊥(t)|), so the polyline needs about
///   N = ∫_0^1 sqrt(|B''_⊥(t)| / (8 ε)) dt
/// chords, placed at equal increments of F(t) = ∫_0^t sqrt(|B''_⊥|): the density that
/// minimises the number of chords for a given largest error as ε -> 0 (the flattening
/// density of R. Levien, "Flattening quadratic Béziers", 2019, who integrates it in closed
/// form for a parabola; for any degree it is integrated here by the midpoint rule on
/// outline_tuning::kDensityCellsPerDegree * n cells, F piecewise linear between them).
/// The vertices are placed by a march that corrects this estimate with certified distances
/// (check_chord, chord_error.hpp). From a vertex a, the first try is the end b with
/// F(b) - F(a) the rest of the integral spread evenly over the chords it needs
/// (ceil((F(1) - F(a)) / sqrt(8 ε)), the last one ending at 1). While every try is within ε,
/// the step grows by the square law, b <- a + (b - a) sqrt(ε / h) (h the chord's distance,
/// aimed a little short; between 2 and 4 times the step); once an end is too far, the longest
/// certified chord is bracketed and the bracket narrowed, alternately by the secant of the
/// distance and by halving, up to outline_tuning::kMarchTries times. A chord within
/// outline_tuning::kChordSlack of ε (or ending at 1) is long enough; then a few longer
/// chords are still tried (outline_tuning::kProbes), because past an inflection or a sharp
/// turn the distance can fall again as the step grows, and a certified one becomes the new
/// start of the search. The farthest certified end is the next vertex. Each chord is thus
/// about as long as the greedy polyline's from the same start, and the estimate makes the
/// first try land close where the curvature varies smoothly (a few checks a vertex).
///
/// The curve and the tolerance are first scaled by a power of two (exact) that brings the
/// largest coordinate to [1, 2): the parameters are the same, and no difference or
/// derivative overflows or underflows anywhere in the double range.
///
/// The density table's work and the checks' are charged to `budget`; returns nothing when
/// it runs out (budget.exhausted()). Precondition: degree >= 1, finite coordinates,
/// tolerance as in FlattenOptions.
[[nodiscard]] std::vector<double> flatten_parameters(const core::Curve& curve, double tolerance,
                                                     core::WorkBudget& budget);

/// The estimate of the chord count N above (F(1) / sqrt(8 ε), not rounded) and its work.
struct ChordEstimate {
  double chords = 0.0;
  std::int64_t work = 0;
};
[[nodiscard]] ChordEstimate estimate_chords(const core::Curve& curve, double tolerance);

/// The polyline of a curve (one polyline, segment 0) or of a path (one per subpath, every
/// segment flattened by flatten_parameters). Refusals happen before the work they guard:
/// the estimates of all segments are summed first (one vertex per estimated chord, rounded
/// up, plus one per subpath), and a sum above max_vertices is too_many_vertices without
/// any vertex placed. Every density table and chord check is charged to `budget`; when it
/// runs out (budget.exhausted(), the one way this says so) there are no polylines.
[[nodiscard]] Flattening flatten(const core::Curve& curve, const FlattenOptions& options,
                                 core::WorkBudget& budget);
[[nodiscard]] Flattening flatten(const path::Path& path, const FlattenOptions& options,
                                 core::WorkBudget& budget);

}  // namespace bezier::outline
