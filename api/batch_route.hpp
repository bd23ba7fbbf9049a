#pragma once

#include <functional>
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
/// items; and when the work its items may spend exceeds limits.max_batch_work (a work-cap
/// problem): each item of a route whose cost the per-item cap bounds (CostBound::work_cap in
/// api/route_table.hpp; the others' cost the degree and t-value limits bound instead) is
/// charged limits.max_work, the most it may spend. It is refused as well,
/// as soon as it is known, when the answers of its items would exceed
/// limits.max_batch_answer_bytes (a 422 that points at the item that crossed it). Every
/// item is computed under `limits` as it stands, so each answer, a work-cap problem
/// included, is the one the route gives alone. limit_reached is set when a limit refused
/// the batch or decided the answer of one of its items.
[[nodiscard]] Reply batch_route(const nlohmann::json& request, const Limits& limits,
                                const BatchItemObserver& observer);

}  // namespace bezier::api
