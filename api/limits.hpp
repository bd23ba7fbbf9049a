#pragma once

#include <cstddef>
#include <cstdint>

#include "core/base/work_budget.hpp"

namespace bezier::api {

/// Per-request limits. The service fills them from flags and environment variables;
/// the defaults here are the documented ones (README, openapi.yaml).
struct Limits {
  /// Highest curve degree accepted (n; a curve has n + 1 control points).
  int max_degree = 20;
  /// Most parameter values in one request: length of a `t` array, or `samples`.
  int max_t_values = 10000;
  /// Most segments in one SVG path ({"path": ...} wherever a curve is taken, api/curve_or_path.hpp).
  /// A path costs memory and time per segment before any work is charged (parsing, boxes);
  /// the work cap bounds everything after.
  int max_path_segments = 10000;
  /// Largest request body in bytes (the service answers 413 above it).
  std::size_t max_body_bytes = 1 << 20;
  /// Per-request work cap for iterative kernels, in work units. Every phase of a request
  /// that can take more than a fixed time is charged to it before or as it runs (the
  /// intersection search's steps, the grouping of its boxes into contacts, the Newton
  /// refinements, the overlap and collinear tests, the self-intersection search's boxes and
  /// Newton runs, and the certification of each self-intersection, which gets what the
  /// search left), each by its degrees and arithmetic (core/intersect/work_cost.hpp,
  /// core/self_intersect/work_cost.hpp), so that units are proportional to time and the
  /// cap bounds a request's CPU time whatever its method. The default is what the heaviest
  /// legitimate request we know needs with a margin (two degree-20 curves crossing 400
  /// times, the most possible, by the default method). BENCHMARKS.md ("Worst requests at the default limits") has the worst
  /// request of every method at this cap and the command that measures it; hitting it
  /// answers 422, never a hang.
  std::int64_t max_work = 22000000;
  /// Most bytes a request's kernel call may store in proportion to how its input meets
  /// itself (core::WorkBudget::charge_memory): the segment pairs whose boxes meet, of one
  /// path or two (16 bytes each), and the copy a path's self-intersection search keeps;
  /// 422 memory-cap above (docs/OPERATIONS.md). At the default work cap a path search
  /// pays at least 80 units a pair it searches (two lines: a step and the overlap test),
  /// so 275 000 pairs (4.4 MB) already exceed max_work: 4 MiB refuses only what the work
  /// cap would, before the pairs are stored rather than after.
  std::int64_t max_request_memory = std::int64_t{4} << 20;
  /// Most items in one POST /batch (its 422 above, before any item is computed).
  int max_batch_items = 1000;
  /// Work cap of a whole batch, in the units of max_work: the batch is refused before any
  /// item is computed when its items may spend more (each item is charged its route's cost
  /// model, api/route_cost.hpp: max_work for a route the per-item cap bounds, its sizes for
  /// the others; api/batch_route.hpp). The default admits 10 work-capped items at the
  /// default max_work: a batch's CPU time about 1 s (docs/WORK_CAPS.md), spread over
  /// compute-pool tasks of one item each.
  std::int64_t max_batch_work = 10 * std::int64_t{22000000};
  /// Largest answer of a whole batch in bytes (the items' answers bound the memory a batch
  /// holds, since each may be much larger than its request: a batch is refused when they
  /// exceed it, before any item is computed when lower bounds of its items' answers
  /// already do). A batch then holds at most this plus one item's answer, twice over
  /// while it is sent (docs/OPERATIONS.md): 8 MiB keeps a few concurrent batches well
  /// inside a 512 MiB pod.
  std::size_t max_batch_answer_bytes = std::size_t{8} << 20;
};

/// One request's budget: max_work work units and max_request_memory bytes.
[[nodiscard]] constexpr core::WorkBudget request_budget(const Limits& limits) noexcept {
  return core::WorkBudget(limits.max_work, limits.max_request_memory);
}

}  // namespace bezier::api
