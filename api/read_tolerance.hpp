#pragma once

#include "api/read_json.hpp"
#include "core/path/path.hpp"

namespace bezier::api {

/// The smallest tolerance /flatten and /offset take, as a fraction of the coordinates' scale:
/// their distances are certified to a few hundred ulps of the scale
/// (core/outline/tuning.hpp), and a tolerance near that buys vertices or cubics, not accuracy.
inline constexpr double kSmallestRelativeTolerance = 1e-9;

/// The required member `tolerance` (at /tolerance): a finite number greater than 0. A
/// refusal is recorded in `reader`; 0 is returned then.
[[nodiscard]] double read_positive_tolerance(RequestReader& reader, const Json& request);

/// Whether `tolerance` is at least kSmallestRelativeTolerance of `scale` (the largest
/// |coordinate| of the input); a refusal at /tolerance naming the smallest one otherwise.
[[nodiscard]] bool tolerance_fits_scale(RequestReader& reader, double tolerance, double scale);

/// The largest |coordinate| of a path's control points.
[[nodiscard]] double coordinate_scale(const path::Path& p);

}  // namespace bezier::api
