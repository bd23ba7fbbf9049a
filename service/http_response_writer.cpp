#include "service/http_response_writer.hpp"

#include <charconv>

namespace bezier::service {

std::string_view reason_phrase(int status) noexcept {
  switch (status) {
    case 100: return "Continue";
    case 200: return "OK";
    case 204: return "No Content";
    case 400: return "Bad Request";
    case 401: return "Unauthorized";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 408: return "Request Timeout";
    case 413: return "Content Too Large";
    case 414: return "URI Too Long";
    case 415: return "Unsupported Media Type";
    case 422: return "Unprocessable Content";
    case 431: return "Request Header Fields Too Large";
    case 500: return "Internal Server Error";
    case 501: return "Not Implemented";
    case 503: return "Service Unavailable";
    case 505: return "HTTP Version Not Supported";
    default: return "Unknown";
  }
}

namespace {

void append_number(std::string& out, std::size_t value) {
  char digits[24];
  const auto end = std::to_chars(digits, digits + sizeof digits, value).ptr;
  out.append(digits, end);
}

void append_header(std::string& out, std::string_view name, std::string_view value) {
  out += name;
  out += ": ";
  out += value;
  out += "\r\n";
}

// Every answer: browsers must take the declared Content-Type as it is, never sniff a
// JSON or text answer into something they would run or render.
constexpr std::string_view kNoSniff = "X-Content-Type-Options: nosniff\r\n";

// HTML answers (the playground's pages): scripts, styles, images, connections and
// everything else from the service's own origin only, no inline code (the page loads
// its scripts and styles as files), and no framing by any page (clickjacking).
constexpr std::string_view kPageSecurityPolicy =
    "Content-Security-Policy: default-src 'self'; base-uri 'self'; form-action 'self'; "
    "frame-ancestors 'none'\r\n";

bool is_html(std::string_view content_type) noexcept {
  constexpr std::string_view kHtml = "text/html";
  return content_type.substr(0, kHtml.size()) == kHtml &&
         (content_type.size() == kHtml.size() || content_type[kHtml.size()] == ';');
}

}  // namespace

void append_response(std::string& out, const Response& response, const WireOptions& options) {
  out.reserve(out.size() + 256 + response.body.size());
  out += "HTTP/1.1 ";
  append_number(out, static_cast<std::size_t>(response.status));
  out += ' ';
  out += reason_phrase(response.status);
  out += "\r\n";
  if (response.status != 204) {
    append_header(out, "Content-Type", response.content_type);
    out += "Content-Length: ";
    append_number(out, response.body.size());
    out += "\r\n";
  }
  out += kNoSniff;
  if (is_html(response.content_type)) out += kPageSecurityPolicy;
  for (const auto& [name, value] : response.headers) append_header(out, name, value);
  if (!options.request_id.empty()) append_header(out, "X-Request-Id", options.request_id);
  if (!options.allow_origin.empty()) {
    append_header(out, "Access-Control-Allow-Origin", options.allow_origin);
    append_header(out, "Access-Control-Expose-Headers", kCorsExposeHeaders);
  }
  if (options.vary_origin) out += "Vary: Origin\r\n";
  if (!options.keep_alive) {
    out += "Connection: close\r\n";
  } else {
    if (options.minor_version == 0) out += "Connection: keep-alive\r\n";
    out += "Keep-Alive: timeout=";
    append_number(out, static_cast<std::size_t>(options.keep_alive_timeout_s));
    out += "\r\n";
  }
  out += "\r\n";
  if (!options.head_only && response.status != 204) out += response.body;
}

}  // namespace bezier::service
