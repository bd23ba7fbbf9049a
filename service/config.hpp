#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "api/limits.hpp"

namespace bezier::service {

enum class LogFormat { text, json };

/// Everything the executable is told at start, parsed once from flags and environment
/// variables (a flag wins over its variable), then immutable.
struct Config {
  std::string host = "127.0.0.1";
  int port = 8080;
  /// The compute pool's threads: they run the requests too expensive for an I/O thread.
  int threads = 8;
  /// Event loops (I/O threads); 0 means one per CPU the process may use (its affinity
  /// mask and cgroup CPU quota, service/cpu_budget.hpp).
  int io_threads = 0;
  /// Requests waiting for a compute thread; beyond it 503 + Retry-After.
  int max_queued_requests = 1024;
  /// Seconds a request may wait for a compute thread: past it, it is answered 503 +
  /// Retry-After instead of computed (its client has likely given up already).
  double queue_deadline_s = 2.0;
  int max_connections = 1024;
  /// Seconds an idle keep-alive connection is kept, and requests served per connection.
  int keep_alive_timeout_s = 5;
  int keep_alive_max_requests = 1000;
  /// Seconds to wait for a request's bytes (slow clients) and to write an answer.
  int read_timeout_s = 5;
  int write_timeout_s = 5;
  /// After SIGTERM: seconds /readyz answers 503 while still serving, so a load
  /// balancer can stop sending before the listener closes.
  double drain_seconds = 0.0;
  /// After the listener closes: seconds in-flight requests get to finish (a client
  /// sending a byte a second could otherwise hold the exit forever). Past it the process
  /// exits with status 1.
  double shutdown_timeout_seconds = 20.0;
  std::string log_level = "info";
  LogFormat log_format = LogFormat::text;
  /// Optional bearer token; empty means no authentication. Never logged.
  std::string auth_token;
  /// Origins whose browser pages may call the service (CORS): each "scheme://host[:port]"
  /// exactly as a browser sends it in Origin, or "*" for any. Empty: CORS is off.
  std::vector<std::string> cors_origins;
  api::Limits limits;
};

/// The outcome of reading the command line: a config, or an exit code with the text
/// to print (for --help, --version or a bad flag).
struct ParsedConfig {
  std::optional<Config> config;
  int exit_code = 0;
  std::string message;
};

/// Whether `value` may be given to --cors-origin: "*", or an origin as a browser
/// serializes it in the Origin header (lower-case scheme "://" host [":" port]).
[[nodiscard]] bool is_cors_origin(std::string_view value) noexcept;

/// Reads flags (argv) and BEZIER_* environment variables.
[[nodiscard]] ParsedConfig parse_config(int argc, char** argv);

}  // namespace bezier::service
