#pragma once

// The routes and the limits the API fuzz targets send their requests under.

#include <array>
#include <string_view>

#include "api/limits.hpp"

namespace bezier::fuzz {

/// The spec's POST routes that api_request_fuzzer and api_structured_fuzzer pick by byte 0,
/// in a fixed order so that a corpus keeps its meaning when the route table grows.
inline constexpr std::array<std::string_view, 5> kApiPaths = {"/evaluate", "/polar", "/loop-area",
                                                              "/intersections", "/classify"};

/// The documented defaults, except a work cap of 20 000 units (about a thousandth of the
/// default): under ASan and coverage a kernel step costs ten to fifty times what it does in
/// a release build, and requests that exhaust the cap (curves retracing themselves,
/// high-order contacts) would take seconds each and starve the run. The cap's own path is
/// the same at any value.
inline api::Limits default_limits() {
  api::Limits limits;
  limits.max_work = 20000;
  return limits;
}

/// Limits that requests reach at small sizes: degree 3, 4 t values, 64 work units.
inline api::Limits tight_limits() {
  api::Limits limits;
  limits.max_degree = 3;
  limits.max_t_values = 4;
  limits.max_work = 64;
  return limits;
}

}  // namespace bezier::fuzz
