#include "service/http_problem.hpp"

#include <nlohmann/json.hpp>

namespace bezier::service {

namespace {

const char* title_of(int status) noexcept {
  switch (status) {
    case 408:
      return "The request was not received within the read timeout";
    case 414:
      return "The request line is too long";
    case 431:
      return "The request headers are too large";
    case 501:
      return "Transfer coding not implemented";
    case 503:
      return "Service is overloaded; retry later";
    case 505:
      return "HTTP version not supported";
    default:
      return "Malformed HTTP request";
  }
}

}  // namespace

Response http_problem(int status, std::string detail, bool shutting_down) {
  if (status == 413) return problem_response(api::ProblemKind::payload_too_large, std::move(detail));
  if (status == 503 && shutting_down) return problem_response(api::ProblemKind::shutting_down, std::move(detail));
  const nlohmann::json body = {
      {"type", status == 503 ? "urn:bezier-service:problem:overloaded" : "urn:bezier-service:problem:bad-request"},
      {"title", title_of(status)},
      {"status", status},
      {"detail", std::move(detail)},
  };
  Response response;
  response.status = status;
  response.content_type = "application/problem+json";
  response.body = body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return response;
}

}  // namespace bezier::service
