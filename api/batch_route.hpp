#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <span>
#include <string_view>

#include <nlohmann/json.hpp>

#include "api/limits.hpp"
#include "api/problem.hpp"

namespace bezier::api {

/// The path of the batch route.
inline constexpr std::string_view kBatchPath = "/batch";

/// Called once per computed item of a batch, in order, with the item's path (as the
/// client sent it) and its answer: what the service needs for its per-item metrics.
using BatchItemObserver = std::function<void(std::string_view path, const Reply& reply)>;

/// POST /batch (api/openapi.yaml): {"requests": [{"path": "/classify", "body": {...}}, ...]} is
/// answered {"responses": [{"body": ..., "status": 200}, ...]}, one response per item in
/// the same order, each the status and the very bytes the route answers when the item's
/// body is sent to it alone (its problems' pointers point into the item's body). An item
/// whose body is not a JSON object gets the 400 the route gives such a body; an item whose
/// path is not one of batch_item_routes() (an unknown path, /batch itself, the GET routes)
/// gets a 404 problem, and the other items are answered all the same.
///
/// The whole batch is refused, before any item is computed, with a 422 whose pointers
/// point into the batch's body: when it is not {"requests": [...]} with every item an
/// object of a string `path` and a `body`; when it has more than limits.max_batch_items
/// items; when the work its items may spend exceeds limits.max_batch_work (a work-cap
/// problem): every item is charged its route's cost model (api/route_cost.hpp; for a
/// route whose kernel charges the per-item cap, limits.max_work and its path data), the
/// most it may spend, so the batch's CPU time is bounded by its work cap; and when the
/// answers of its items certainly exceed limits.max_batch_answer_bytes (lower bounds of
/// the /evaluate and /polar answers; a 422 at the item where they cross it). It is refused
/// as well, as soon as it is known, when the answers of its items exceed
/// limits.max_batch_answer_bytes (a 422 that points at the item that crossed it). Every
/// item is computed under `limits` as it stands, so each answer, a work-cap problem
/// included, is the one the route gives alone. limit_reached is set when a limit refused
/// the batch or decided the answer of one of its items.
[[nodiscard]] Reply batch_route(const nlohmann::json& request, const Limits& limits,
                                const BatchItemObserver& observer);

/// batch_route() one item at a time, for a caller that interleaves a batch's items with
/// other work (the service runs each item as a task of its compute pool, queued behind
/// the requests that wait, so that a batch never holds a compute thread for longer than
/// one item). The refusals of the whole batch are decided when it is constructed; the
/// answer is batch_route()'s, byte for byte.
class BatchRun {
 public:
  /// A batch whose answer is already known (a body that is not a JSON object, say).
  explicit BatchRun(Reply answer);
  /// Validates and charges the batch `request` (a JSON object), which the run keeps.
  BatchRun(nlohmann::json request, const Limits& limits);

  /// Whether the answer is ready: every item computed, or the batch refused.
  [[nodiscard]] bool finished() const noexcept { return finished_; }
  /// Computes the next item, which `observer` then sees. Precondition: !finished().
  void compute_next(const BatchItemObserver& observer);
  /// The answer. Precondition: finished(); called once.
  [[nodiscard]] Reply take_answer();

 private:
  void finish_with_answers();
  void finish(Reply answer);

  nlohmann::json request_;
  Limits limits_;
  std::size_t next_ = 0;
  std::size_t count_ = 0;
  std::string out_;
  bool limit_reached_ = false;
  bool finished_ = false;
  Reply answer_;
};

}  // namespace bezier::api
