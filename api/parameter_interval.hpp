#pragma once

#include <optional>

#include "api/read_json.hpp"

namespace bezier::api {

/// A closed parameter interval [a, b] with 0 <= a <= b <= 1.
struct ParameterInterval {
  double a = 0.0;
  double b = 1.0;
};

/// The optional `interval` member of the measuring routes (/length, /bounds, /nearest):
/// exactly two numbers [a, b] with 0 <= a <= b <= 1 (a = b is a single point), [0, 1] when
/// absent. Problems are recorded at /interval (or /interval/i) and give nullopt.
[[nodiscard]] std::optional<ParameterInterval> read_parameter_interval(RequestReader& reader,
                                                                       const Json& request);

}  // namespace bezier::api
