#pragma once

#include <nlohmann/json.hpp>

#include "api/limits.hpp"
#include "api/problem.hpp"

namespace bezier::api {

// One function per POST route, each in its own <name>_route.cpp: read and validate
// the request object, call the kernel, build the answer. The request is already known
// to be a JSON object; pointers in errors are relative to its root.

[[nodiscard]] Reply evaluate_route(const nlohmann::json& request, const Limits& limits);
[[nodiscard]] Reply polar_route(const nlohmann::json& request, const Limits& limits);
[[nodiscard]] Reply classify_route(const nlohmann::json& request, const Limits& limits);
[[nodiscard]] Reply loop_area_route(const nlohmann::json& request, const Limits& limits);
[[nodiscard]] Reply intersections_route(const nlohmann::json& request, const Limits& limits);
[[nodiscard]] Reply length_route(const nlohmann::json& request, const Limits& limits);
[[nodiscard]] Reply bounds_route(const nlohmann::json& request, const Limits& limits);
[[nodiscard]] Reply nearest_route(const nlohmann::json& request, const Limits& limits);
[[nodiscard]] Reply contains_route(const nlohmann::json& request, const Limits& limits);
[[nodiscard]] Reply boolean_route(const nlohmann::json& request, const Limits& limits);
[[nodiscard]] Reply flatten_route(const nlohmann::json& request, const Limits& limits);
[[nodiscard]] Reply offset_route(const nlohmann::json& request, const Limits& limits);
[[nodiscard]] Reply stroke_route(const nlohmann::json& request, const Limits& limits);
[[nodiscard]] Reply segments_route(const nlohmann::json& request, const Limits& limits);

}  // namespace bezier::api
