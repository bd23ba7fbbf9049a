#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <utility>

#include <spdlog/fmt/fmt.h>

#include <spdlog/logger.h>

#include "service/config.hpp"

namespace bezier::service {

/// The service's one logger, on stdout, in the configured level and format: text lines,
/// or one JSON object per line ({"time", "level", "msg", ...fields}) for log shippers.
[[nodiscard]] std::shared_ptr<spdlog::logger> make_logger(const Config& config);

/// `text` as the inside of a JSON string (quotes, backslashes and control characters
/// escaped), for building JSON log lines by hand on the request path.
[[nodiscard]] std::string json_escape(std::string_view text);

/// The service's logger with its format: messages go out as plain text, or in the JSON
/// format as a "msg" member, so every line is one valid JSON object.
class Log {
 public:
  Log(std::shared_ptr<spdlog::logger> logger, LogFormat format)
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

  [[nodiscard]] spdlog::logger& logger() noexcept { return *logger_; }
  [[nodiscard]] LogFormat format() const noexcept { return format_; }

 private:
  std::shared_ptr<spdlog::logger> logger_;
  LogFormat format_;
};


}  // namespace bezier::service
