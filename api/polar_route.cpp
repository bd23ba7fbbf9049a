#include <limits>

#include "api/read_json.hpp"
#include "api/routes.hpp"
#include "api/write_json.hpp"
#include "core/evaluate.hpp"
#include "core/polar.hpp"

namespace bezier::api {

namespace {

constexpr double kAnyFinite = std::numeric_limits<double>::max();

struct PolarRequest {
  std::vector<double> us;  ///< the polar's fixed arguments u_1..u_k
  bool first_polar = false;  ///< t0 was a number, not an array
  std::vector<double> ts;  ///< where to evaluate the polar curve
};

template <class P>
nlohmann::json polar_answer(const core::BasicCurve<P>& curve, const PolarRequest& request) {
  const core::BasicCurve<P> polar_curve = core::polar(curve, request.us);
  nlohmann::json results = nlohmann::json::array();
  for (const double t : request.ts) {
    results.push_back({{"t", t}, {"point", point_json(core::evaluate(polar_curve, t))}});
  }
  nlohmann::json answer = {{"degree", polar_curve.degree()},
                           {"control_points", points_json(polar_curve)},
                           {"results", std::move(results)}};
  if (request.first_polar) answer["curve_point"] = point_json(core::evaluate(curve, request.us[0]));
  // With all n arguments fixed the polar is a single point: the blossom value.
  if (polar_curve.degree() == 0) answer["blossom"] = point_json(polar_curve.front());
  return answer;
}

}  // namespace

Reply polar_route(const nlohmann::json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request, {"points", "t0", "t", "samples"}, "");
  std::optional<std::variant<core::Curve, core::Curve3>> curve;
  if (const auto* points = reader.required(request, "points", "")) {
    curve = reader.curve(*points, "/points");
  }
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
  if (!reader.ok()) return validation_reply(reader.take_errors());
  return json_reply(std::visit([&](const auto& c) { return polar_answer(c, parsed); }, *curve));
}

}  // namespace bezier::api
