#include "api/batch_route.hpp"

#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "api/handler.hpp"
#include "api/nearest_name.hpp"
#include "api/read_json.hpp"
#include "api/route_table.hpp"

namespace bezier::api {

namespace {

constexpr double kAnyFinite = std::numeric_limits<double>::max();

// Whether an item of `path` is charged to the batch's work cap: the routes the per-item
// work cap bounds (api/route_table.hpp). The others' cost the degree and t-value limits
// bound; their answers are bounded by max_batch_answer_bytes.
bool charged_to_work_cap(std::string_view path) {
  const ComputeRoute* route = find_compute_route(path);
  return route != nullptr && route->cost == CostBound::work_cap;
}

bool is_batch_item_route(std::string_view path) { return find_compute_route(path) != nullptr; }

// The routes whose items the batch's work cap is not charged for, as a sentence names them.
std::string uncharged_routes_text() {
  std::vector<std::string_view> routes;
  for (const ComputeRoute& route : kComputeRoutes) {
    if (route.cost != CostBound::work_cap) routes.push_back(route.path);
  }
  std::string text;
  for (std::size_t i = 0; i < routes.size(); ++i) {
    if (i > 0) text += i + 1 == routes.size() ? " and " : ", ";
    text += routes[i];
  }
  return text;
}

std::string item_routes_text() {
  std::string text;
  for (const std::string_view route : batch_item_routes()) {
    if (!text.empty()) text += ", ";
    text += route;
  }
  return text;
}

// One validated item: where its path and body are in the request.
struct Item {
  std::string_view path;
  const Json* body;
};

// A lower bound on the bytes of an item's answer, from its request alone, for the routes
// whose answer grows with the request's t values or samples (/evaluate, /polar: up to
// max_t_values points each, megabytes from a request of a few bytes); 0 for the others
// and for a body the route would refuse (the route's own checks, run here without
// computing anything). Each result is at least {"point":[x,y],"t":t}, every number at
// least one character: 17 + 2d bytes for d coordinates.
std::size_t answer_bytes_at_least(const Item& item, const Limits& limits) {
  const bool evaluate = item.path == "/evaluate";
  if ((!evaluate && item.path != "/polar") || !item.body->is_object()) return 0;
  const Json& body = *item.body;
  RequestReader reader(limits);
  if (evaluate) {
    reader.reject_unknown_fields(body, {"points", "t", "samples", "derivatives", "frame", "split"}, "");
  } else {
    reader.reject_unknown_fields(body, {"points", "t0", "t", "samples"}, "");
  }
  const auto curve = reader.request_curve(body);
  const std::vector<double> ts = reader.parameters(body, /*required=*/evaluate);
  int derivatives = 0;
  if (const Json* d = RequestReader::optional(body, "derivatives")) {
    derivatives = reader.integer(*d, "/derivatives", 0, limits.max_degree).value_or(0);
  }
  if (const Json* f = RequestReader::optional(body, "frame"); f != nullptr && !f->is_boolean()) reader.fail("/frame", "expected a boolean");
  if (const Json* s = RequestReader::optional(body, "split")) reader.number(*s, "/split");
  if (evaluate && ts.size() * static_cast<std::size_t>(derivatives + 1) > static_cast<std::size_t>(limits.max_t_values)) {
    return 0;
  }
  if (!evaluate) {
    const Json* t0 = reader.required(body, "t0", "");
    const auto us = t0 == nullptr ? std::nullopt : reader.number_or_numbers(*t0, "/t0", -kAnyFinite, kAnyFinite);
    if (curve && us && us->size() > static_cast<std::size_t>(std::visit([](const auto& c) { return c.degree(); }, *curve))) {
      return 0;
    }
  }
  if (!reader.ok() || !curve) return 0;
  const std::size_t dimension = std::holds_alternative<core::Curve>(*curve) ? 2 : 3;
  return ts.size() * (17 + 2 * dimension);
}

// The answer of one item: the route's, or a 404 for a path no item may name.
Reply item_answer(const Item& item, const Limits& limits) {
  if (!is_batch_item_route(item.path)) {
    return problem_reply(ProblemKind::not_found, "no route " + std::string(item.path) +
                                                     did_you_mean(item.path, batch_item_routes()) +
                                                     " in a batch: an item names one of " + item_routes_text());
  }
  return compute_route_answer(item.path, *item.body, limits);
}

}  // namespace

Reply batch_route(const nlohmann::json& request, const Limits& limits, const BatchItemObserver& observer) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request, {"requests"}, "");
  const Json* requests = reader.required(request, "requests", "");
  if (requests != nullptr && !requests->is_array()) {
    reader.fail("/requests", "must be an array of {\"path\", \"body\"} items");
    requests = nullptr;
  }
  if (requests != nullptr && requests->size() > static_cast<std::size_t>(limits.max_batch_items)) {
    reader.fail_limit("/requests", "at most " + std::to_string(limits.max_batch_items) + " items in a batch, got " +
                                       std::to_string(requests->size()));
    return reader.refusal();
  }
  std::vector<Item> items;
  std::int64_t charged_items = 0;
  if (requests != nullptr) {
    items.reserve(requests->size());
    for (std::size_t i = 0; i < requests->size(); ++i) {
      const Json& entry = (*requests)[i];
      const std::string pointer = pointer_to("/requests", i);
      if (!entry.is_object()) {
        reader.fail(pointer, "an item is an object {\"path\": \"/classify\", \"body\": {...}}");
        continue;
      }
      reader.reject_unknown_fields(entry, {"path", "body"}, pointer);
      const Json* path = reader.required(entry, "path", pointer);
      if (path != nullptr && !path->is_string()) {
        reader.fail(pointer_to(pointer, "path"), "must be a string: the route's path, such as \"/classify\"");
        path = nullptr;
      }
      // A null body is a body (the route answers it 400, as it would alone).
      const auto body = entry.find("body");
      if (body == entry.end()) reader.fail(pointer_to(pointer, "body"), "required field is missing");
      if (path == nullptr || body == entry.end()) continue;
      items.push_back({path->get_ref<const std::string&>(), &*body});
      if (charged_to_work_cap(items.back().path)) ++charged_items;
    }
  }
  if (!reader.ok()) return reader.refusal();

  // Charged before any item runs: an item may spend up to max_work, so this is the most
  // the batch may spend. Compared by division, which cannot overflow. A work-cap problem
  // names no field (ValidationProblem in api/openapi.yaml): the detail says what to do.
  if (charged_items > 0 && limits.max_batch_work / charged_items < limits.max_work) {
    return problem_reply(ProblemKind::work_cap,
                         "the batch has " + std::to_string(charged_items) +
                             " items of routes the per-item work cap of " + std::to_string(limits.max_work) +
                             " units bounds, which may spend up to " + std::to_string(charged_items) + " x " +
                             std::to_string(limits.max_work) + " units, above the batch's work cap of " +
                             std::to_string(limits.max_batch_work) +
                             ": send them in smaller batches (items of " + uncharged_routes_text() +
                             " are not charged)");
  }

  // Refused before any item is computed when the answers certainly exceed the cap: at the
  // item where their lower bounds do (the answer itself would cross it there or earlier).
  std::size_t at_least = 0;
  for (std::size_t i = 0; i < items.size(); ++i) {
    at_least += answer_bytes_at_least(items[i], limits);
    if (at_least > limits.max_batch_answer_bytes) {
      Reply refused = validation_reply(
          {{pointer_to("/requests", i), "the answers of items 0 to " + std::to_string(i) + " take at least " +
                                            std::to_string(at_least) + " bytes, above the batch's answer cap of " +
                                            std::to_string(limits.max_batch_answer_bytes) +
                                            " bytes: send the items in smaller batches"}});
      refused.limit_reached = true;
      return refused;
    }
  }

  std::string out = R"({"responses":[)";
  // The answer's last bytes: the cap is on the whole answer, so the answers so far are
  // measured as if closed after each item.
  constexpr std::string_view kClosing = "]}";
  bool limit_reached = false;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Reply reply = item_answer(items[i], limits);
    if (observer) observer(items[i].path, reply);
    limit_reached = limit_reached || reply.limit_reached;
    if (i > 0) out += ',';
    out += R"({"body":)";
    out += reply.body;
    out += R"(,"status":)";
    out += std::to_string(reply.status);
    out += '}';
    if (out.size() + kClosing.size() > limits.max_batch_answer_bytes) {
      Reply refused = validation_reply(
          {{pointer_to("/requests", i), "the answers of items 0 to " + std::to_string(i) + " take " +
                                            std::to_string(out.size() + kClosing.size()) +
                                            " bytes, above the batch's answer cap of " +
                                            std::to_string(limits.max_batch_answer_bytes) +
                                            " bytes: send the items in smaller batches"}});
      refused.limit_reached = true;
      return refused;
    }
  }
  out += kClosing;
  Reply reply{200, "application/json", std::move(out)};
  reply.limit_reached = limit_reached;
  return reply;
}

}  // namespace bezier::api
