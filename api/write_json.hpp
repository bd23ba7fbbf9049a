#pragma once

#include <span>

#include "api/json_writer.hpp"
#include "core/point.hpp"

namespace bezier::api {

/// The answers' geometric pieces, written to text (JsonWriter).

/// [x, y]
inline JsonWriter& write_point(JsonWriter& w, core::Point2 p) { return w.pair(p.x, p.y); }
/// [x, y, z]
inline JsonWriter& write_point(JsonWriter& w, core::Point3 p) {
  return w.begin_array().value(p.x).value(p.y).value(p.z).end_array();
}
/// [[x, y], ...] or [[x, y, z], ...]
template <class P>
JsonWriter& write_points(JsonWriter& w, std::span<const P> points) {
  w.begin_array();
  for (const P& p : points) write_point(w, p);
  return w.end_array();
}

}  // namespace bezier::api
