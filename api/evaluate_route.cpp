#include "api/read_json.hpp"
#include "api/routes.hpp"
#include "api/write_json.hpp"
#include "core/curve/derivative.hpp"
#include "core/curve/evaluate.hpp"
#include "core/measure/frame.hpp"
#include "core/curve/subdivide.hpp"

namespace bezier::api {

namespace {

struct EvaluateRequest {
  std::vector<double> ts;
  int derivatives = 0;
  bool frame = false;
  std::optional<double> split;
};

// {"degree", "results": [{"curvature"?, "derivatives"?, "normal"?, "point", "t", "tangent"?}],
//  "split"?: {"left", "right", "t"}}, members in key order (the text a document of the answer
// would dump to). The frame's three members are null where B'(t) = 0 (and the normal alone
// in 3-D where B' x B'' = 0: the principal normal is undefined there).
template <class P>
Reply evaluate_answer(const core::BasicCurve<P>& curve, const EvaluateRequest& request) {
  JsonWriter w;
  w.begin_object();
  w.key("degree").value(curve.degree());
  w.key("results").begin_array();
  for (const double t : request.ts) {
    w.begin_object();
    std::optional<core::Frame<P>> frame;
    if (request.frame) {
      frame = core::frame(curve, t);
      frame ? w.key("curvature").value(frame->curvature) : w.key("curvature").null();
    }
    if (request.derivatives > 0) {
      // derivatives_at keeps the hodographs unrounded: within one rounding of the exact
      // value, where evaluating rounded hodograph points is not.
      w.key("derivatives").begin_array();
      for (const auto& d : core::derivatives_at(curve, t, request.derivatives)) write_point(w, d);
      w.end_array();
    }
    if (request.frame) {
      w.key("normal");
      frame && frame->normal ? write_point(w, *frame->normal) : w.null();
    }
    write_point(w.key("point"), core::evaluate(curve, t));
    w.key("t").value(t);
    if (request.frame) {
      w.key("tangent");
      frame ? write_point(w, frame->tangent) : w.null();
    }
    w.end_object();
  }
  w.end_array();
  if (request.split) {
    const auto halves = core::subdivide(curve, *request.split);
    w.key("split").begin_object();
    write_points(w.key("left"), halves.left.points());
    write_points(w.key("right"), halves.right.points());
    w.key("t").value(*request.split);
    w.end_object();
  }
  w.end_object();
  return json_reply(std::move(w));
}

}  // namespace

Reply evaluate_route(const nlohmann::json& request, const Limits& limits) {
  RequestReader reader(limits);
  reader.reject_unknown_fields(request, {"points", "t", "samples", "derivatives", "frame", "split"}, "");
  const auto curve = reader.request_curve(request);
  EvaluateRequest parsed;
  parsed.ts = reader.parameters(request, /*required=*/true);
  if (const auto* d = RequestReader::optional(request, "derivatives")) {
    if (const auto k = reader.integer(*d, "/derivatives", 0, limits.max_degree, RequestReader::Bound::limit)) {
      parsed.derivatives = *k;
    }
  }
  // Each derivative is another point per t: the answer is bounded by points, not by t
  // values, so 10000 t with 20 derivatives (9.5 MB, 0.24 s) is not one request.
  const std::size_t answer_points = parsed.ts.size() * static_cast<std::size_t>(parsed.derivatives + 1);
  if (answer_points > static_cast<std::size_t>(limits.max_t_values)) {
    reader.fail_limit("/derivatives", "t values x (derivatives + 1) = " + std::to_string(answer_points) +
                                          " points is above the limit of " +
                                          std::to_string(limits.max_t_values));
  }
  if (const auto* f = RequestReader::optional(request, "frame")) {
    if (f->is_boolean()) {
      parsed.frame = f->get<bool>();
    } else {
      reader.fail("/frame", "expected a boolean");
    }
  }
  if (const auto* s = RequestReader::optional(request, "split")) {
    parsed.split = reader.number(*s, "/split");
  }
  if (!reader.ok()) return reader.refusal();
  return std::visit([&](const auto& c) { return evaluate_answer(c, parsed); }, *curve);
}

}  // namespace bezier::api
