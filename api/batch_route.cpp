#include "api/batch_route.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "api/handler.hpp"
#include "api/nearest_name.hpp"
#include "api/read_json.hpp"

namespace bezier::api {

namespace {

// The routes whose cost the degree and t-value limits bound rather than the work cap:
// their items are not charged to the batch's work cap (their answers are bounded by
// max_batch_answer_bytes instead). Every other item route is charged max_work.
constexpr std::array<std::string_view, 5> kRoutesWithoutWorkCap = {"/evaluate", "/polar", "/classify",
                                                                   "/bounds", "/segments"};

bool is_batch_item_route(std::string_view path) {
  const auto routes = batch_item_routes();
  return std::find(routes.begin(), routes.end(), path) != routes.end();
}

bool charged_to_work_cap(std::string_view path) {
  return is_batch_item_route(path) &&
         std::find(kRoutesWithoutWorkCap.begin(), kRoutesWithoutWorkCap.end(), path) == kRoutesWithoutWorkCap.end();
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
                             ": send them in smaller batches (items of /evaluate, /polar, /classify and "
                             "/bounds are not charged)");
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
