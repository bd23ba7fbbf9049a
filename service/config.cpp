#include "service/config.hpp"

#include <cstdlib>
#include <sstream>

#include <CLI/CLI.hpp>

#include "service/version.hpp"

namespace bezier::service {

bool is_cors_origin(std::string_view value) noexcept {
  if (value == "*") return true;
  // RFC 6454 §6.2: scheme "://" host [":" port]; a browser sends it lower-case, without
  // a path, query or trailing slash.
  const std::size_t separator = value.find("://");
  if (separator == std::string_view::npos || separator == 0) return false;
  for (std::size_t i = 0; i < separator; ++i) {
    const char c = value[i];
    const bool letter = c >= 'a' && c <= 'z';
    if (!(letter || (i > 0 && ((c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.')))) return false;
  }
  const std::string_view authority = value.substr(separator + 3);
  if (authority.empty()) return false;
  for (const char c : authority) {
    const bool allowed = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '.' || c == ':' ||
                         c == '[' || c == ']';
    if (!allowed) return false;
  }
  // host [":" port]: an IPv6 literal in brackets, or a name or IPv4 address without ':'
  // or brackets; the port, when given, decimal digits naming a TCP port (at most 65535).
  std::string_view port;
  if (authority.front() == '[') {
    const std::size_t close = authority.find(']');
    if (close == std::string_view::npos || close == 1) return false;
    const std::string_view after = authority.substr(close + 1);
    if (!after.empty() && after.front() != ':') return false;
    if (authority.substr(1, close - 1).find_first_of("[]") != std::string_view::npos) return false;
    if (!after.empty()) port = after.substr(1);
    if (!after.empty() && port.empty()) return false;
  } else {
    const std::size_t colon = authority.find(':');
    const std::string_view host = authority.substr(0, colon);
    if (host.empty() || host.find_first_of("[]") != std::string_view::npos) return false;
    if (colon != std::string_view::npos) {
      port = authority.substr(colon + 1);
      if (port.empty()) return false;
    }
  }
  if (port.size() > 5) return false;
  unsigned number = 0;
  for (const char c : port) {
    if (c < '0' || c > '9') return false;
    number = number * 10 + static_cast<unsigned>(c - '0');
  }
  return number <= 65535;
}

ParsedConfig parse_config(int argc, char** argv) {
  Config config;
  CLI::App app{"bezier-service: a Bézier-curve geometry kernel behind a JSON/HTTP API"};
  app.set_version_flag("--version", "bezier-service " + std::string(kServiceVersion));
  app.add_option("--host", config.host, "Address to bind")->envname("BEZIER_HOST")->capture_default_str();
  app.add_option("--port", config.port, "Port to listen on (0 picks a free port)")
      ->envname("BEZIER_PORT")->check(CLI::Range(0, 65535))->capture_default_str();
  // One engine is left; the flag stays so that deployments that name it keep starting,
  // and any other value stops start-up with a message that says why.
  std::string engine = "epoll";
  app.add_option("--http-engine", engine, "HTTP front end: epoll (event loops + compute pool), the only one")
      ->envname("BEZIER_HTTP_ENGINE")
      ->check(CLI::Validator(
          [](const std::string& value) -> std::string {
            if (value == "epoll") return {};
            return "unknown HTTP engine '" + value + "': the only engine is epoll";
          },
          "epoll"))
      ->capture_default_str();
  app.add_option("--threads", config.threads, "Compute pool threads (the requests too expensive for an event loop)")
      ->envname("BEZIER_THREADS")->check(CLI::Range(1, 1024))->capture_default_str();
  app.add_option("--io-threads", config.io_threads, "Event loops (I/O threads), 0 = one per CPU the process may use (affinity mask, cgroup cpu.max)")
      ->envname("BEZIER_IO_THREADS")->check(CLI::Range(0, 256))->capture_default_str();
  app.add_option("--max-queued-requests", config.max_queued_requests,
                 "Requests waiting for a compute thread (503 beyond)")
      ->envname("BEZIER_MAX_QUEUED_REQUESTS")->check(CLI::Range(1, 1000000))->capture_default_str();
  app.add_option("--queue-deadline", config.queue_deadline_s,
                 "Seconds a request may wait for a compute thread (503 beyond, instead of computing it)")
      ->envname("BEZIER_QUEUE_DEADLINE")->check(CLI::Range(0.001, 3600.0))->capture_default_str();
  app.add_option("--max-connections", config.max_connections,
                 "Most connections served at once (beyond it 503)")
      ->envname("BEZIER_MAX_CONNECTIONS")->check(CLI::Range(1, 65536))->capture_default_str();
  app.add_option("--keep-alive-timeout", config.keep_alive_timeout_s, "Seconds an idle keep-alive connection stays open")
      ->envname("BEZIER_KEEP_ALIVE_TIMEOUT")->check(CLI::Range(0, 3600))->capture_default_str();
  app.add_option("--keep-alive-max-requests", config.keep_alive_max_requests, "Requests served per connection")
      ->envname("BEZIER_KEEP_ALIVE_MAX_REQUESTS")->check(CLI::Range(1, 1000000))->capture_default_str();
  app.add_option("--read-timeout", config.read_timeout_s, "Seconds to wait for request bytes")
      ->envname("BEZIER_READ_TIMEOUT")->check(CLI::Range(1, 3600))->capture_default_str();
  app.add_option("--write-timeout", config.write_timeout_s, "Seconds to wait while writing an answer")
      ->envname("BEZIER_WRITE_TIMEOUT")->check(CLI::Range(1, 3600))->capture_default_str();
  app.add_option("--drain-seconds", config.drain_seconds, "After SIGTERM, seconds /readyz says 503 before the listener closes")
      ->envname("BEZIER_DRAIN_SECONDS")->check(CLI::Range(0.0, 3600.0))->capture_default_str();
  app.add_option("--shutdown-timeout", config.shutdown_timeout_seconds,
                 "After the listener closes, seconds in-flight requests get before the process exits anyway (status 1)")
      ->envname("BEZIER_SHUTDOWN_TIMEOUT")->check(CLI::Range(0.0, 3600.0))->capture_default_str();
  app.add_option("--max-body-bytes", config.limits.max_body_bytes, "Largest request body (413 above)")
      ->envname("BEZIER_MAX_BODY_BYTES")->check(CLI::Range(std::size_t{64}, std::size_t{1} << 30))->capture_default_str();
  app.add_option("--max-degree", config.limits.max_degree, "Highest curve degree accepted")
      ->envname("BEZIER_MAX_DEGREE")->check(CLI::Range(1, 1000))->capture_default_str();
  app.add_option("--max-t-values", config.limits.max_t_values, "Most t values or samples per request")
      ->envname("BEZIER_MAX_T_VALUES")->check(CLI::Range(1, 10000000))->capture_default_str();
  app.add_option("--max-path-segments", config.limits.max_path_segments, "Most segments in one SVG path (422 above)")
      ->envname("BEZIER_MAX_PATH_SEGMENTS")->check(CLI::Range(1, 10000000))->capture_default_str();
  app.add_option("--max-work", config.limits.max_work, "Per-request work cap of iterative kernels (work units, about 3-6 ns each)")
      ->envname("BEZIER_MAX_WORK")->check(CLI::Range(std::int64_t{1000}, std::int64_t{1} << 40))->capture_default_str();
  app.add_option("--max-request-memory", config.limits.max_request_memory,
                 "Most bytes a request's kernel call may store for the segment pairs its paths meet in (422 above)")
      ->envname("BEZIER_MAX_REQUEST_MEMORY")->check(CLI::Range(std::int64_t{1024}, std::int64_t{1} << 40))
      ->capture_default_str();
  app.add_option("--max-batch-items", config.limits.max_batch_items, "Most items in one POST /batch (422 above)")
      ->envname("BEZIER_MAX_BATCH_ITEMS")->check(CLI::Range(1, 1000000))->capture_default_str();
  app.add_option("--max-batch-work", config.limits.max_batch_work,
                 "Work cap of a whole batch: each item of a work-capped route is charged --max-work (422 above)")
      ->envname("BEZIER_MAX_BATCH_WORK")->check(CLI::Range(std::int64_t{1000}, std::int64_t{1} << 50))
      ->capture_default_str();
  app.add_option("--max-batch-answer-bytes", config.limits.max_batch_answer_bytes,
                 "Largest answer of a whole batch (422 when its items' answers exceed it)")
      ->envname("BEZIER_MAX_BATCH_ANSWER_BYTES")
      ->check(CLI::Range(std::size_t{1024}, std::size_t{1} << 34))->capture_default_str();
  app.add_option("--cors-origin", config.cors_origins,
                 "Origin allowed to call the service from a browser (CORS), as scheme://host[:port], or * for any; "
                 "repeatable, or comma-separated in the variable; none: CORS off")
      ->envname("BEZIER_CORS_ORIGIN")->delimiter(',')->take_all()
      ->check(CLI::Validator(
          [](const std::string& value) -> std::string {
            if (is_cors_origin(value)) return {};
            return "'" + value + "' is not an origin: * or scheme://host[:port], no path, no trailing slash";
          },
          "ORIGIN"));
  app.add_option("--log-level", config.log_level, "trace, debug, info, warn, error, critical or off")
      ->envname("BEZIER_LOG_LEVEL")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "critical", "off"}))
      ->capture_default_str();
  std::string format = "text";
  app.add_option("--log-format", format, "text or json (one JSON object per line)")
      ->envname("BEZIER_LOG_FORMAT")->check(CLI::IsMember({"text", "json"}))->capture_default_str();
  // The token is read from the environment only: a flag would show in `ps`. --help lists
  // it after the flags, so that every setting is there.
  if (const char* token = std::getenv("BEZIER_AUTH_TOKEN")) config.auth_token = token;
  app.footer(
      "Environment only:\n"
      "  (Env:BEZIER_AUTH_TOKEN)     When set, POST routes need \"Authorization: Bearer <token>\"; unset,\n"
      "                              no authentication. Not a flag (a flag would show in ps); never logged");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    std::ostringstream out;
    const int code = app.exit(e, out, out);
    return {std::nullopt, code, out.str()};
  }
  config.log_format = format == "json" ? LogFormat::json : LogFormat::text;
  return {config, 0, {}};
}

}  // namespace bezier::service
