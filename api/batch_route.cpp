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

bool is_batch_item_route(std::string_view path) { return find_compute_route(path) != nullptr; }

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

// The most work units an item may spend: its route's cost model; an item of a path no
// item may name is answered 404 at once.
std::int64_t item_work_bound(const Item& item, const Limits& limits) {
  const ComputeRoute* route = find_compute_route(item.path);
  return route == nullptr ? 0 : route->work_bound(*item.body, limits);
}

// The items of a batch that passed validation: where its path and body are.
Item item_at(const Json& requests, std::size_t i) {
  const Json& entry = requests[i];
  return {entry.find("path")->get_ref<const std::string&>(), &*entry.find("body")};
}

}  // namespace

BatchRun::BatchRun(Reply answer) { finish(std::move(answer)); }

BatchRun::BatchRun(nlohmann::json request, const Limits& limits) : request_(std::move(request)), limits_(limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request_, {"requests"}, "");
  const Json* requests = reader.required(request_, "requests", "");
  if (requests != nullptr && !requests->is_array()) {
    reader.fail("/requests", "must be an array of {\"path\", \"body\"} items");
    requests = nullptr;
  }
  if (requests != nullptr && requests->size() > static_cast<std::size_t>(limits.max_batch_items)) {
    reader.fail_limit("/requests", "at most " + std::to_string(limits.max_batch_items) + " items in a batch, got " +
                                       std::to_string(requests->size()));
    finish(reader.refusal());
    return;
  }
  if (requests != nullptr) {
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
      }
      // A null body is a body (the route answers it 400, as it would alone).
      if (entry.find("body") == entry.end()) reader.fail(pointer_to(pointer, "body"), "required field is missing");
    }
  }
  if (!reader.ok()) {
    finish(reader.refusal());
    return;
  }
  count_ = requests->size();

  // Charged before any item runs: each item's cost model bounds what it may spend, so their
  // sum is the most the batch may spend. Each bound is at most a few times max_work and
  // there are at most max_batch_items, so the sum cannot overflow. A work-cap problem names
  // no field (ValidationProblem in api/openapi.yaml): the detail says what to do.
  std::int64_t work = 0;
  for (std::size_t i = 0; i < count_; ++i) work += item_work_bound(item_at(*requests, i), limits);
  if (work > limits.max_batch_work) {
    finish(problem_reply(ProblemKind::work_cap,
                                "the batch's " + std::to_string(count_) + " items may spend up to " +
                                    std::to_string(work) + " work units (each item by its route's sizes; " +
                                    std::to_string(limits.max_work) +
                                    " for a route the per-item work cap bounds), above the batch's work cap of " +
                                    std::to_string(limits.max_batch_work) + ": send them in smaller batches"));
    return;
  }
  // Refused before any item is computed when the answers certainly exceed the cap: at the
  // item where their lower bounds do (the answer itself would cross it there or earlier).
  std::size_t at_least = 0;
  for (std::size_t i = 0; i < count_; ++i) {
    at_least += answer_bytes_at_least(item_at(*requests, i), limits);
    if (at_least > limits.max_batch_answer_bytes) {
      Reply refused = validation_reply(
          {{pointer_to("/requests", i), "the answers of items 0 to " + std::to_string(i) + " take at least " +
                                            std::to_string(at_least) + " bytes, above the batch's answer cap of " +
                                            std::to_string(limits.max_batch_answer_bytes) +
                                            " bytes: send the items in smaller batches"}});
      refused.limit_reached = true;
      finish(std::move(refused));
      return;
    }
  }

  out_ = R"({"responses":[)";
  if (count_ == 0) finish_with_answers();
}

void BatchRun::compute_next(const BatchItemObserver& observer) {
  // The answer's last bytes: the cap is on the whole answer, so the answers so far are
  // measured as if closed after each item.
  constexpr std::string_view kClosing = "]}";
  const std::size_t i = next_++;
  const Item item = item_at(request_["requests"], i);
  const Reply reply = item_answer(item, limits_);
  if (observer) observer(item.path, reply);
  limit_reached_ = limit_reached_ || reply.limit_reached;
  if (i > 0) out_ += ',';
  out_ += R"({"body":)";
  out_ += reply.body;
  out_ += R"(,"status":)";
  out_ += std::to_string(reply.status);
  out_ += '}';
  if (out_.size() + kClosing.size() > limits_.max_batch_answer_bytes) {
    Reply refused = validation_reply(
        {{pointer_to("/requests", i), "the answers of items 0 to " + std::to_string(i) + " take " +
                                          std::to_string(out_.size() + kClosing.size()) +
                                          " bytes, above the batch's answer cap of " +
                                          std::to_string(limits_.max_batch_answer_bytes) +
                                          " bytes: send the items in smaller batches"}});
    refused.limit_reached = true;
    out_.clear();
    out_.shrink_to_fit();
    finish(std::move(refused));
    return;
  }
  if (next_ == count_) finish_with_answers();
}

void BatchRun::finish_with_answers() {
  out_ += "]}";
  Reply reply{200, "application/json", std::move(out_)};
  reply.limit_reached = limit_reached_;
  finish(std::move(reply));
}

void BatchRun::finish(Reply answer) {
  answer_ = std::move(answer);
  finished_ = true;
  request_ = nullptr;
}

Reply BatchRun::take_answer() { return std::move(answer_); }

Reply batch_route(const nlohmann::json& request, const Limits& limits, const BatchItemObserver& observer) {
  BatchRun run(request, limits);
  while (!run.finished()) run.compute_next(observer);
  return run.take_answer();
}

}  // namespace bezier::api
