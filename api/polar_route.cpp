#include <limits>

#include "api/read_json.hpp"
#include "api/routes.hpp"
#include "api/write_json.hpp"
#include "core/curve/evaluate.hpp"
#include "core/curve/polar.hpp"

namespace bezier::api {

namespace {

constexpr double kAnyFinite = std::numeric_limits<double>::max();

struct PolarRequest {
  std::vector<double> us;  ///< the polar's fixed arguments u_1..u_k
  bool first_polar = false;  ///< t0 was a number, not an array
  std::vector<double> ts;  ///< where to evaluate the polar curve
};

// {"blossom"?, "control_points", "curve_point"?, "degree", "results": [{"point", "t"}]},
// members in key order (the text a document of the answer would dump to).
template <class P>
Reply polar_answer(const core::BasicCurve<P>& curve, const PolarRequest& request) {
  const core::BasicCurve<P> polar_curve = core::polar(curve, request.us);
  JsonWriter w;
  w.begin_object();
  // With all n arguments fixed the polar is a single point: the blossom value.
  if (polar_curve.degree() == 0) write_point(w.key("blossom"), polar_curve.front());
  write_points(w.key("control_points"), polar_curve.points());
  if (request.first_polar) write_point(w.key("curve_point"), core::evaluate(curve, request.us[0]));
  w.key("degree").value(polar_curve.degree());
  w.key("results").begin_array();
  for (const double t : request.ts) {
    w.begin_object();
    write_point(w.key("point"), core::evaluate(polar_curve, t));
    w.key("t").value(t);
    w.end_object();
  }
  w.end_array();
  w.end_object();
  return json_reply(std::move(w));
}

}  // namespace

Reply polar_route(const nlohmann::json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request, {"points", "t0", "t", "samples"}, "");
  const auto curve = reader.request_curve(request);
  PolarRequest parsed;
  if (const auto* t0 = reader.required(request, "t0", "")) {
    parsed.first_polar = !t0->is_array();
    if (auto us = reader.number_or_numbers(*t0, "/t0", -kAnyFinite, kAnyFinite)) parsed.us = std::move(*us);
  }
  if (curve && !parsed.us.empty()) {
    const int degree = std::visit([](const auto& c) { return c.degree(); }, *curve);
    if (static_cast<int>(parsed.us.size()) > degree) {
      reader.fail("/t0", "a curve of degree " + std::to_string(degree) + " has polars for at most " +
                             std::to_string(degree) + " arguments, got " +
                             std::to_string(parsed.us.size()));
    }
  }
  parsed.ts = reader.parameters(request, /*required=*/false);
  if (!reader.ok()) return reader.refusal();
  return std::visit([&](const auto& c) { return polar_answer(c, parsed); }, *curve);
}

}  // namespace bezier::api
