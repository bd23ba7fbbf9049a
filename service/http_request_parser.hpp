#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace bezier::service {

/// One parsed HTTP/1.x request. The head (request line and headers) is kept as one
/// string and every field is a view into it, so a request costs two allocations (head,
/// body) however many headers it has.
struct HttpRequest {
  std::string head;
  std::string_view method;
  std::string_view target;  ///< as sent: "/evaluate?x=1", or "http://host/evaluate?x=1"
  std::string_view path;    ///< the target's path, without scheme, authority or query
  int minor_version = 1;    ///< HTTP/1.0 or HTTP/1.1
  struct Header {
    std::string_view name;
    std::string_view value;  ///< without surrounding spaces and tabs
  };
  std::vector<Header> headers;
  std::string body;  ///< de-chunked when sent with Transfer-Encoding: chunked
  /// HTTP/1.1 unless "Connection: close"; HTTP/1.0 only with "Connection: keep-alive".
  bool keep_alive = true;
  bool expect_continue = false;  ///< "Expect: 100-continue" (HTTP/1.1)

  /// The first header called `name` (ASCII case-insensitive), empty when absent.
  [[nodiscard]] std::string_view header(std::string_view name) const noexcept;
};

/// Limits the parser enforces while reading, before the request is complete.
struct ParserLimits {
  /// Request line plus headers (and a chunked body's trailers), CRLFs included: 431
  /// above it (414 when the request line alone exceeds it).
  std::size_t max_head_bytes = 16 * 1024;
  /// The body after de-chunking: 413 above it, decided from Content-Length before a
  /// byte of the body is read.
  std::size_t max_body_bytes = 1 << 20;
};

/// Why a request was refused: the HTTP status to answer (400, 413, 414, 431, 501, 505)
/// and a sentence for the problem's detail. The connection is closed after the answer:
/// the rest of the stream cannot be trusted to start at a request boundary.
struct ParseError {
  int status = 400;
  std::string detail;
};

/// An incremental HTTP/1.1 request parser (RFC 9112): bytes go in as they arrive, in
/// any split; a request comes out once complete. Pipelined requests are handled by
/// feeding the bytes after a completed request into the next one (feed() reports how
/// many it used). Content-Length bodies and chunked transfer coding are accepted, both
/// within ParserLimits; anything ambiguous (both, or two different lengths: request
/// smuggling; two Host or Content-Encoding headers) is an error, and so is an HTTP/1.1
/// request without Host. The target may be in origin form ("/path?query") or absolute
/// form ("http://host/path?query"). Not thread-safe: one parser per connection.
class HttpRequestParser {
 public:
  enum class State {
    need_more,  ///< every byte was used; feed more
    complete,   ///< request() is ready; the bytes after it were not used
    error,      ///< error() says why; stop reading
  };
  struct Progress {
    State state;
    std::size_t used;  ///< bytes of the input that belong to this request
  };

  explicit HttpRequestParser(ParserLimits limits) : limits_(limits) {}

  /// Consumes bytes until the request is complete or an error is found.
  Progress feed(std::string_view input);

  /// Whether any byte of a request has been received (timeouts: idle vs. reading).
  [[nodiscard]] bool started() const noexcept { return phase_ != Phase::idle; }
  /// Whether the head has been parsed and the body is still to come: the moment to send
  /// "100 Continue" to a client that asked for it.
  [[nodiscard]] bool awaiting_body() const noexcept {
    return phase_ == Phase::length_body || phase_ == Phase::chunk_size || phase_ == Phase::chunk_data ||
           phase_ == Phase::chunk_data_end || phase_ == Phase::trailers;
  }
  [[nodiscard]] const HttpRequest& request() const noexcept { return request_; }
  [[nodiscard]] HttpRequest& request() noexcept { return request_; }
  [[nodiscard]] const ParseError& error() const noexcept { return error_; }

  /// Ready for the next request on the same connection.
  void reset();

 private:
  enum class Phase { idle, head, length_body, chunk_size, chunk_data, chunk_data_end, trailers, done, failed };

  Progress fail(int status, std::string detail, std::size_t used);
  /// Parses request_.head once its blank line has arrived; false on error.
  bool parse_head();
  bool parse_request_line(std::string_view line);
  /// Host (exactly one on HTTP/1.1, at most one on 1.0) and Content-Encoding (at most one).
  bool check_single_fields();
  bool parse_framing();
  /// One line of a chunked body (size line or trailer) from line_; false on error.
  bool chunk_line_done();

  ParserLimits limits_;
  Phase phase_ = Phase::idle;
  HttpRequest request_;
  ParseError error_;
  std::size_t remaining_ = 0;  ///< body bytes (length_body) or chunk bytes still expected
  std::string line_;           ///< a chunk-size or trailer line being assembled
  std::size_t trailer_bytes_ = 0;
};

}  // namespace bezier::service
