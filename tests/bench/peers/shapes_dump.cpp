// The inputs and our answers that tests/bench/peers/peers_bench.mjs checks the JavaScript
// peers against, as JSON on stdout. Not a benchmark.
//
//   bezier_peer_shapes                  the shapes: boolean pairs (region_bench_shapes.hpp)
//                                       with our union and intersection areas; the hard cases
//                                       with our areas and the sample points of
//                                       region_case_truth.hpp; the flatten and offset inputs
//   bezier_peer_shapes flatten TOL      our polylines (outline/flatten.hpp) of the flatten
//                                       inputs at tolerance TOL
//   bezier_peer_shapes offset D TOL     our offset cubics (outline/offset.hpp) at distance D
//                                       (left of travel, y up) of every segment of the glyph
//                                       outlines, within TOL
//   bezier_peer_shapes stroke W TOL JOIN CAP
//                                       our stroke outlines (outline/stroke.hpp) of the glyph
//                                       outlines (closed) and of the random cubics (each an
//                                       open path), width W, within TOL: per shape its
//                                       contours, each a list of segments as flat control
//                                       point lists (2 points a line, 4 a cubic)
//   bezier_peer_shapes stroke-time SET W TOL JOIN CAP MS
//                                       CPU time of outline::stroke per shape of SET (glyphs
//                                       or random_cubics): passes over the set, paths built
//                                       beforehand, until MS milliseconds of this process's
//                                       CPU time (CLOCK_PROCESS_CPUTIME_ID); prints
//                                       {"us_per_shape":..,"passes":..}. Not a certified
//                                       figure: the machine's load shows in it.
//
// Flatten and offset inputs: the A outlines of the 8 pairs of 50 cubics (glyph outlines), and
// 256 random cubics: mulberry32 seeded with 1 after the 320000 draws of the cubic pairs,
// x and y of each control point in turn (BENCHMARKS.md's benchmark input).

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "core/base/curve.hpp"
#include "core/outline/flatten.hpp"
#include "core/outline/offset.hpp"
#include "core/outline/stroke.hpp"
#include "core/path/svg_path_data.hpp"
#include "core/region/boolean.hpp"
#include "core/region/region.hpp"
#include "tests/bench/region_bench_shapes.hpp"
#include "tests/bench/region_case_truth.hpp"
#include "tests/support/mulberry32.hpp"

namespace {

using bezier::bench::CubicOutline;
using bezier::core::Curve;
using bezier::core::Point2;
namespace region = bezier::region;

constexpr std::int64_t kWork = 1000000000;

std::vector<Curve> cubics_of(const CubicOutline& points) {
  std::vector<Curve> curves;
  for (std::size_t k = 0; k + 3 < points.size(); k += 3) {
    curves.emplace_back(std::vector<Point2>{points[k], points[k + 1], points[k + 2], points[k + 3]});
  }
  return curves;
}

region::Region region_of(const CubicOutline& points) {
  return region::region_from_curves(cubics_of(points), region::FillRule::nonzero);
}

void print_points(const std::vector<Point2>& points) {
  std::printf("[");
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::printf("%s%.17g,%.17g", i ? "," : "", points[i].x, points[i].y);
  }
  std::printf("]");
}

void print_string(const std::string& s) {
  std::printf("\"");
  for (const char c : s) {
    if (c == '"' || c == '\\') std::printf("\\");
    std::printf("%c", c);
  }
  std::printf("\"");
}

std::vector<CubicOutline> glyph_outlines() {
  std::vector<CubicOutline> glyphs;
  for (const auto& pair : bezier::bench::outline_pairs(50, bezier::bench::kPairsPerCount)) glyphs.push_back(pair.a);
  return glyphs;
}

std::vector<std::vector<Point2>> random_cubics() {
  bezier::test::Mulberry32 rng(1);
  for (int i = 0; i < 320000; ++i) rng.next();
  std::vector<std::vector<Point2>> cubics;
  for (int i = 0; i < 256; ++i) {
    std::vector<Point2> c;
    for (int k = 0; k < 4; ++k) {
      const double x = rng.next();
      c.push_back({x, rng.next()});
    }
    cubics.push_back(c);
  }
  return cubics;
}

void dump_shapes() {
  std::printf("{\"pairs\":[\n");
  bool first = true;
  for (const int n : bezier::bench::kPairCubicCounts) {
    for (const auto& pair : bezier::bench::outline_pairs(n, bezier::bench::kPairsPerCount)) {
      const region::Region a = region_of(pair.a), b = region_of(pair.b);
      const auto u = region::boolean_operation(region::BooleanOperation::union_, a, b, kWork);
      const auto i = region::boolean_operation(region::BooleanOperation::intersection, a, b, kWork);
      std::printf("%s{\"cubics\":%d,\"union_area\":%.17g,\"intersection_area\":%.17g,\"ok\":%s,\"a\":", first ? "" : ",\n",
                  n, u.area, i.area,
                  u.status == region::BooleanStatus::ok && i.status == region::BooleanStatus::ok ? "true" : "false");
      print_points(pair.a);
      std::printf(",\"b\":");
      print_points(pair.b);
      std::printf("}");
      first = false;
    }
  }
  std::printf("],\n\"cases\":[\n");
  first = true;
  for (const bezier::bench::HardCase& c : bezier::bench::hard_cases()) {
    const region::FillRule rule = c.evenodd ? region::FillRule::evenodd : region::FillRule::nonzero;
    const auto a = region::region_from_path(bezier::path::parse_svg_path_data(c.a, 100000).path, rule);
    const auto b = region::region_from_path(bezier::path::parse_svg_path_data(c.b, 100000).path, rule);
    const bezier::bench::CaseTruth truth = bezier::bench::case_truth(a, b);
    std::printf("%s{\"name\":", first ? "" : ",\n");
    first = false;
    print_string(c.name);
    std::printf(",\"a\":");
    print_string(c.a);
    std::printf(",\"b\":");
    print_string(c.b);
    std::printf(",\"evenodd\":%s,\"area_tolerance\":%.17g,\"ops\":[", c.evenodd ? "true" : "false",
                bezier::bench::kAreaTolerance * truth.box.area());
    for (std::size_t k = 0; k < truth.areas.size(); ++k) {
      std::printf("%s{\"op\":\"%s\",\"area\":%.17g,\"ok\":%s}", k ? "," : "",
                  bezier::bench::operation_name(bezier::bench::kCaseOperations[k]), truth.areas[k],
                  truth.statuses[k] == region::BooleanStatus::ok ? "true" : "false");
    }
    std::printf("],\"points\":[");
    for (std::size_t k = 0; k < truth.points.size(); ++k) {
      const auto& s = truth.points[k];
      std::printf("%s[%.17g,%.17g,%d,%d]", k ? "," : "", s.p.x, s.p.y, s.in_a ? 1 : 0, s.in_b ? 1 : 0);
    }
    std::printf("]}");
  }
  std::printf("],\n\"glyphs\":[");
  first = true;
  for (const CubicOutline& g : glyph_outlines()) {
    std::printf("%s", first ? "" : ",");
    first = false;
    print_points(g);
  }
  std::printf("],\n\"random_cubics\":[");
  first = true;
  for (const auto& c : random_cubics()) {
    std::printf("%s", first ? "" : ",");
    first = false;
    print_points(c);
  }
  std::printf("]}\n");
}

void print_flattening(const bezier::outline::Flattening& f) {
  if (f.status != bezier::outline::FlattenStatus::ok || f.polylines.size() != 1) {
    std::fprintf(stderr, "flatten failed\n");
    std::exit(1);
  }
  std::vector<Point2> points;
  for (const auto& v : f.polylines[0]) points.push_back(v.point);
  print_points(points);
}

void dump_flatten(double tolerance) {
  bezier::outline::FlattenOptions options;
  options.tolerance = tolerance;
  options.max_vertices = 100000000;
  bezier::core::WorkBudget budget;
  std::printf("{\"glyphs\":[");
  bool first = true;
  for (const CubicOutline& g : glyph_outlines()) {
    std::printf("%s", first ? "" : ",");
    first = false;
    print_flattening(bezier::outline::flatten(region_of(g).path, options, budget));
  }
  std::printf("],\n\"random_cubics\":[");
  first = true;
  for (const auto& c : random_cubics()) {
    std::printf("%s", first ? "" : ",");
    first = false;
    print_flattening(bezier::outline::flatten(Curve(c), options, budget));
  }
  std::printf("]}\n");
}

void dump_offset(double d, double tolerance) {
  // Per glyph, the offset cubics of every segment in order, as flat control point lists.
  std::printf("{\"glyphs\":[");
  bool first = true;
  for (const CubicOutline& g : glyph_outlines()) {
    std::printf("%s[", first ? "" : ",");
    first = false;
    bool first_cubic = true;
    for (const Curve& c : cubics_of(g)) {
      bezier::core::WorkBudget budget;
      const auto o = bezier::outline::offset_curve(c, d, tolerance, budget);
      if (budget.exhausted()) {
        std::fprintf(stderr, "offset failed\n");
        std::exit(1);
      }
      for (const auto& cubic : o.cubics) {
        std::printf("%s", first_cubic ? "" : ",");
        first_cubic = false;
        print_points({cubic.points.begin(), cubic.points.end()});
      }
    }
    std::printf("]");
  }
  std::printf("]}\n");
}

/// The stroke inputs: the glyph outlines as closed paths, the random cubics as open paths.
std::vector<bezier::path::Path> stroke_inputs(const std::string& set) {
  std::vector<bezier::path::Path> paths;
  if (set == "glyphs") {
    for (const CubicOutline& g : glyph_outlines()) {
      bezier::path::Path p;
      p.segments = cubics_of(g);
      p.subpaths.push_back({0, p.segments.size(), true});
      paths.push_back(std::move(p));
    }
  } else if (set == "random_cubics") {
    for (const auto& c : random_cubics()) {
      bezier::path::Path p;
      p.segments.emplace_back(c);
      p.subpaths.push_back({0, 1, false});
      paths.push_back(std::move(p));
    }
  } else {
    std::fprintf(stderr, "unknown set %s\n", set.c_str());
    std::exit(2);
  }
  return paths;
}

bezier::outline::StrokeStyle stroke_style(double width, const std::string& join, const std::string& cap) {
  bezier::outline::StrokeStyle style;
  style.width = width;
  style.join = join == "round" ? bezier::outline::LineJoin::round
               : join == "bevel" ? bezier::outline::LineJoin::bevel
                                 : bezier::outline::LineJoin::miter;
  style.cap = cap == "round" ? bezier::outline::LineCap::round
              : cap == "square" ? bezier::outline::LineCap::square
                                : bezier::outline::LineCap::butt;
  return style;
}

bezier::outline::StrokeOutline stroke_of(const bezier::path::Path& path,
                                         const bezier::outline::StrokeStyle& style, double tolerance) {
  bezier::core::WorkBudget budget;
  auto o = bezier::outline::stroke(path, style, tolerance, budget, 100000000);
  if (o.status != bezier::outline::StrokeStatus::ok) {
    std::fprintf(stderr, "stroke failed\n");
    std::exit(1);
  }
  return o;
}

void dump_stroke(double width, double tolerance, const std::string& join, const std::string& cap) {
  const auto style = stroke_style(width, join, cap);
  std::printf("{");
  bool first_set = true;
  for (const char* set : {"glyphs", "random_cubics"}) {
    std::printf("%s\"%s\":[", first_set ? "" : ",\n", set);
    first_set = false;
    bool first = true;
    for (const auto& path : stroke_inputs(set)) {
      std::printf("%s[", first ? "" : ",");
      first = false;
      bool first_contour = true;
      for (const auto& contour : stroke_of(path, style, tolerance).contours) {
        std::printf("%s[", first_contour ? "" : ",");
        first_contour = false;
        for (std::size_t k = 0; k < contour.size(); ++k) {
          std::printf("%s", k ? "," : "");
          print_points({contour[k].points().begin(), contour[k].points().end()});
        }
        std::printf("]");
      }
      std::printf("]");
    }
    std::printf("]");
  }
  std::printf("}\n");
}

double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

void time_stroke(const std::string& set, double width, double tolerance, const std::string& join,
                 const std::string& cap, double min_ms) {
  const auto style = stroke_style(width, join, cap);
  const auto paths = stroke_inputs(set);
  std::size_t segments = 0;
  for (const auto& path : paths) segments += stroke_of(path, style, tolerance).segment_count;  // warm-up
  long passes = 0;
  const double start = cpu_ms();
  double elapsed = 0.0;
  do {
    for (const auto& path : paths) {
      const auto o = stroke_of(path, style, tolerance);
      if (o.segment_count == 0) std::exit(1);
    }
    ++passes;
    elapsed = cpu_ms() - start;
  } while (elapsed < min_ms);
  std::printf("{\"us_per_shape\":%.6g,\"passes\":%ld,\"segments\":%zu}\n",
              elapsed * 1e3 / (static_cast<double>(passes) * static_cast<double>(paths.size())), passes,
              segments);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 1) {
    dump_shapes();
  } else if (argc == 3 && std::strcmp(argv[1], "flatten") == 0) {
    dump_flatten(std::strtod(argv[2], nullptr));
  } else if (argc == 4 && std::strcmp(argv[1], "offset") == 0) {
    dump_offset(std::strtod(argv[2], nullptr), std::strtod(argv[3], nullptr));
  } else if (argc == 6 && std::strcmp(argv[1], "stroke") == 0) {
    dump_stroke(std::strtod(argv[2], nullptr), std::strtod(argv[3], nullptr), argv[4], argv[5]);
  } else if (argc == 8 && std::strcmp(argv[1], "stroke-time") == 0) {
    time_stroke(argv[2], std::strtod(argv[3], nullptr), std::strtod(argv[4], nullptr), argv[5], argv[6],
                std::strtod(argv[7], nullptr));
  } else {
    std::fprintf(stderr, "usage: %s [flatten TOL | offset D TOL | stroke W TOL JOIN CAP | stroke-time SET W TOL JOIN CAP MS]\n", argv[0]);
    return 2;
  }
  return 0;
}
