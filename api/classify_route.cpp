#include <string>

#include "api/read_json.hpp"
#include "api/routes.hpp"
#include "api/write_json.hpp"
#include "core/classify.hpp"

namespace bezier::api {

namespace {

// The answer of DESIGN §3, plus the Loop–Blinn class of the unbounded curve:
// {"type", "canonical_point": [x, y] | null, "inflections": [t...], "cusp": t | null,
//  "self_intersection": {"t": [t1, t2], "point": [x, y]} | null, "loop_blinn"}.
nlohmann::json classification_json(const core::CubicClassification& c) {
  nlohmann::json inflections = nlohmann::json::array();
  for (const double t : c.inflections.values()) inflections.push_back(t);
  nlohmann::json answer = {
      {"type", std::string(core::name(c.type))},
      {"canonical_point", c.canonical_point ? point_json(*c.canonical_point) : nlohmann::json()},
      {"inflections", std::move(inflections)},
      {"cusp", c.cusp ? nlohmann::json(*c.cusp) : nlohmann::json()},
      {"self_intersection", nullptr},
      {"loop_blinn", std::string(core::name(c.loop_blinn))},
  };
  if (c.self_intersection) {
    answer["self_intersection"] = {
        {"t", pair_json(c.self_intersection->t1, c.self_intersection->t2)},
        {"point", point_json(c.self_intersection->point)}};
  }
  return answer;
}

}  // namespace

Reply classify_route(const nlohmann::json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request, {"points"}, "");
  std::optional<core::Curve> curve;
  if (const auto* points = reader.required(request, "points", "")) {
    // Classification is of cubics only: say so before any generic curve message.
    if (points->is_array() && points->size() != 4) {
      reader.fail("/points", "classification needs a cubic: exactly 4 control points [x, y], got " +
                                 std::to_string(points->size()));
    } else {
      curve = reader.curve2(*points, "/points");
    }
  }
  if (!reader.ok()) return validation_reply(reader.take_errors());
  return json_reply(classification_json(core::classify(*curve)));
}

}  // namespace bezier::api
