#pragma once

#include <cstddef>
#include <cstdint>

namespace bezier::api {

/// Per-request limits. The service fills them from flags and environment variables;
/// the defaults here are the documented ones (README, openapi.yaml).
struct Limits {
  /// Highest curve degree accepted (n; a curve has n + 1 control points).
  int max_degree = 20;
  /// Most parameter values in one request: length of a `t` array, or `samples`.
  int max_t_values = 10000;
  /// Largest request body in bytes (the service answers 413 above it).
  std::size_t max_body_bytes = 1 << 20;
  /// Per-request work cap for iterative kernels, in work units: each clipping or
  /// subdivision step, Newton iteration and parameter box is charged by its degrees and
  /// arithmetic (core/intersect/work_cost.hpp, core/self_intersection_work_cost.hpp), so
  /// that units are proportional to time; one unit is about 3-6 ns on the reference
  /// machine. The default is what the heaviest legitimate request we know needs with a
  /// margin (two degree-20 curves crossing 400 times, the most possible: 20.4 M units by
  /// the default method), which bounds a request's kernel time near 80-110 ms
  /// (BENCHMARKS.md §4b). Hitting it answers 422, never a hang.
  std::int64_t max_work = 22000000;
};

}  // namespace bezier::api
