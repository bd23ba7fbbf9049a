#pragma once

#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include <spdlog/fmt/fmt.h>

#include <spdlog/async_logger.h>

#include "service/config.hpp"

namespace bezier::service {

/// The service's one logger, on stdout, in the configured level and format: text lines,
/// or one JSON object per line ({"time", "level", "msg", ...fields}) for log shippers.
/// Asynchronous: one background thread formats and writes.
[[nodiscard]] std::shared_ptr<spdlog::async_logger> make_logger(const Config& config);

/// `text` as the inside of a JSON string, for building JSON log lines by hand on the
/// request path: quotes, backslashes and control characters escaped, and every byte
/// that is not part of a well-formed UTF-8 sequence (RFC 3629) written as the four
/// characters \xHH (in JSON "\\xHH"), so the line stays valid UTF-8 JSON whatever a
/// client sent and the bytes can still be read back.
[[nodiscard]] std::string json_escape(std::string_view text);

/// A field of a log line beyond its message: `name` and its value, already JSON (a
/// number, true or false, or a quoted, escaped string). In the text format it is written
/// as name=value, a string without its quotes.
struct LogField {
  std::string_view name;
  std::string json_value;

  [[nodiscard]] static LogField text(std::string_view name, std::string_view value);
  [[nodiscard]] static LogField number(std::string_view name, long long value);
  [[nodiscard]] static LogField flag(std::string_view name, bool value);
};

/// `message` with `fields` as the body of one log line in `format` (what follows the
/// time and level: `"msg":"...","name":value,...` in JSON, `message name=value ...` in text).
[[nodiscard]] std::string log_line_body(LogFormat format, std::string_view message,
                                        std::initializer_list<LogField> fields);

/// The service's logger with its format: messages go out as plain text, or in the JSON
/// format as a "msg" member, so every line is one valid JSON object.
class Log {
 public:
  Log(std::shared_ptr<spdlog::async_logger> logger, LogFormat format)
      : logger_(std::move(logger)), format_(format) {}

  template <class... Args>
  void write(spdlog::level::level_enum level, fmt::format_string<Args...> text, Args&&... args) {
    if (!logger_->should_log(level)) return;
    const std::string message = fmt::format(text, std::forward<Args>(args)...);
    if (format_ == LogFormat::json) {
      logger_->log(level, "\"msg\":\"{}\"", json_escape(message));
    } else {
      logger_->log(level, "{}", message);
    }
  }
  template <class... Args>
  void info(fmt::format_string<Args...> text, Args&&... args) {
    write(spdlog::level::info, text, std::forward<Args>(args)...);
  }
  template <class... Args>
  void warn(fmt::format_string<Args...> text, Args&&... args) {
    write(spdlog::level::warn, text, std::forward<Args>(args)...);
  }
  template <class... Args>
  void error(fmt::format_string<Args...> text, Args&&... args) {
    write(spdlog::level::err, text, std::forward<Args>(args)...);
  }
  template <class... Args>
  void critical(fmt::format_string<Args...> text, Args&&... args) {
    write(spdlog::level::critical, text, std::forward<Args>(args)...);
  }

  /// Writes `message` with `fields` at `level` whatever the configured level: the line
  /// that tells where the service listens must reach its output even at --log-level
  /// warn or off (scripts and tests read the port from it). Flushed at once.
  void always(spdlog::level::level_enum level, std::string_view message, std::initializer_list<LogField> fields);

  [[nodiscard]] spdlog::logger& logger() noexcept { return *logger_; }
  [[nodiscard]] LogFormat format() const noexcept { return format_; }

 private:
  std::shared_ptr<spdlog::async_logger> logger_;
  LogFormat format_;
};


}  // namespace bezier::service
