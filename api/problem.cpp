#include "api/problem.hpp"

#include <nlohmann/json.hpp>

#include "api/write_json.hpp"

namespace bezier::api {

namespace {

struct ProblemInfo {
  int status;
  const char* slug;
  const char* title;
};

ProblemInfo info_of(ProblemKind kind) noexcept {
  switch (kind) {
    case ProblemKind::malformed_json:
      return {400, "malformed-json", "Malformed request body"};
    case ProblemKind::validation:
      return {422, "validation", "Request failed validation"};
    case ProblemKind::work_cap:
      return {422, "work-cap", "Request needs more work than the per-request cap allows"};
    case ProblemKind::memory_cap:
      return {422, "memory-cap", "Request needs more memory than the per-request limit allows"};
    case ProblemKind::result_overflow:
      return {422, "result-overflow", "The answer overflows the double range"};
    case ProblemKind::payload_too_large:
      return {413, "payload-too-large", "Request body is larger than the limit"};
    case ProblemKind::unsupported_media_type:
      return {415, "unsupported-media-type", "The body must be application/json, without a content coding"};
    case ProblemKind::not_found:
      return {404, "not-found", "No such route"};
    case ProblemKind::method_not_allowed:
      return {405, "method-not-allowed", "Method not allowed on this route"};
    case ProblemKind::unauthorized:
      return {401, "unauthorized", "Missing or invalid bearer token"};
    case ProblemKind::shutting_down:
      return {503, "shutting-down", "Service is shutting down"};
    case ProblemKind::internal:
      break;
  }
  return {500, "internal", "Internal error"};
}

// At most `limit` bytes of `text` (cut at a UTF-8 character boundary), then "…": what a
// detail quotes of the request (a pointer holds the client's member names, of any length)
// stays short. The `errors` list keeps every pointer whole: a client matches them.
// Messages quote at most a short excerpt of a value themselves (the path parser's numbers);
// kMessageBytes is a backstop far above any message's own length.
constexpr std::size_t kQuotedPointerBytes = 64;
constexpr std::size_t kMessageBytes = 512;
std::string excerpt(std::string_view text, std::size_t limit) {
  if (text.size() <= limit) return std::string(text);
  std::size_t cut = limit;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  std::string out(text.substr(0, cut));
  out += "\xE2\x80\xA6";
  return out;
}

}  // namespace

/// The end of every work-cap problem's detail: what a client can change to finish.
constexpr std::string_view kWorkCapAdvice =
    ". To finish within the cap, ask for less per request: a larger `tolerance` or another "
    "`method` (/intersections), fewer `targets` or `at_lengths`, a shorter path or a larger "
    "`arc_tolerance` (fewer arc segments), fewer batch items; or run the service with a larger "
    "--max-work (BEZIER_MAX_WORK; --max-batch-work for a whole batch)";

int status_of(ProblemKind kind) noexcept { return info_of(kind).status; }

Reply problem_reply(ProblemKind kind, std::string detail, std::vector<FieldError> errors) {
  const ProblemInfo info = info_of(kind);
  // What a client can change: every work-cap problem ends with it.
  if (kind == ProblemKind::work_cap) detail += kWorkCapAdvice;
  nlohmann::json body = {
      {"type", std::string("urn:bezier-service:problem:") + info.slug},
      {"title", info.title},
      {"status", info.status},
      {"detail", std::move(detail)},
  };
  if (!errors.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (auto& e : errors) list.push_back({{"pointer", std::move(e.pointer)}, {"message", std::move(e.message)}});
    body["errors"] = std::move(list);
  }
  // Invalid UTF-8 from the request may be echoed in a message: replace, never throw.
  Reply reply{info.status, "application/problem+json", dump_json(body)};
  reply.limit_reached = kind == ProblemKind::work_cap;
  reply.decided_by_work_cap = kind == ProblemKind::work_cap;
  return reply;
}

Reply validation_reply(std::vector<FieldError> errors) {
  std::string detail = "request rejected";
  if (!errors.empty()) {
    detail = "'";
    detail += excerpt(errors.front().pointer, kQuotedPointerBytes);
    detail += "': ";
    detail += excerpt(errors.front().message, kMessageBytes);
  }
  if (errors.size() > 1) detail += " (and " + std::to_string(errors.size() - 1) + " more)";
  return problem_reply(ProblemKind::validation, std::move(detail), std::move(errors));
}

Reply json_reply(JsonWriter&& answer) {
  // Finite input can still give a result beyond the double range (B(2) of a segment to
  // 1e308, a derivative of alternating ±1e308 points). JSON has no infinity and the
  // writer put null in its place: the request is answered as unanswerable instead. The
  // problem names the answer's field, not a request field: the request broke no rule,
  // and which of its fields made the number overflow is not known here.
  if (!answer.all_finite()) {
    return problem_reply(ProblemKind::result_overflow,
                         "the result overflows the double range (answer field '" +
                             answer.first_non_finite_pointer() + "')");
  }
  return {200, "application/json", std::move(answer).take()};
}

Reply memory_cap_reply(const std::string& pointer, std::string why) {
  std::string detail = "'";
  detail += excerpt(pointer, kQuotedPointerBytes);
  detail += "': ";
  detail += why;
  detail +=
      ". To finish within the limit, split the path or run the service with a larger "
      "--max-request-memory (BEZIER_MAX_REQUEST_MEMORY)";
  Reply reply =
      problem_reply(ProblemKind::memory_cap, std::move(detail), {{pointer, std::move(why)}});
  reply.limit_reached = true;
  return reply;
}

Reply self_intersection_work_cap_reply(std::int64_t work, std::int64_t max_work) {
  return problem_reply(ProblemKind::work_cap,
                       "the self-intersection search spent " + std::to_string(work) +
                           " work units without finishing and ran out of the per-request "
                           "work cap of " +
                           std::to_string(max_work) +
                           " units (a curve that comes within rounding of retracing part of "
                           "itself without doing so needs work that grows without bound as it "
                           "gets closer)");
}

}  // namespace bezier::api
