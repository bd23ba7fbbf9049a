#pragma once

// The invariants every answer of bezier::api::handle() must keep, whatever the body
// (api/openapi.yaml): only the statuses the API documents for a POST body (a 500 is a bug), a
// body that is valid JSON, the content type that goes with the status, RFC 9457 problem
// details with type/title/status/detail, error pointers that are JSON Pointers into the
// request, and no NaN or infinity smuggled into a 200 answer (nlohmann writes those as
// null).

#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "api/parse_json.hpp"
#include "api/problem.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace bezier::fuzz {

/// Whether `value` holds a null where no documented field may be null. nlohmann writes a
/// NaN or an infinity as null, so a null elsewhere (inside a point, a t list, an area) is a
/// non-finite result that leaked into a 200 answer (finding F1). The nullable fields
/// (api/openapi.yaml): canonical_point, cusp, self_intersection (/classify),
/// closed_area (/loop-area), and with `frame` curvature, normal, tangent (/evaluate,
/// where B'(t) = 0).
[[nodiscard]] inline bool has_undocumented_null(const nlohmann::json& value) {
  if (value.is_array()) {
    for (const auto& element : value) {
      if (element.is_null() || has_undocumented_null(element)) return true;
    }
  } else if (value.is_object()) {
    for (const auto& [key, member] : value.items()) {
      if (member.is_null()) {
        constexpr std::array<std::string_view, 7> kNullable = {
            "canonical_point", "cusp", "self_intersection", "closed_area", "curvature", "normal", "tangent"};
        bool nullable = false;
        for (const auto k : kNullable) nullable = nullable || key == k;
        if (!nullable) return true;
      } else if (has_undocumented_null(member)) {
        return true;
      }
    }
  }
  return false;
}

/// Whether `pointer` is a syntactically valid JSON Pointer whose parent exists in
/// `request` (the field itself may be missing: "required field is missing").
[[nodiscard]] inline bool points_into(const nlohmann::json& request, const std::string& pointer) {
  try {
    const nlohmann::json::json_pointer p(pointer);
    if (p.empty()) return true;
    return request.contains(p.parent_pointer());
  } catch (const nlohmann::json::exception&) {
    return false;
  }
}

/// Checks `reply` against the invariants above. `body` is the request body it answers.
inline void check_reply(std::string_view body, const api::Reply& reply) {
  constexpr std::array kAllowed = {200, 400, 413, 415, 422};
  bool allowed = false;
  for (const int s : kAllowed) allowed = allowed || reply.status == s;
  check(allowed, [&] {
    return "status " + std::to_string(reply.status) +
           " is not one a POST body may get: " + reply.body.substr(0, 2000);
  });

  const auto answer = nlohmann::json::parse(reply.body, nullptr, /*allow_exceptions=*/false);
  check(!answer.is_discarded(), [&] { return "reply body is not valid JSON: " + reply.body; });
  check(answer.is_object(), "reply body is not a JSON object");

  // The request as the API saw it: api::parse_json, not nlohmann (which reads a NUL byte as
  // the end of the text, so "{}\0x" would count as an object), held to nlohmann's verdict in
  // tests/api/parse_json_test.cpp. Nothing when it does not parse, or nests too deeply.
  const api::ParsedJson parsed = api::parse_json(body);
  const nlohmann::json request = parsed.ok ? parsed.value : nlohmann::json(nlohmann::json::value_t::discarded);
  if (!request.is_discarded()) {
    check(request.is_object() == (reply.status != 400),
          [&] { return "400 must mean exactly 'body is not a JSON object'; got " + reply.body; });
  }

  if (reply.status == 200) {
    check(reply.content_type == "application/json",
          [&] { return "200 with content type " + reply.content_type; });
    check(!has_undocumented_null(answer), [&] {
      return "null in a 200 answer where a number belongs (a NaN or infinity was written): " +
             reply.body.substr(0, 2000);
    });
    return;
  }

  check(reply.content_type == "application/problem+json",
        [&] { return "error status with content type " + reply.content_type; });
  for (const char* key : {"type", "title", "detail"}) {
    check(answer.contains(key) && answer[key].is_string() &&
              !answer[key].get_ref<const std::string&>().empty(),
          [&] {
            return std::string("problem body without a non-empty string '") + key +
                   "': " + reply.body;
          });
  }
  check(answer.contains("status") && answer["status"].is_number_integer() &&
            answer["status"].get<int>() == reply.status,
        [&] { return "problem 'status' differs from the HTTP status: " + reply.body; });
  if (answer.contains("errors")) {
    const auto& errors = answer["errors"];
    check(reply.status == 422,
          [&] { return "'errors' on a status other than 422: " + reply.body; });
    check(errors.is_array() && !errors.empty(), "'errors' is not a non-empty array");
    for (const auto& e : errors) {
      check(e.is_object() && e.contains("pointer") && e["pointer"].is_string() &&
                e.contains("message") && e["message"].is_string() &&
                !e["message"].get_ref<const std::string&>().empty(),
            [&] { return "malformed entry in 'errors': " + e.dump(); });
      if (request.is_object()) {
        check(points_into(request, e["pointer"].get<std::string>()), [&] {
          return "error pointer " + e["pointer"].dump() + " is not a JSON Pointer into the request";
        });
      }
    }
  }
}

}  // namespace bezier::fuzz
