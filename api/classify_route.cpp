#include <string>

#include "api/read_json.hpp"
#include "api/routes.hpp"
#include "api/write_json.hpp"
#include "core/cubic/classify.hpp"

namespace bezier::api {

namespace {

// The answer (api/openapi.yaml), plus the Loop–Blinn class of the unbounded curve:
// {"type", "canonical_point": [x, y] | null, "inflections": [t...], "cusp": t | null,
//  "self_intersection": {"t": [t1, t2], "point": [x, y]} | null, "loop_blinn"},
// written with members in key order (the text a document of the answer would dump to).
Reply classification_answer(const core::CubicClassification& c) {
  JsonWriter w;
  w.begin_object();
  w.key("canonical_point");
  if (c.canonical_point) {
    write_point(w, *c.canonical_point);
  } else {
    w.null();
  }
  w.key("cusp");
  if (c.cusp) {
    w.value(*c.cusp);
  } else {
    w.null();
  }
  w.key("inflections").begin_array();
  for (const double t : c.inflections.values()) w.value(t);
  w.end_array();
  w.key("loop_blinn").value(core::to_string(c.loop_blinn));
  w.key("self_intersection");
  if (c.self_intersection) {
    w.begin_object();
    write_point(w.key("point"), c.self_intersection->point);
    w.key("t").pair(c.self_intersection->t1, c.self_intersection->t2);
    w.end_object();
  } else {
    w.null();
  }
  w.key("type").value(core::to_string(c.type));
  w.end_object();
  return json_reply(std::move(w));
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
  if (!reader.ok()) return reader.refusal();
  return classification_answer(core::classify(*curve));
}

}  // namespace bezier::api
