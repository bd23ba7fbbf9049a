#pragma once

#include <span>
#include <vector>

#include <nlohmann/json.hpp>

#include "api/json_writer.hpp"
#include "core/curve.hpp"
#include "core/point.hpp"

namespace bezier::api {

/// [x, y]
[[nodiscard]] inline nlohmann::json point_json(core::Point2 p) { return nlohmann::json::array({p.x, p.y}); }
/// [x, y, z]
[[nodiscard]] inline nlohmann::json point_json(core::Point3 p) {
  return nlohmann::json::array({p.x, p.y, p.z});
}

/// [[x, y], ...] or [[x, y, z], ...]
template <class P>
[[nodiscard]] nlohmann::json points_json(std::span<const P> points) {
  nlohmann::json out = nlohmann::json::array();
  for (const P& p : points) out.push_back(point_json(p));
  return out;
}

template <class P>
[[nodiscard]] nlohmann::json points_json(const core::BasicCurve<P>& curve) {
  return points_json(curve.points());
}

/// [lo, hi]
[[nodiscard]] inline nlohmann::json pair_json(double lo, double hi) {
  return nlohmann::json::array({lo, hi});
}

/// The same pieces written to text (JsonWriter).
inline JsonWriter& write_point(JsonWriter& w, core::Point2 p) { return w.pair(p.x, p.y); }
inline JsonWriter& write_point(JsonWriter& w, core::Point3 p) {
  return w.begin_array().value(p.x).value(p.y).value(p.z).end_array();
}
template <class P>
JsonWriter& write_points(JsonWriter& w, std::span<const P> points) {
  w.begin_array();
  for (const P& p : points) write_point(w, p);
  return w.end_array();
}

}  // namespace bezier::api
