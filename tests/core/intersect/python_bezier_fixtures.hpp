#pragma once

// Reader for the Python `bezier` library's curve-intersection fixtures
// (tests/fixtures/python-bezier/, from dhermes/bezier, Apache License 2.0; see the README
// there). Numbers are JSON numbers, exact rationals "p/q" (rounded once to the nearest
// double, as the library's own float64 tests read them) or C99 hex floats.

#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/base/curve.hpp"
#include "tests/support/exact.hpp"

namespace bezier::test::python_bezier {

inline std::string fixture_dir() {
  return std::string(BEZIER_SOURCE_DIR) + "/tests/fixtures/python-bezier/";
}

inline nlohmann::json read_json(const std::string& name) {
  std::ifstream in(fixture_dir() + name);
  if (!in) throw std::runtime_error("cannot open fixture " + fixture_dir() + name);
  return nlohmann::json::parse(in);
}

/// A fixture number as the nearest double.
inline double number(const nlohmann::json& v) {
  if (v.is_number()) return v.get<double>();
  const std::string s = v.get<std::string>();
  if (s.find("0x") != std::string::npos) return std::strtod(s.c_str(), nullptr);
  const auto slash = s.find('/');
  if (slash == std::string::npos) return std::strtod(s.c_str(), nullptr);
  const long long p = std::stoll(s.substr(0, slash)), q = std::stoll(s.substr(slash + 1));
  return (Rational(p) / Rational(q)).to_double();
}

/// All curves, by id.
inline std::map<std::string, core::Curve> curves() {
  std::map<std::string, core::Curve> out;
  const nlohmann::json all = read_json("curves.json");  // kept alive: items() refers to it
  for (const auto& [id, value] : all.items()) {
    const auto& cp = value.at("control_points");
    std::vector<core::Point2> pts;
    for (std::size_t i = 0; i < cp[0].size(); ++i)
      pts.push_back({number(cp[0][i]), number(cp[1][i])});
    out.emplace(id, core::Curve(std::move(pts)));
  }
  return out;
}

struct Case {
  int id = 0;
  std::string curve1, curve2, type, note;
  std::vector<double> t, s;          ///< curve1_params, curve2_params (same order)
  std::vector<core::Point2> points;  ///< the intersection points
};

inline std::vector<Case> cases() {
  std::vector<Case> out;
  const nlohmann::json all = read_json("curve_intersections.json");
  for (const auto& c : all) {
    Case k;
    k.id = c.at("id").get<int>();
    k.curve1 = c.at("curve1").get<std::string>();
    k.curve2 = c.at("curve2").get<std::string>();
    k.type = c.at("type").get<std::string>();
    k.note = c.value("note", "");
    for (const auto& v : c.at("curve1_params")) k.t.push_back(number(v));
    for (const auto& v : c.at("curve2_params")) k.s.push_back(number(v));
    const auto& pts = c.at("intersections");
    for (std::size_t i = 0; i < pts[0].size(); ++i)
      k.points.push_back({number(pts[0][i]), number(pts[1][i])});
    out.push_back(std::move(k));
  }
  return out;
}

}  // namespace bezier::test::python_bezier
