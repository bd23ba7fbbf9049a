#pragma once
// The inputs of the region benchmarks, shared by the lib2geom comparison
// (tests/bench/lib2geom/regions_bench.cpp) and the JavaScript peers (tests/bench/peers/, which
// read them from tests/bench/peers/shapes_dump.cpp's JSON), so that every library runs on the
// same doubles.
//
// Glyph-like outline of n cubics: a star-shaped closed curve r(θ) = R (1 + a1 sin(k1 θ + φ1)
// + a2 cos(k2 θ + φ2)) about a centre, through n points at equal steps of θ, each span a cubic
// with Catmull-Rom tangents (C1 at the joints, so no corners), counter-clockwise; the last
// point is the first, bit for bit. Its parameters are mulberry32 draws (BENCHMARKS.md), in
// the order k1, k2, a1, a2, φ1, φ2:
//   k1 = 2 + floor(5 u), k2 = 5 + floor(6 u), a1 = 0.1 + 0.15 u, a2 = 0.03 + 0.07 u,
//   φ = 2π u.
// Pairs: for n cubics, mulberry32 seeded with n; each pair draws a direction ψ = 2π u, then
// outline A about (0, 0) and outline B about 0.6 (cos ψ, sin ψ), both R = 1: they overlap
// over much of their area and their boundaries cross a few to a few dozen times.
//
// The 64-cubic outline of /contains is tests/bench/contains_bench.cpp's (the first of
// path_bench.cpp's), with its 32 x 32 grid of targets and its targets on the outline.
//
// The hard cases are the geometry of tests/core/region/boolean_test.cpp, as SVG path data
// with their fill rules; simplify cases are the operand against an empty path.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstddef>
#include <string>
#include <vector>

#include "core/base/point.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::bench {

/// A closed outline as the control points of its cubics: 3 n + 1 points, cubic k is
/// points[3k .. 3k + 3], points.back() == points.front().
using CubicOutline = std::vector<core::Point2>;

/// The Catmull-Rom closed cubic spline through `on` (the points in order, not repeated).
inline CubicOutline catmull_rom_closed(const std::vector<core::Point2>& on) {
  const int n = static_cast<int>(on.size());
  const auto at = [&](int k) { return on[static_cast<std::size_t>(((k % n) + n) % n)]; };
  CubicOutline points;
  for (int k = 0; k < n; ++k) {
    const core::Point2 p0 = at(k), p1 = at(k + 1);
    points.push_back(p0);
    points.push_back(p0 + (at(k + 1) - at(k - 1)) / 6.0);
    points.push_back(p1 - (at(k + 2) - at(k)) / 6.0);
  }
  points.push_back(on.front());
  return points;
}

inline CubicOutline glyph_outline(test::Mulberry32& rng, int n, core::Point2 centre, double radius) {
  const double k1 = 2 + std::floor(5 * rng.next());
  const double k2 = 5 + std::floor(6 * rng.next());
  const double a1 = 0.1 + 0.15 * rng.next();
  const double a2 = 0.03 + 0.07 * rng.next();
  const double phi1 = 2 * M_PI * rng.next();
  const double phi2 = 2 * M_PI * rng.next();
  std::vector<core::Point2> on;
  for (int k = 0; k < n; ++k) {
    const double theta = 2 * M_PI * k / n;
    const double r = radius * (1 + a1 * std::sin(k1 * theta + phi1) + a2 * std::cos(k2 * theta + phi2));
    on.push_back({centre.x + r * std::cos(theta), centre.y + r * std::sin(theta)});
  }
  return catmull_rom_closed(on);
}

struct OutlinePair {
  CubicOutline a, b;
};

inline std::vector<OutlinePair> outline_pairs(int cubics, int count) {
  test::Mulberry32 rng(static_cast<std::uint32_t>(cubics));
  std::vector<OutlinePair> pairs;
  for (int i = 0; i < count; ++i) {
    const double psi = 2 * M_PI * rng.next();
    OutlinePair pair;
    pair.a = glyph_outline(rng, cubics, {0, 0}, 1);
    pair.b = glyph_outline(rng, cubics, {0.6 * std::cos(psi), 0.6 * std::sin(psi)}, 1);
    pairs.push_back(std::move(pair));
  }
  return pairs;
}

/// The cubic counts and pairs per count of the boolean benchmarks.
inline constexpr int kPairCubicCounts[] = {20, 50, 100};
inline constexpr int kPairsPerCount = 8;

/// contains_bench.cpp's outline: r(θ) = 1 + 0.15 sin(5 θ) + 0.05 cos(11 θ), 64 points.
inline CubicOutline contains_outline() {
  std::vector<core::Point2> on;
  for (int k = 0; k < 64; ++k) {
    const double theta = 2 * M_PI * k / 64;
    const double r = 1 + 0.15 * std::sin(5 * theta) + 0.05 * std::cos(11 * theta);
    on.push_back({r * std::cos(theta), r * std::sin(theta)});
  }
  return catmull_rom_closed(on);
}

/// contains_bench.cpp's spread targets: a 32 x 32 grid over [-1.3, 1.3]^2, moved off its
/// symmetry.
inline std::vector<core::Point2> contains_spread_targets() {
  std::vector<core::Point2> targets;
  for (int i = 0; i < 32; ++i) {
    for (int j = 0; j < 32; ++j) {
      targets.push_back({-1.3 + 2.6 * (i + 0.3183) / 32, -1.3 + 2.6 * (j + 0.5772) / 32});
    }
  }
  return targets;
}

/// SVG path data of a circle of four cubic arcs (tests/core/region/boolean_test.cpp's).
inline std::string circle_data(double cx, double cy, double r) {
  const double k = 0.5522847498307936 * r;
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer,
                "M%.17g %.17g C%.17g %.17g %.17g %.17g %.17g %.17g C%.17g %.17g %.17g %.17g "
                "%.17g %.17g C%.17g %.17g %.17g %.17g %.17g %.17g C%.17g %.17g %.17g %.17g %.17g "
                "%.17g Z",
                cx + r, cy, cx + r, cy + k, cx + k, cy + r, cx, cy + r, cx - k, cy + r, cx - r,
                cy + k, cx - r, cy, cx - r, cy - k, cx - k, cy - r, cx, cy - r, cx + k, cy - r,
                cx + r, cy - k, cx + r, cy);
  return buffer;
}

struct HardCase {
  std::string name;
  std::string a, b;  ///< SVG path data; b empty: the simplify of a
  bool evenodd = false;  ///< both operands' fill rule (nonzero otherwise)
};

/// The hard cases of tests/core/region/boolean_test.cpp (the degree-5 operand is left out:
/// no peer takes a quintic; the 10000 single-point chains of ZeroLengthSegmentsAddNothing
/// are cut to 10).
inline std::vector<HardCase> hard_cases() {
  std::vector<HardCase> cases = {
      {"overlapping squares", "M0 0 H2 V2 H0 Z", "M1 1 H3 V3 H1 Z"},
      {"shared edge, opposite directions", "M0 0 H1 V1 H0 Z", "M1 0 H2 V1 H1 Z"},
      {"shared edge, same direction", "M0 0 H2 V1 H0 Z", "M1 0 H2 V2 H1 Z"},
      {"corner square sharing two edges", "M0 0 H2 V2 H0 Z", "M0 0 H1 V1 H0 Z"},
      {"vertex touching an edge", "M0 0 H2 V2 H0 Z", "M1 2 L2 4 L0 4 Z"},
      {"four edges through a corner", "M0 0 H2 V2 H0 Z", "M0 0 L3 1 L1 3 Z"},
      {"checkerboard: eight edges through one point", "M0 0 H1 V1 H0 Z M1 1 H2 V2 H1 Z",
       "M1 0 H2 V1 H1 Z M0 1 H1 V2 H0 Z"},
      {"nested contours (nonzero) against a square in the middle", "M0 0 H4 V4 H0 Z M1 1 H3 V3 H1 Z",
       "M1.5 1.5 H2.5 V2.5 H1.5 Z"},
      {"nested contours (evenodd) against a square in the middle", "M0 0 H4 V4 H0 Z M1 1 H3 V3 H1 Z",
       "M1.5 1.5 H2.5 V2.5 H1.5 Z", true},
      {"nested contours and a triangle through both", "M0 0 H4 V4 H0 Z M1 1 H3 V3 H1 Z", "M0 2 L4 1 L4 3 Z"},
      {"disjoint operands", "M0 0 H1 V1 H0 Z", "M2 0 H3 V1 H2 Z"},
      {"equal operands", "M0 0 H2 Q3 1 2 2 H0 Z", "M0 0 H2 Q3 1 2 2 H0 Z"},
      {"operand and its reversed copy", "M0 0 H2 Q3 1 2 2 H0 Z", "M0 0 V2 H2 Q3 1 2 0 Z"},
      {"one inside the other", "M0 0 H4 V4 H0 Z", "M1 1 H2 V2 H1 Z"},
      {"empty operand", "M0 0 H2 V2 H0 Z", ""},
      {"figure eight (simplify)", "M0 0 L2 2 L2 0 L0 2 Z", ""},
      {"figure eight against a bar", "M0 0 L2 2 L2 0 L0 2 Z", "M0.5 0 H1.5 V2 H0.5 Z"},
      {"the same square twice in one path (simplify)", "M0 0 H2 V2 H0 Z M0 0 H2 V2 H0 Z", ""},
      {"a square and its half in one path (simplify, evenodd)", "M0 0 H2 V2 H0 Z M0 0 H1 V2 H0 Z", "", true},
      {"segments retracing themselves (simplify)",
       "M0 0 H2 V2 H0 Z M0.5 0.5 C1.5 1 1.5 1 0.5 0.5 M3 3 C4 4 4 4 3 3", ""},
      {"zero-length segment and single-point chains", "M0 0 H2 L2 0 V2 H0 Z",
       "M1 1 H3 V3 H1 Z M9 9 Z M9 9 Z M9 9 Z M9 9 Z M9 9 Z M9 9 Z M9 9 Z M9 9 Z M9 9 Z M9 9 Z"},
      {"circles tangent at a joint", circle_data(0, 0, 1), circle_data(2, 0, 1)},
      {"circles tangent inside (at a joint)", circle_data(0, 0, 2), circle_data(1, 0, 1)},
  };
  // Crossings closer than the tolerance: the triangle's vertex 2^-50 inside the square's edge.
  {
    char buffer[256];
    const double d = 0x1p-50;
    std::snprintf(buffer, sizeof buffer, "M%.17g 1 L4 0 L4 2 Z", 2 - d);
    cases.push_back({"triangle vertex 2^-50 inside a square's edge", "M0 0 H2 V2 H0 Z", buffer});
  }
  // Mirrored arcs touching at their middles, inside a segment of each.
  {
    const double s = std::sqrt(0.5), k = 0.5522847498307936;
    const core::Point2 p[4] = {{s, -s}, {s + k * s, -s + k * s}, {s + k * s, s - k * s}, {s, s}};
    const double m = 0.125 * (p[0].x + 3 * p[1].x + 3 * p[2].x + p[3].x);  // B(1/2).x
    char buffer[1024];
    const auto shape = [&](double sign, double offset) {
      std::snprintf(buffer, sizeof buffer,
                    "M%.17g %.17g C%.17g %.17g %.17g %.17g %.17g %.17g L%.17g %.17g L%.17g %.17g Z",
                    offset + sign * p[0].x, p[0].y, offset + sign * p[1].x, p[1].y,
                    offset + sign * p[2].x, p[2].y, offset + sign * p[3].x, p[3].y,
                    offset + sign * -1.0, s, offset + sign * -1.0, -s);
      return std::string(buffer);
    };
    cases.push_back({"mirrored arcs touching at their middles", shape(1.0, 0.0), shape(-1.0, 2 * m)});
  }
  // Circles touching from outside near the direction 0.3 rad, 1e-12 apart and overlapping by
  // 1e-12 (the centre distance is 2 r(0.3) + gap with r(0.3) ~ the circle's radius there).
  for (const double gap : {1e-12, -1e-12}) {
    // r at 0.3 rad of the four-arc circle, by bisection on the first arc's angle.
    const double k = 0.5522847498307936;
    const auto arc = [&](double t) {
      const double u = 1 - t;
      return core::Point2{u * u * u + 3 * u * u * t + 3 * u * t * t * k,
                          3 * u * u * t * k + 3 * u * t * t + t * t * t};
    };
    double lo = 0, hi = 1;
    for (int i = 0; i < 100; ++i) {
      const double mid = (lo + hi) / 2;
      const core::Point2 q = arc(mid);
      (std::atan2(q.y, q.x) < 0.3 ? lo : hi) = mid;
    }
    const core::Point2 on = arc(lo);
    const double d = 2 * std::hypot(on.x, on.y) + gap;
    cases.push_back({gap > 0 ? "circles 1e-12 apart" : "circles overlapping by 1e-12", circle_data(0, 0, 1),
                     circle_data(d * std::cos(0.3), d * std::sin(0.3), 1)});
  }
  return cases;
}

}  // namespace bezier::bench
