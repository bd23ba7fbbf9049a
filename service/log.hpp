#pragma once

#include <memory>
#include <string>

#include <spdlog/logger.h>

#include "service/config.hpp"

namespace bezier::service {

/// The service's one logger, on stdout, in the configured level and format: text lines,
/// or one JSON object per line ({"time", "level", "msg", ...fields}) for log shippers.
[[nodiscard]] std::shared_ptr<spdlog::logger> make_logger(const Config& config);

/// `text` as the inside of a JSON string (quotes, backslashes and control characters
/// escaped), for building JSON log lines by hand on the request path.
[[nodiscard]] std::string json_escape(std::string_view text);

}  // namespace bezier::service
