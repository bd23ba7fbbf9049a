#pragma once

#include <span>
#include <string_view>

#include <nlohmann/json.hpp>

#include "api/batch_route.hpp"
#include "api/limits.hpp"
#include "api/problem.hpp"

namespace bezier::api {

/// The POST routes of the API, in the order the spec lists them: the compute routes,
/// then /batch.
[[nodiscard]] std::span<const std::string_view> post_routes() noexcept;

/// The compute routes: every POST route but /batch, the paths a batch item may name.
[[nodiscard]] std::span<const std::string_view> batch_item_routes() noexcept;

/// Whether `path` is one of post_routes().
[[nodiscard]] bool is_post_route(std::string_view path) noexcept;

/// The whole request -> response path for a POST route, without sockets: parses the
/// body, checks that it is a JSON object, validates it and calls the kernel.
/// Never throws for any body (only std::bad_alloc may escape). Precondition:
/// is_post_route(path); content type, method and body size are the service's checks.
/// `observer` sees every computed item of a /batch request (batch_route.hpp).
[[nodiscard]] Reply handle(std::string_view path, std::string_view body, const Limits& limits,
                           const BatchItemObserver& observer = {});

/// handle(kBatchPath, body, limits) as a run computed one item at a time
/// (api/batch_route.hpp): the same answer, byte for byte, once every item is computed.
[[nodiscard]] BatchRun start_batch(std::string_view body, const Limits& limits);

/// The answer of compute route `path` to a parsed body, as handle() gives it after
/// parsing: 400 when the body is not a JSON object, 404 when `path` is not one of
/// batch_item_routes().
[[nodiscard]] Reply compute_route_answer(std::string_view path, const nlohmann::json& body,
                                         const Limits& limits);

/// The OpenAPI document, byte for byte api/openapi.yaml (compiled in).
[[nodiscard]] std::string_view openapi_yaml() noexcept;
/// The same document as JSON (tools/openapi_to_json.py's text, converted at build time).
[[nodiscard]] std::string_view openapi_json() noexcept;

}  // namespace bezier::api
