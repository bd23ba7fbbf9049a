#include "api/read_tolerance.hpp"

#include <algorithm>
#include <optional>
#include <string>

#include "api/write_json.hpp"

namespace bezier::api {

double read_positive_tolerance(RequestReader& reader, const Json& request) {
  const Json* value = reader.required(request, "tolerance", "");
  if (value == nullptr) return 0.0;
  const std::optional<double> given = reader.number(*value, "/tolerance");
  if (given && !(*given > 0.0)) reader.fail("/tolerance", "must be greater than 0");
  return given.value_or(0.0);
}

bool tolerance_fits_scale(RequestReader& reader, double tolerance, double scale) {
  const double smallest = kSmallestRelativeTolerance * scale;
  if (tolerance >= smallest) return true;
  std::string text;
  append_json_number(smallest, text);
  reader.fail("/tolerance", "must be at least 1e-9 of the coordinates' scale (" + text + ")");
  return false;
}

double coordinate_scale(const path::Path& p) {
  double s = 0.0;
  for (const core::Curve& segment : p.segments) s = std::max(s, core::scale(segment));
  return s;
}

}  // namespace bezier::api
