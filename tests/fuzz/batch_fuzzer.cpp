// libFuzzer target: POST /batch, bezier::api::handle("/batch", body, limits, observer).
//
// Input: byte 0 picks how the body is made (bit 0) and the limits (bit 1: the documented
// defaults with a smaller work cap, or tight ones: 4 items, room for 2 items of the
// work-capped routes, and the answer cap 1024 + bytes 1-2 (little-endian) modulo 4096, so
// that it falls anywhere between one item's answer and several). The rest is either
//   - raw: the batch's body as the service would pass it on, or
//   - items: one item a line, its first byte the path (byte - '0' modulo the 13 paths of
//     kItemPaths: '0' /evaluate ... '7' /nearest, then /batch and two paths no item may
//     name, then ';' /contains, '<' /boolean), the rest of the line the item's body, put into the batch
//     as it is.
//
// Checks on every execution: everything in reply_checks.hpp for the batch itself; on a
// 200 answer, {"responses": [...]} with one {"body": object, "status"} per item, each a
// status a route gives (200, 400, 404, 422) and, on a problem, its body's `status` equal
// to it, the observer called once per item in order with the item's path and status, and
// the whole answer within the answer cap. With items whose bodies are JSON on their own
// (then the batch holds exactly those items): the answer the contract (api/batch_route.hpp,
// README "POST /batch") gives, computed here from each item sent alone to its route:
//   - more items than max_batch_items: 422 at /requests;
//   - items whose cost models (api/route_cost.hpp: max_work for the work-capped routes) add
//     up above max_batch_work: the work-cap 422;
//   - an answer longer than max_batch_answer_bytes: 422 at the first item whose answer
//     makes it longer (the answer of that item and those before it, closed), or at a
//     later item with none computed (lower bounds of /evaluate and /polar answers);
//   - otherwise 200 with the text of the items' answers alone, byte for byte, and
//     limit_reached exactly when one of them has it set;
// each refusal with limit_reached set and before any item is computed (the answer cap's
// at most up to the item that crossed it).
//
// Run: see docs/FUZZING.md (with -dict=tests/fuzz/batch_fuzzer.dict).

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "api/handler.hpp"
#include "api/limits.hpp"
#include "api/parse_json.hpp"
#include "api/route_table.hpp"
#include "tests/fuzz/api_limits.hpp"
#include "tests/fuzz/fuzz_support.hpp"
#include "tests/fuzz/reply_checks.hpp"
#include "tests/support/batch_body.hpp"

namespace {

using Json = nlohmann::json;
using bezier::fuzz::check;

// The compute routes of api/openapi.yaml (what an item may name), the batch route itself,
// and paths no route has.
// /contains and /boolean came after the others and are last, so that the seeds keep their paths.
constexpr std::array<std::string_view, 13> kItemPaths = {
    "/evaluate", "/polar",   "/classify", "/loop-area",    "/intersections", "/length",
    "/bounds",   "/nearest", "/batch",    "/openapi.yaml", "/evaluate/",     "/contains",
    "/boolean"};
constexpr std::size_t kComputeRoutes = 8;

bool is_compute_route(std::string_view path) {
  return path == "/contains" || path == "/boolean" ||
         std::find(kItemPaths.begin(), kItemPaths.begin() + kComputeRoutes, path) !=
             kItemPaths.begin() + kComputeRoutes;
}

// The other API targets' limits (api_limits.hpp) with a batch's: the defaults, with room
// for 32 items of the work-capped routes; or at most 4 items, 2 of them charged, segments
// and an answer cap that small requests reach.
bezier::api::Limits default_limits() {
  bezier::api::Limits limits = bezier::fuzz::default_limits();
  limits.max_batch_work = 32 * limits.max_work;
  return limits;
}

bezier::api::Limits tight_limits(std::size_t answer_bytes) {
  bezier::api::Limits limits = bezier::fuzz::tight_limits();
  limits.max_path_segments = 4;
  limits.max_batch_items = 4;
  limits.max_batch_work = 2 * limits.max_work;
  limits.max_batch_answer_bytes = answer_bytes;
  return limits;
}

using Item = bezier::test::BatchItem;

// What a batch charges its items (README, "POST /batch"): each its route's cost model
// (api/route_cost.hpp, named in api/route_table.hpp), from its body as the batch parses it.
std::int64_t batch_charge(const std::vector<Item>& items, const bezier::api::Limits& limits) {
  std::int64_t work = 0;
  for (const Item& item : items) {
    if (const bezier::api::ComputeRoute* route = bezier::api::find_compute_route(item.path)) {
      work += route->work_bound(bezier::api::parse_json(item.body).value, limits);
    }
  }
  return work;
}

std::vector<Item> split_items(std::string_view text) {
  std::vector<Item> items;
  while (!text.empty()) {
    const std::size_t end = std::min(text.find('\n'), text.size());
    const std::string_view line = text.substr(0, end);
    text.remove_prefix(std::min(end + 1, text.size()));
    if (line.empty()) continue;
    const auto selector = static_cast<unsigned char>(line[0] - '0');
    items.push_back({std::string(kItemPaths[selector % kItemPaths.size()]), std::string(line.substr(1))});
  }
  return items;
}

/// How deeply `value` nests: 0 for a scalar, 1 for a container of scalars.
int nesting(const Json& value) {
  if (!value.is_structured()) return 0;
  int deepest = 0;
  for (const Json& element : value) deepest = std::max(deepest, nesting(element));
  return deepest + 1;
}

/// Whether `body`, put into the batch as it is, is exactly one JSON value that the batch
/// can hold: JSON on its own, without the byte-order mark a body alone may begin with, and
/// nesting no deeper than the parser's limit below the batch's own three levels.
bool embeds_as_one_value(std::string_view body) {
  if (body.substr(0, 3) == "\xEF\xBB\xBF") return false;
  const bezier::api::ParsedJson parsed = bezier::api::parse_json(body);
  return parsed.ok && 3 + nesting(parsed.value) <= bezier::api::kMaxJsonDepth;
}

struct Observed {
  std::string path;
  int status;
};

/// The answer of an item naming no compute route: the 404 problem a batch of that item
/// alone answers (it depends on the path only).
const std::string& not_found_body(std::string_view path) {
  static std::map<std::string, std::string, std::less<>> cache;
  if (const auto it = cache.find(path); it != cache.end()) return it->second;
  const std::string batch = R"({"requests":[{"path":")" + std::string(path) + R"(","body":{}}]})";
  const bezier::api::Reply reply = bezier::api::handle("/batch", batch, bezier::api::Limits{});
  const std::string head = R"({"responses":[{"body":)";
  const std::string tail = R"(,"status":404}]})";
  check(reply.status == 200 && reply.body.starts_with(head) && reply.body.ends_with(tail),
        [&] { return "an item naming " + std::string(path) + " is not answered 404: " + reply.body; });
  const std::string body = reply.body.substr(head.size(), reply.body.size() - head.size() - tail.size());
  const Json problem = Json::parse(body);
  check(problem.value("type", "") == "urn:bezier-service:problem:not-found",
        [&] { return "the 404 of an item is not a not-found problem: " + body; });
  return cache.emplace(std::string(path), body).first->second;
}

std::vector<std::string> pointers_of(const Json& answer) {
  std::vector<std::string> pointers;
  if (answer.contains("errors")) {
    for (const Json& e : answer["errors"]) pointers.push_back(e.value("pointer", ""));
  }
  return pointers;
}

/// A 200 answer: its shape, the items' statuses, the observer's calls, the answer cap.
void check_answer_shape(const bezier::api::Reply& reply, const Json& request, const bezier::api::Limits& limits,
                        const std::vector<Observed>& observed) {
  check(reply.body.size() <= limits.max_batch_answer_bytes, [&] {
    return "a 200 answer of " + std::to_string(reply.body.size()) + " bytes, above the answer cap of " +
           std::to_string(limits.max_batch_answer_bytes);
  });
  const Json answer = Json::parse(reply.body);
  check(answer.size() == 1 && answer.contains("responses") && answer["responses"].is_array(),
        [&] { return "a 200 answer that is not {\"responses\": [...]}: " + reply.body.substr(0, 2000); });
  const Json& responses = answer["responses"];
  const Json& requests = request["requests"];
  check(responses.size() == requests.size() && observed.size() == requests.size(), [&] {
    return std::to_string(requests.size()) + " items, " + std::to_string(responses.size()) + " responses, " +
           std::to_string(observed.size()) + " observed";
  });
  for (std::size_t i = 0; i < responses.size(); ++i) {
    const Json& r = responses[i];
    check(r.is_object() && r.size() == 2 && r.contains("body") && r["body"].is_object() &&
              r.contains("status") && r["status"].is_number_integer(),
          [&] { return "response " + std::to_string(i) + " is not {\"body\": {...}, \"status\"}: " + r.dump(); });
    const int status = r["status"].get<int>();
    check(status == 200 || status == 400 || status == 404 || status == 422,
          [&] { return "response " + std::to_string(i) + " has status " + std::to_string(status); });
    if (status != 200) {
      check(r["body"].value("status", 0) == status,
            [&] { return "response " + std::to_string(i) + ": the problem's status differs: " + r.dump(); });
    }
    check(observed[i].status == status && observed[i].path == requests[i]["path"].get<std::string>(), [&] {
      return "observed item " + std::to_string(i) + " as " + observed[i].path + " " +
             std::to_string(observed[i].status) + ", answered " + r.dump().substr(0, 500);
    });
  }
}

/// The contract's answer to a batch of `items`, each body JSON on its own.
void check_against_items_alone(const std::vector<Item>& items, const bezier::api::Limits& limits,
                               const bezier::api::Reply& reply, const std::vector<Observed>& observed) {
  const Json answer = Json::parse(reply.body);
  if (items.size() > static_cast<std::size_t>(limits.max_batch_items)) {
    check(reply.status == 422 && reply.limit_reached && pointers_of(answer) == std::vector<std::string>{"/requests"},
          [&] { return "too many items, answered " + reply.body; });
    check(observed.empty(), "items computed in a batch refused for its items' count");
    return;
  }
  const std::int64_t charged = batch_charge(items, limits);
  if (charged > limits.max_batch_work) {
    check(reply.status == 422 && reply.limit_reached &&
              answer.value("type", "") == "urn:bezier-service:problem:work-cap",
          [&] { return std::to_string(charged) + " units charged to the items, answered " + reply.body; });
    check(observed.empty(), "items computed in a batch refused for its work");
    return;
  }
  std::string expected = R"({"responses":[)";
  bool limit_reached = false;
  for (std::size_t i = 0; i < items.size(); ++i) {
    std::string entry = i > 0 ? "," : "";
    if (is_compute_route(items[i].path)) {
      const bezier::api::Reply alone = bezier::api::handle(items[i].path, items[i].body, limits);
      limit_reached = limit_reached || alone.limit_reached;
      entry += R"({"body":)" + alone.body + R"(,"status":)" + std::to_string(alone.status) + '}';
    } else {
      entry += R"({"body":)" + not_found_body(items[i].path) + R"(,"status":404})";
    }
    expected += entry;
    if (expected.size() + 2 > limits.max_batch_answer_bytes) {
      // Refused at this item, or, before any item is computed, at this one or a later one:
      // where lower bounds of the /evaluate and /polar answers cross the cap (they never
      // exceed the real answers, so they cross here or after).
      const std::vector<std::string> pointers = pointers_of(answer);
      const std::string_view prefix = "/requests/";
      const bool at_or_after =
          pointers.size() == 1 && pointers[0].rfind(prefix, 0) == 0 &&
          (pointers[0] == std::string(prefix) + std::to_string(i) ||
           (observed.empty() && std::stoul(pointers[0].substr(prefix.size())) > i));
      check(reply.status == 422 && reply.limit_reached && at_or_after,
            [&] {
              return "the answer through item " + std::to_string(i) + " takes " + std::to_string(expected.size() + 2) +
                     " bytes, above the cap of " + std::to_string(limits.max_batch_answer_bytes) + "; answered " +
                     reply.body.substr(0, 2000);
            });
      check(observed.size() <= i + 1, "items computed after the one that crossed the answer cap");
      return;
    }
  }
  expected += "]}";
  check(reply.status == 200 && reply.body == expected, [&] {
    return "the batch answer differs from its items' answers alone:\n  batch: " + reply.body.substr(0, 2000) +
           "\n  alone: " + expected.substr(0, 2000);
  });
  check(reply.limit_reached == limit_reached, "limit_reached differs from the items' answers alone");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3) return -1;
  const bool as_items = (data[0] & 1u) != 0;
  const std::size_t answer_bytes = 1024 + ((data[1] | (std::size_t{data[2]} << 8)) % 4096);
  const bezier::api::Limits limits = (data[0] & 2u) ? tight_limits(answer_bytes) : default_limits();
  const std::string_view rest(reinterpret_cast<const char*>(data + 3), size - 3);

  std::vector<Item> items;
  std::string body;
  if (as_items) {
    items = split_items(rest);
    body = bezier::test::batch_body(items);
  } else {
    body = std::string(rest);
  }
  if (bezier::fuzz::print_inputs()) std::fprintf(stderr, "%s\n", body.c_str());

  std::vector<Observed> observed;
  const bezier::api::Reply reply =
      bezier::api::handle("/batch", body, limits, [&](std::string_view path, const bezier::api::Reply& item) {
        observed.push_back({std::string(path), item.status});
      });
  bezier::fuzz::check_reply(body, reply);
  if (reply.status == 200) {
    const bezier::api::ParsedJson request = bezier::api::parse_json(body);
    check_answer_shape(reply, request.value, limits, observed);
  } else {
    check(observed.empty() || reply.status == 422, [&] { return "items computed in a batch answered " + reply.body; });
  }
  if (as_items && std::all_of(items.begin(), items.end(), [](const Item& item) { return embeds_as_one_value(item.body); })) {
    check_against_items_alone(items, limits, reply, observed);
  }
  return 0;
}
