#include "service/http_request_parser.hpp"

#include <algorithm>
#include <optional>

namespace bezier::service {

namespace {

// A chunk-size line ("1a2b;name=value\r\n") longer than this is not a real client.
constexpr std::size_t kMaxChunkLine = 1024;
// Headers in one request; a browser sends about 15.
constexpr std::size_t kMaxHeaders = 100;

char lower(char c) noexcept { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

bool iequals(std::string_view a, std::string_view b) noexcept {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

// RFC 9110 §5.6.2: token characters (method and header names).
bool is_tchar(char c) noexcept {
  if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9')) return true;
  return std::string_view("!#$%&'*+-.^_`|~").find(c) != std::string_view::npos;
}

bool is_token(std::string_view s) noexcept { return !s.empty() && std::all_of(s.begin(), s.end(), is_tchar); }

std::string_view trim(std::string_view s) noexcept {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// Calls `each` with every element of a comma-separated header list, trimmed.
template <class Each>
void for_each_element(std::string_view list, Each each) {
  while (!list.empty()) {
    const std::size_t comma = list.find(',');
    const std::string_view element = trim(list.substr(0, comma));
    if (!element.empty()) each(element);
    if (comma == std::string_view::npos) break;
    list.remove_prefix(comma + 1);
  }
}

// RFC 9112 §3.2.2: the path and query of an absolute-form target
// ("http://host:port/path?query"; an empty path is "/"), or nullopt when the target is not
// an http or https URI with a non-empty authority. Userinfo ("user@host") is refused, as
// RFC 9110 §4.2.4 advises for a URI from an untrusted source.
std::optional<std::string_view> origin_of_absolute_form(std::string_view target) noexcept {
  const std::size_t colon = target.find(':');
  if (colon == std::string_view::npos) return std::nullopt;
  const std::string_view scheme = target.substr(0, colon);
  if (!iequals(scheme, "http") && !iequals(scheme, "https")) return std::nullopt;
  std::string_view rest = target.substr(colon + 1);
  if (rest.substr(0, 2) != "//") return std::nullopt;
  rest.remove_prefix(2);
  const std::size_t authority_end = std::min(rest.find('/'), rest.find('?'));
  const std::string_view authority = rest.substr(0, authority_end);
  if (authority.empty() || authority.find('@') != std::string_view::npos) return std::nullopt;
  if (authority_end == std::string_view::npos) return std::string_view("/");
  rest.remove_prefix(authority_end);
  return rest.front() == '?' ? std::string_view("/") : rest;
}

// RFC 9110 §7.2: Host = uri-host [ ":" port ], where uri-host is an IP literal in
// brackets, an IPv4 address or a reg-name (unreserved, pct-encoded, sub-delims); empty
// when the target URI has no authority.
bool is_host_value(std::string_view value) noexcept {
  constexpr std::string_view kAllowed = "-._~%!$&'()*+,;=:[]";
  return std::all_of(value.begin(), value.end(), [&](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           kAllowed.find(c) != std::string_view::npos;
  });
}

}  // namespace

std::string_view HttpRequest::header(std::string_view name) const noexcept {
  for (const Header& h : headers) {
    if (iequals(h.name, name)) return h.value;
  }
  return {};
}

void HttpRequestParser::reset() {
  phase_ = Phase::idle;
  // clear() keeps the capacity: a keep-alive connection's requests reuse the buffers.
  request_.head.clear();
  request_.headers.clear();
  request_.body.clear();
  request_.method = request_.target = request_.path = {};
  request_.minor_version = 1;
  request_.keep_alive = true;
  request_.expect_continue = false;
  error_ = {};
  remaining_ = 0;
  line_.clear();
  trailer_bytes_ = 0;
}

HttpRequestParser::Progress HttpRequestParser::fail(int status, std::string detail, std::size_t used) {
  phase_ = Phase::failed;
  error_ = {status, std::move(detail)};
  return {State::error, used};
}

HttpRequestParser::Progress HttpRequestParser::feed(std::string_view input) {
  std::size_t used = 0;
  for (;;) {
    switch (phase_) {
      case Phase::idle:
        // RFC 9112 §2.2: empty lines before a request line are ignored (some clients
        // send a CRLF after a POST body).
        while (used < input.size() && (input[used] == '\r' || input[used] == '\n')) ++used;
        if (used == input.size()) return {State::need_more, used};
        phase_ = Phase::head;
        break;

      case Phase::head: {
        std::string& head = request_.head;
        const std::size_t before = head.size();
        // Never hold more than the limit (plus one byte to know it was exceeded).
        const std::size_t room = limits_.max_head_bytes + 1 - std::min(before, limits_.max_head_bytes);
        const std::size_t take = std::min(input.size() - used, room);
        head.append(input.substr(used, take));
        const std::size_t end = head.find("\r\n\r\n", before >= 3 ? before - 3 : 0);
        // RFC 9112 §2.2: a line of the head ends in CRLF. A bare LF would never complete
        // the head (the client waits for an answer, the server for the blank line, until
        // the read timeout), and a proxy that accepts it frames differently: 400 at once.
        const std::size_t scanned = end == std::string::npos ? head.size() : end + 4;
        for (std::size_t i = before; i < scanned; ++i) {
          if (head[i] == '\n' && (i == 0 || head[i - 1] != '\r')) {
            return fail(400, "a line of the request head ends in a bare LF, not CRLF", used + take);
          }
        }
        if (end == std::string::npos || end + 4 > limits_.max_head_bytes) {
          if (head.size() <= limits_.max_head_bytes) return {State::need_more, used + take};
          if (head.find("\r\n") == std::string::npos) {
            return fail(414, "the request line is longer than " + std::to_string(limits_.max_head_bytes) + " bytes",
                        used + take);
          }
          return fail(431, "the request line and headers are longer than " +
                               std::to_string(limits_.max_head_bytes) + " bytes",
                      used + take);
        }
        used += end + 4 - before;
        head.resize(end + 4);
        if (!parse_head()) return {State::error, used};
        break;
      }

      case Phase::length_body:
      case Phase::chunk_data: {
        const std::size_t take = std::min(remaining_, input.size() - used);
        request_.body.append(input.substr(used, take));
        used += take;
        remaining_ -= take;
        if (remaining_ > 0) return {State::need_more, used};
        phase_ = phase_ == Phase::length_body ? Phase::done : Phase::chunk_data_end;
        break;
      }

      case Phase::chunk_size:
      case Phase::chunk_data_end:
      case Phase::trailers: {
        bool line_ended = false;
        while (used < input.size() && !line_ended) {
          const char c = input[used++];
          line_ += c;
          line_ended = c == '\n';
          if (line_.size() > kMaxChunkLine) return fail(400, "a chunk-size or trailer line is too long", used);
        }
        if (!line_ended) return {State::need_more, used};
        if (!chunk_line_done()) return {State::error, used};
        break;
      }

      case Phase::done:
        return {State::complete, used};
      case Phase::failed:
        return {State::error, used};
    }
  }
}

bool HttpRequestParser::parse_head() {
  std::string_view rest(request_.head);
  rest.remove_suffix(2);  // the blank line's CRLF; every line below ends in CRLF
  const std::size_t line_end = rest.find("\r\n");
  if (!parse_request_line(rest.substr(0, line_end))) return false;
  rest.remove_prefix(line_end + 2);
  while (!rest.empty()) {
    const std::size_t eol = rest.find("\r\n");
    const std::string_view line = rest.substr(0, eol);
    rest.remove_prefix(eol + 2);
    if (line.front() == ' ' || line.front() == '\t') {
      fail(400, "obsolete line folding in a header", 0);  // RFC 9112 §5.2
      return false;
    }
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos || !is_token(line.substr(0, colon))) {
      fail(400, "malformed header line", 0);
      return false;
    }
    const std::string_view value = trim(line.substr(colon + 1));
    for (const char c : value) {
      if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f) {
        fail(400, "control character in a header value", 0);
        return false;
      }
    }
    if (request_.headers.size() == kMaxHeaders) {
      fail(431, "more than " + std::to_string(kMaxHeaders) + " headers", 0);
      return false;
    }
    request_.headers.push_back({line.substr(0, colon), value});
  }
  return check_single_fields() && parse_framing();
}

bool HttpRequestParser::check_single_fields() {
  int hosts = 0;
  int codings = 0;
  int authorizations = 0;
  for (const HttpRequest::Header& h : request_.headers) {
    if (iequals(h.name, "host")) {
      ++hosts;
      if (!is_host_value(h.value)) {
        fail(400, "the Host header is not host[:port]", 0);
        return false;
      }
    } else if (iequals(h.name, "content-encoding")) {
      ++codings;
    } else if (iequals(h.name, "authorization")) {
      ++authorizations;
    }
  }
  // RFC 9112 §3.2: a server must answer 400 to an HTTP/1.1 request without Host, and to
  // any request with more than one.
  if (hosts > 1 || (hosts == 0 && request_.minor_version == 1)) {
    fail(400, hosts == 0 ? "an HTTP/1.1 request must have a Host header" : "more than one Host header", 0);
    return false;
  }
  // Which codings apply would depend on whether a reader joins the lines or takes one.
  if (codings > 1) {
    fail(400, "more than one Content-Encoding header", 0);
    return false;
  }
  // RFC 9110 §11.6.2 defines one set of credentials; with two, the server and a proxy in
  // front of it might each check a different one.
  if (authorizations > 1) {
    fail(400, "more than one Authorization header", 0);
    return false;
  }
  return true;
}

bool HttpRequestParser::parse_request_line(std::string_view line) {
  const std::size_t sp1 = line.find(' ');
  const std::size_t sp2 = sp1 == std::string_view::npos ? sp1 : line.find(' ', sp1 + 1);
  if (sp2 == std::string_view::npos || line.find(' ', sp2 + 1) != std::string_view::npos) {
    fail(400, "the request line is not 'METHOD TARGET HTTP/1.x'", 0);
    return false;
  }
  request_.method = line.substr(0, sp1);
  request_.target = line.substr(sp1 + 1, sp2 - sp1 - 1);
  const std::string_view version = line.substr(sp2 + 1);
  if (!is_token(request_.method)) {
    fail(400, "malformed method", 0);
    return false;
  }
  for (const char c : request_.target) {
    if (static_cast<unsigned char>(c) <= 0x20 || c == 0x7f) {
      fail(400, "control character in the request target", 0);
      return false;
    }
  }
  // RFC 9112 §3.2: origin-form ("/path?query"), absolute-form (a URI), or "*" for OPTIONS.
  const bool asterisk = request_.target == "*" && request_.method == "OPTIONS";
  std::optional<std::string_view> origin = request_.target;
  if (request_.target.empty()) {
    origin = std::nullopt;
  } else if (request_.target.front() != '/' && !asterisk) {
    origin = origin_of_absolute_form(request_.target);
  }
  if (!origin) {
    fail(400, "the request target must be a path starting with '/' or an absolute http URI", 0);
    return false;
  }
  request_.path = origin->substr(0, origin->find('?'));
  if (version.size() != 8 || version.substr(0, 5) != "HTTP/" || version[6] != '.' ||
      !(version[5] >= '0' && version[5] <= '9') || !(version[7] >= '0' && version[7] <= '9')) {
    fail(400, "malformed HTTP version", 0);
    return false;
  }
  if (version[5] != '1' || (version[7] != '0' && version[7] != '1')) {
    fail(505, "only HTTP/1.0 and HTTP/1.1 are served", 0);
    return false;
  }
  request_.minor_version = version[7] - '0';
  return true;
}

bool HttpRequestParser::parse_framing() {
  bool has_length = false;
  bool chunked = false;
  std::size_t length = 0;
  bool close = false;
  bool keep_alive = false;
  for (const HttpRequest::Header& h : request_.headers) {
    if (iequals(h.name, "content-length")) {
      // RFC 9112 §6.3: 1*DIGIT; several must agree (else the framing is ambiguous).
      std::size_t value = 0;
      bool too_large = false;
      if (h.value.empty()) {
        fail(400, "empty Content-Length", 0);
        return false;
      }
      for (const char c : h.value) {
        if (c < '0' || c > '9') {
          fail(400, "Content-Length is not a number", 0);
          return false;
        }
        too_large = too_large || value > (limits_.max_body_bytes + 9) / 10;
        if (!too_large) value = value * 10 + static_cast<std::size_t>(c - '0');
      }
      if (too_large) value = limits_.max_body_bytes + 1;
      if (has_length && value != length) {
        fail(400, "conflicting Content-Length headers", 0);
        return false;
      }
      has_length = true;
      length = value;
    } else if (iequals(h.name, "transfer-encoding")) {
      bool only_chunked = true;
      int codings = 0;
      for_each_element(h.value, [&](std::string_view coding) {
        ++codings;
        only_chunked = only_chunked && iequals(coding, "chunked");
      });
      if (!only_chunked || codings != 1 || chunked) {
        fail(501, "only 'Transfer-Encoding: chunked' is supported", 0);
        return false;
      }
      chunked = true;
    } else if (iequals(h.name, "connection")) {
      for_each_element(h.value, [&](std::string_view option) {
        close = close || iequals(option, "close");
        keep_alive = keep_alive || iequals(option, "keep-alive");
      });
    } else if (iequals(h.name, "expect")) {
      request_.expect_continue = request_.minor_version == 1 && iequals(h.value, "100-continue");
    }
  }
  if (chunked && (has_length || request_.minor_version == 0)) {
    // RFC 9112 §6.1: both is a smuggling attempt; chunked is not HTTP/1.0.
    fail(400, has_length ? "both Content-Length and Transfer-Encoding" : "chunked transfer coding in HTTP/1.0", 0);
    return false;
  }
  request_.keep_alive = request_.minor_version == 1 ? !close : keep_alive && !close;
  if (length > limits_.max_body_bytes) {
    fail(413, "the body is larger than " + std::to_string(limits_.max_body_bytes) + " bytes", 0);
    return false;
  }
  if (chunked) {
    phase_ = Phase::chunk_size;
  } else if (length > 0) {
    request_.body.reserve(length);
    remaining_ = length;
    phase_ = Phase::length_body;
  } else {
    phase_ = Phase::done;
  }
  return true;
}

bool HttpRequestParser::chunk_line_done() {
  if (line_.size() < 2 || line_[line_.size() - 2] != '\r') {
    fail(400, "a chunk line does not end in CRLF", 0);
    return false;
  }
  const std::string_view line(line_.data(), line_.size() - 2);
  switch (phase_) {
    case Phase::chunk_size: {
      // chunk-size [ ";" chunk-ext ]: hexadecimal; extensions are ignored.
      const std::string_view size_text = trim(line.substr(0, line.find(';')));
      std::size_t size = 0;
      bool too_large = false;
      if (size_text.empty()) {
        fail(400, "missing chunk size", 0);
        return false;
      }
      for (const char c : size_text) {
        const char l = lower(c);
        const int digit = l >= '0' && l <= '9' ? l - '0' : l >= 'a' && l <= 'f' ? l - 'a' + 10 : -1;
        if (digit < 0) {
          fail(400, "the chunk size is not hexadecimal", 0);
          return false;
        }
        too_large = too_large || size > limits_.max_body_bytes;
        if (!too_large) size = size * 16 + static_cast<std::size_t>(digit);
      }
      if (too_large || size > limits_.max_body_bytes - request_.body.size()) {
        fail(413, "the body is larger than " + std::to_string(limits_.max_body_bytes) + " bytes", 0);
        return false;
      }
      remaining_ = size;
      phase_ = size == 0 ? Phase::trailers : Phase::chunk_data;
      break;
    }
    case Phase::chunk_data_end:
      if (!line.empty()) {
        fail(400, "chunk data is longer than its size", 0);
        return false;
      }
      phase_ = Phase::chunk_size;
      break;
    default:  // trailers: ignored, but bounded like the head
      trailer_bytes_ += line_.size();
      if (trailer_bytes_ > limits_.max_head_bytes) {
        fail(431, "the trailers are longer than " + std::to_string(limits_.max_head_bytes) + " bytes", 0);
        return false;
      }
      if (line.empty()) phase_ = Phase::done;
      break;
  }
  line_.clear();
  return true;
}

}  // namespace bezier::service
