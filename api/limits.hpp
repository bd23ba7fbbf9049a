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
  /// Per-request work cap for iterative kernels, in kernel steps (clipping or
  /// subdivision steps, candidate boxes). Hitting it answers 422, never a hang.
  std::int64_t max_work = 200000;
};

}  // namespace bezier::api
