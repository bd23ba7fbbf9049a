#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "api/read_json.hpp"
#include "core/base/point.hpp"

namespace bezier::api {

inline constexpr std::size_t dimension_of(core::Point2) { return 2; }
inline constexpr std::size_t dimension_of(core::Point3) { return 3; }

/// The member `targets` (at /targets): 1 to max_t_values points of P's dimension, each
/// refused at its pointer when it is not `dimension_reason`'s number of numbers (the
/// reason follows the count in the message, e.g. ", the curve's dimension").
template <class P>
std::optional<std::vector<P>> read_targets(RequestReader& reader, const Json& value,
                                           std::string_view dimension_reason) {
  constexpr std::size_t kDimension = dimension_of(P{});
  if (!value.is_array()) {
    reader.fail("/targets", "expected an array of points");
    return std::nullopt;
  }
  if (value.empty()) {
    reader.fail("/targets", "must not be empty");
    return std::nullopt;
  }
  const auto limit = static_cast<std::size_t>(reader.limits().max_t_values);
  if (value.size() > limit) {
    reader.fail_limit("/targets", "at most " + std::to_string(limit) + " targets allowed, got " +
                                      std::to_string(value.size()) + " (the max_t_values limit)");
    return std::nullopt;
  }
  std::vector<P> targets;
  targets.reserve(value.size());
  bool all_ok = true;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const Json& p = value[i];
    const std::string pointer = pointer_to("/targets", i);
    if (!p.is_array() || p.size() != kDimension) {
      reader.fail(pointer, "expected a point of " + std::to_string(kDimension) + " numbers" +
                               std::string(dimension_reason));
      all_ok = false;
      continue;
    }
    P target;
    double* coordinates = &target.x;
    for (std::size_t k = 0; k < kDimension; ++k) {
      const auto c = reader.number(p[k], pointer_to(pointer, k));
      all_ok = all_ok && c.has_value();
      coordinates[k] = c.value_or(0.0);
    }
    targets.push_back(target);
  }
  if (!all_ok) return std::nullopt;
  return targets;
}

}  // namespace bezier::api
