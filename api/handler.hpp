#pragma once

#include <span>
#include <string_view>

#include "api/limits.hpp"
#include "api/problem.hpp"

namespace bezier::api {

/// The POST routes of the API, in the order the spec lists them.
[[nodiscard]] std::span<const std::string_view> post_routes() noexcept;

/// Whether `path` is one of post_routes().
[[nodiscard]] bool is_post_route(std::string_view path) noexcept;

/// The whole request -> response path for a POST route, without sockets: parses the
/// body, checks that it is a JSON object, validates it and calls the kernel.
/// Never throws for any body (only std::bad_alloc may escape). Precondition:
/// is_post_route(path); content type, method and body size are the service's checks.
[[nodiscard]] Reply handle(std::string_view path, std::string_view body, const Limits& limits);

/// The OpenAPI document, byte for byte api/openapi.yaml (compiled in).
[[nodiscard]] std::string_view openapi_yaml() noexcept;

}  // namespace bezier::api
