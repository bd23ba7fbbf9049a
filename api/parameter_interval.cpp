#include "api/parameter_interval.hpp"

#include <string>

namespace bezier::api {

std::optional<ParameterInterval> read_interval(RequestReader& reader, const Json& value,
                                               SinglePointInterval single_point) {
  const bool apart = single_point == SinglePointInterval::refused;
  const auto ts = reader.numbers(value, "/interval", 0.0, 1.0);
  if (!ts) return std::nullopt;
  if (ts->size() != 2) {
    reader.fail("/interval", std::string("expected exactly 2 numbers ") + (apart ? "[t1, t2]" : "[a, b]") +
                                 ", got " + std::to_string(ts->size()));
    return std::nullopt;
  }
  const double a = (*ts)[0], b = (*ts)[1];
  if (apart ? !(a < b) : !(a <= b)) {
    reader.fail("/interval", apart ? "must be increasing: interval[0] < interval[1]"
                                   : "must not be reversed: interval[0] <= interval[1]");
    return std::nullopt;
  }
  return ParameterInterval{a, b};
}

std::optional<ParameterInterval> read_parameter_interval(RequestReader& reader, const Json& request) {
  const Json* value = RequestReader::optional(request, "interval");
  if (value == nullptr) return ParameterInterval{};
  return read_interval(reader, *value, SinglePointInterval::allowed);
}

}  // namespace bezier::api
