#include "service/log.hpp"

#include <cstdio>

#include <spdlog/async.h>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

namespace bezier::service {

std::shared_ptr<spdlog::async_logger> make_logger(const Config& config) {
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

namespace {

bool is_continuation(unsigned char byte) noexcept { return (byte & 0xC0) == 0x80; }

// The length of the well-formed UTF-8 sequence at the start of `text` (RFC 3629 §4:
// no overlong forms, no surrogates, nothing above U+10FFFF), or 0 if there is none.
std::size_t utf8_sequence_length(std::string_view text) noexcept {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(0);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned char second_low = 0x80;
  unsigned char second_high = 0xBF;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) second_low = 0xA0;   // overlong below U+0800
    if (lead == 0xED) second_high = 0x9F;  // surrogates U+D800..U+DFFF
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) second_low = 0x90;   // overlong below U+10000
    if (lead == 0xF4) second_high = 0x8F;  // above U+10FFFF
  } else {
    return 0;  // a continuation byte, C0, C1 or F5..FF
  }
  if (text.size() < length || byte(1) < second_low || byte(1) > second_high) return 0;
  for (std::size_t i = 2; i < length; ++i) {
    if (!is_continuation(byte(i))) return 0;
  }
  return length;
}

void append_hex_escape(std::string& out, std::string_view prefix, unsigned value) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%02x", value);
  out += prefix;
  out += buf;
}

}  // namespace

std::string json_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  while (!text.empty()) {
    const auto c = static_cast<unsigned char>(text.front());
    if (c == '"') {
      out += "\\\"";
    } else if (c == '\\') {
      out += "\\\\";
    } else if (c < 0x20) {
      append_hex_escape(out, "\\u00", c);
    } else if (c >= 0x80) {
      if (const std::size_t length = utf8_sequence_length(text)) {
        out.append(text.substr(0, length));
        text.remove_prefix(length);
        continue;
      }
      append_hex_escape(out, "\\\\x", c);  // JSON "\\xHH": the text \xHH
    } else {
      out += static_cast<char>(c);
    }
    text.remove_prefix(1);
  }
  return out;
}

LogField LogField::text(std::string_view name, std::string_view value) {
  std::string quoted;
  quoted.reserve(value.size() + 2);
  quoted += '"';
  quoted += json_escape(value);
  quoted += '"';
  return {name, std::move(quoted)};
}

LogField LogField::number(std::string_view name, long long value) { return {name, std::to_string(value)}; }

LogField LogField::flag(std::string_view name, bool value) { return {name, value ? "true" : "false"}; }

std::string log_line_body(LogFormat format, std::string_view message, std::initializer_list<LogField> fields) {
  std::string body;
  if (format == LogFormat::json) {
    body = "\"msg\":\"";
    body += json_escape(message);
    body += '"';
    for (const LogField& field : fields) {
      body += ",\"";
      body += field.name;
      body += "\":";
      body += field.json_value;
    }
    return body;
  }
  body = message;
  for (const LogField& field : fields) {
    body += ' ';
    body += field.name;
    body += '=';
    const bool quoted = field.json_value.size() >= 2 && field.json_value.front() == '"';
    body += quoted ? std::string_view(field.json_value).substr(1, field.json_value.size() - 2)
                   : std::string_view(field.json_value);
  }
  return body;
}

void Log::always(spdlog::level::level_enum level, std::string_view message, std::initializer_list<LogField> fields) {
  const std::string body = log_line_body(format_, message, fields);
  // Posted to the writer thread like any line, past the logger's level check.
  spdlog::thread_pool()->post_log(std::shared_ptr<spdlog::async_logger>(logger_),
                                  spdlog::details::log_msg(logger_->name(), level, body),
                                  spdlog::async_overflow_policy::block);
  logger_->flush();
}

}  // namespace bezier::service
