#pragma once

#include <optional>

#include "api/read_json.hpp"

namespace bezier::api {

/// A closed parameter interval [a, b] with 0 <= a <= b <= 1.
struct ParameterInterval {
  double a = 0.0;
  double b = 1.0;
};

/// Whether a request may give a single point (a = b) as its interval: a point is an
/// interval to measure on (/length, /bounds, /nearest), but it encloses no area
/// (/loop-area, where the ends are called t1 < t2: the area of [t2, t1] is minus that of
/// [t1, t2]).
enum class SinglePointInterval { allowed, refused };

/// `value` as the member `interval`: exactly two numbers in [0, 1], in order (a <= b, or
/// a < b when a single point is refused). Problems are recorded at /interval (or
/// /interval/i) and give nullopt.
[[nodiscard]] std::optional<ParameterInterval> read_interval(RequestReader& reader, const Json& value,
                                                             SinglePointInterval single_point);

/// The optional `interval` member of the measuring routes (/length, /bounds, /nearest):
/// read_interval with a single point allowed, [0, 1] when absent.
[[nodiscard]] std::optional<ParameterInterval> read_parameter_interval(RequestReader& reader,
                                                                       const Json& request);

}  // namespace bezier::api
