#pragma once

#include <cstdint>

#include <nlohmann/json.hpp>

#include "api/limits.hpp"

namespace bezier::api {

/// The cost model of the compute routes: the most work units a request may spend, read
/// from its sizes (degree, t values and derivatives, samples, path data) before it runs,
/// in the units of Limits::max_work (docs/WORK_CAPS.md, "The work unit": about one
/// coordinate update of de Casteljau's algorithm in doubles). A batch charges each item
/// this bound against Limits::max_batch_work before any item runs (api/batch_route.hpp),
/// so that the batch's CPU time is bounded by its work cap whatever routes its items name.
///
/// The sizes are read without validating the body: a body its route would refuse is
/// charged as the sizes it shows (a refusal costs less than the computation it refuses),
/// and sizes above a limit are charged at the limit (the route refuses them before any
/// work that grows with them). Each route's line in api/route_table.hpp names its model.
/// The constants are fitted so that a unit costs no more CPU time on these routes than on
/// the work-capped kernels (docs/WORK_CAPS.md gives the command that measures them).
using RouteCost = std::int64_t (*)(const nlohmann::json& body, const Limits& limits);

/// A route whose kernel charges the per-request work cap: limits.max_work, plus what its
/// path data costs before the kernel charges anything (parsing it, the segments' boxes):
/// path_segments_at_most() x kPathSegmentUnits.
[[nodiscard]] std::int64_t work_capped_cost(const nlohmann::json& body, const Limits& limits);

/// /evaluate: per t value, the point, each derivative and (with `frame`) the tangent,
/// normal and curvature, each a de Casteljau run of the degree and its coordinates written
/// (kNumberUnits each); `split` one subdivision.
[[nodiscard]] std::int64_t evaluate_cost(const nlohmann::json& body, const Limits& limits);

/// /polar: per t value (or once, without t) the blossom, a de Casteljau run of the degree,
/// and its coordinates written.
[[nodiscard]] std::int64_t polar_cost(const nlohmann::json& body, const Limits& limits);

/// /classify: a fixed amount, the exact predicates of one cubic included.
[[nodiscard]] std::int64_t classify_cost(const nlohmann::json& body, const Limits& limits);

/// /bounds: the certified roots of the derivative of each coordinate, (n + 1)^3 x
/// kRootUnits per curve of degree n (a path: per segment, at most cubic).
[[nodiscard]] std::int64_t bounds_cost(const nlohmann::json& body, const Limits& limits);

/// /segments: per segment, its parse and its control points written.
[[nodiscard]] std::int64_t segments_cost(const nlohmann::json& body, const Limits& limits);

/// The most segments the path data anywhere in `body` (every member "path" holding a
/// string, at any depth) may stand for: a segment takes at least one character of path
/// data, except that an elliptical arc may stand for up to limits.max_path_segments cubics;
/// each path at most limits.max_path_segments (above it the path is refused).
[[nodiscard]] std::int64_t path_segments_at_most(const nlohmann::json& body, const Limits& limits);

/// What one item costs whatever its sizes (dispatch, validation, a short answer), charged
/// to the routes bounded by their sizes alone.
inline constexpr std::int64_t kRequestUnits = 2000;
/// One number written to the answer (shortest round-trip digits) and read from it.
inline constexpr std::int64_t kNumberUnits = 64;
/// One segment of path data before a kernel charges it: parsed, stored, boxed.
inline constexpr std::int64_t kPathSegmentUnits = 512;
/// The certified root finder's work per (n + 1)^3 for a derivative of a degree-n curve.
inline constexpr std::int64_t kRootUnits = 16;
/// The Stone-DeRose classification of one cubic, its exact predicates included.
inline constexpr std::int64_t kClassifyUnits = 50000;

}  // namespace bezier::api
