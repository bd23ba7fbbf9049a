#include "service/log.hpp"

#include <cstdio>

#include <spdlog/async.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

namespace bezier::service {

std::shared_ptr<spdlog::logger> make_logger(const Config& config) {
  // Asynchronous: a request thread only queues its access line; one background thread
  // formats and writes. Writing and flushing stdout on every request thread cost half
  // the throughput and added 1 s tails at 64 connections (tests/bench/http/load.sh).
  // The queue blocks when full rather than dropping lines.
  spdlog::init_thread_pool(8192, 1);
  auto logger = std::make_shared<spdlog::async_logger>(
      "bezier", std::make_shared<spdlog::sinks::stdout_sink_st>(), spdlog::thread_pool(),
      spdlog::async_overflow_policy::block);
  spdlog::register_logger(logger);
  logger->set_level(spdlog::level::from_str(config.log_level));
  if (config.log_format == LogFormat::json) {
    // Messages are written as `"msg":"...",...` fragments (see json_escape).
    logger->set_pattern(R"({"time":"%Y-%m-%dT%H:%M:%S.%fZ","level":"%l",%v})", spdlog::pattern_time_type::utc);
  } else {
    logger->set_pattern("%Y-%m-%dT%H:%M:%S.%fZ %l %v", spdlog::pattern_time_type::utc);
  }
  // Lines reach a pipe (docker logs, tests) within a second, warnings at once.
  logger->flush_on(spdlog::level::warn);
  spdlog::flush_every(std::chrono::seconds(1));
  return logger;
}

std::string json_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out;
}

}  // namespace bezier::service
