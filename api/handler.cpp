#include "api/handler.hpp"

#include <array>
#include <string>
#include <utility>
#include <variant>

#include "api/nearest_name.hpp"
#include "api/parse_json.hpp"
#include "api/read_json.hpp"
#include "api/route_table.hpp"

namespace bezier::api {

namespace {

// The compute routes, then /batch.
constexpr std::array<std::string_view, kComputeRoutes.size() + 1> kPaths = [] {
  std::array<std::string_view, kComputeRoutes.size() + 1> paths{};
  for (std::size_t i = 0; i < kComputeRoutes.size(); ++i) paths[i] = kComputeRoutes[i].path;
  paths[kComputeRoutes.size()] = kBatchPath;
  return paths;
}();

}  // namespace

std::span<const std::string_view> post_routes() noexcept { return kPaths; }

std::span<const std::string_view> batch_item_routes() noexcept {
  return std::span<const std::string_view>(kPaths).first(kComputeRoutes.size());
}

bool is_post_route(std::string_view path) noexcept {
  for (const std::string_view p : kPaths) {
    if (p == path) return true;
  }
  return false;
}

Reply compute_route_answer(std::string_view path, const nlohmann::json& body, const Limits& limits) {
  if (!body.is_object()) {
    return problem_reply(ProblemKind::malformed_json, "body must be a JSON object");
  }
  if (const ComputeRoute* route = find_compute_route(path)) return route->answer(body, limits);
  return problem_reply(ProblemKind::not_found, "no route " + std::string(path) + did_you_mean(path, kPaths));
}

namespace {

// The body parsed, or the problem a body that does not parse is answered.
std::variant<Reply, nlohmann::json> parse_body(std::string_view body) {
  if (body.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    return problem_reply(ProblemKind::malformed_json,
                         std::string(body.empty() ? "the body is empty" : "the body is only whitespace") +
                             ": send a JSON object, e.g. {\"points\": [[0, 0], [1, 2], [2, 0]], \"t\": 0.5} "
                             "for /evaluate (the routes and their fields: GET /openapi.yaml)");
  }
  ParsedJson parsed = parse_json(body);
  // Nested too deeply to parse: a body that is not an object is a 400 like any other; an
  // object is a request this service will not take.
  if (parsed.too_deep && parsed.root_is_object) {
    return validation_reply({{"", "the body nests arrays or objects deeper than " +
                                      std::to_string(kMaxJsonDepth) + " levels"}});
  }
  if (!parsed.ok) {
    return problem_reply(ProblemKind::malformed_json, "body is not valid JSON: at byte " +
                                                          std::to_string(parsed.error_offset) + ", " +
                                                          parsed.error);
  }
  return std::move(parsed.value);
}

}  // namespace

BatchRun start_batch(std::string_view body, const Limits& limits) {
  auto parsed = parse_body(body);
  if (Reply* refused = std::get_if<Reply>(&parsed)) return BatchRun(std::move(*refused));
  nlohmann::json& request = std::get<nlohmann::json>(parsed);
  if (!request.is_object()) return BatchRun(compute_route_answer(kBatchPath, request, limits));
  return BatchRun(std::move(request), limits);
}

Reply handle(std::string_view path, std::string_view body, const Limits& limits,
             const BatchItemObserver& observer) {
  if (path == kBatchPath) {
    BatchRun run = start_batch(body, limits);
    while (!run.finished()) run.compute_next(observer);
    return run.take_answer();
  }
  auto parsed = parse_body(body);
  if (Reply* refused = std::get_if<Reply>(&parsed)) return std::move(*refused);
  return compute_route_answer(path, std::get<nlohmann::json>(parsed), limits);
}

}  // namespace bezier::api
