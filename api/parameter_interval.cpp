#include "api/parameter_interval.hpp"

#include <string>

namespace bezier::api {

std::optional<ParameterInterval> read_parameter_interval(RequestReader& reader,
                                                         const Json& request) {
  const Json* value = RequestReader::optional(request, "interval");
  if (value == nullptr) return ParameterInterval{};
  const auto ts = reader.numbers(*value, "/interval", 0.0, 1.0);
  if (!ts) return std::nullopt;
  if (ts->size() != 2) {
    reader.fail("/interval", "expected exactly 2 numbers [a, b], got " + std::to_string(ts->size()));
    return std::nullopt;
  }
  if (!((*ts)[0] <= (*ts)[1])) {
    reader.fail("/interval", "must not be reversed: interval[0] <= interval[1]");
    return std::nullopt;
  }
  return ParameterInterval{(*ts)[0], (*ts)[1]};
}

}  // namespace bezier::api
