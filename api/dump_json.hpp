#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace bezier::api {

/// Writes `value` as compact JSON text, as nlohmann's dump() with invalid UTF-8 replaced
/// does: members in key order, numbers as the shortest text that reads back to the same
/// double (std::to_chars, laid out by nlohmann's rules: "1.0", "0.001", "1e-05",
/// "1.5e+20"), non-finite numbers as null, control characters escaped and each byte of an
/// invalid UTF-8 sequence replaced by U+FFFD. It is a fraction of nlohmann's cost: its
/// string writer decodes every byte through a UTF-8 state machine, which made the answer
/// of a problem+json half the time of the request.
[[nodiscard]] std::string dump_json(const nlohmann::json& value);

/// One string or number in exactly the text dump_json gives it, appended to `out`.
void append_json_string(std::string_view text, std::string& out);
void append_json_number(double value, std::string& out);

}  // namespace bezier::api
