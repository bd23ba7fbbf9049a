// The region hard cases (tests/bench/region_bench_shapes.hpp: the geometry of
// tests/core/region/boolean_test.cpp) through lib2geom 1.2.2's PathIntersectionGraph, checked
// against tests/bench/region_case_truth.hpp: for each case and operation (union, intersection,
// a minus b, xor), lib2geom's result area against our certified result's, and the sample
// points (farther than 1e-3 of the operands' diagonal from both boundaries) where membership
// in lib2geom's result differs from op(in a, in b) by our certified winding numbers of the
// operands. lib2geom's result is read under the even-odd rule (PathVector::winding odd, area
// by region_geom.hpp's geom_filled_area): it does not make its contours' orientation
// consistent, so its result means what it should only as a set of non-crossing boundaries. Not a benchmark: a table, one line per case and operation.
//
//   ninja -C build-lib2geom bezier_lib2geom_region_cases && build-lib2geom/bezier_lib2geom_region_cases

#include <2geom/intersection-graph.h>
#include <2geom/svg-path-parser.h>
#include <2geom/utils.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "core/path/svg_path_data.hpp"
#include "core/region/boolean.hpp"
#include "core/region/region.hpp"
#include "tests/bench/lib2geom/region_geom.hpp"
#include "tests/bench/region_bench_shapes.hpp"
#include "tests/bench/region_case_truth.hpp"

namespace {

namespace region = bezier::region;

region::Region region_of(const std::string& data, region::FillRule rule) {
  bezier::path::PathDataParse parse = bezier::path::parse_svg_path_data(data, 100000);
  if (parse.error) std::fprintf(stderr, "unparsed: %s\n", data.c_str());
  return region::region_from_path(std::move(parse.path), rule);
}

}  // namespace

int main() {
  std::printf("case | op | ours: area | lib2geom: area | points wrong / checked | verdict\n");
  int wrong_lines = 0, lines = 0;
  for (const bezier::bench::HardCase& c : bezier::bench::hard_cases()) {
    const region::FillRule rule = c.evenodd ? region::FillRule::evenodd : region::FillRule::nonzero;
    const region::Region a = region_of(c.a, rule), b = region_of(c.b, rule);
    const bezier::bench::CaseTruth truth = bezier::bench::case_truth(a, b);
    const Geom::PathVector ga = Geom::parse_svg_path(c.a.c_str());
    const Geom::PathVector gb = c.b.empty() ? Geom::PathVector() : Geom::parse_svg_path(c.b.c_str());
    const double area_tolerance = bezier::bench::kAreaTolerance * truth.box.area();
    int k = 0;
    for (const region::BooleanOperation op : bezier::bench::kCaseOperations) {
      ++lines;
      const double ours = truth.areas[static_cast<std::size_t>(k)];
      const bool ours_ok = truth.statuses[static_cast<std::size_t>(k)] == region::BooleanStatus::ok;
      ++k;
      std::string verdict;
      double area = NAN;
      int wrong = 0;
      try {
        Geom::PathIntersectionGraph graph(ga, gb);
        const Geom::PathVector r = op == region::BooleanOperation::union_        ? graph.getUnion()
                                   : op == region::BooleanOperation::intersection ? graph.getIntersection()
                                   : op == region::BooleanOperation::difference   ? graph.getAminusB()
                                                                                  : graph.getXOR();
        if (!graph.valid()) verdict += " invalid-graph";
        int non_bezier = 0;
        area = bezier::bench::geom_filled_area(r, &non_bezier);
        if (non_bezier > 0) verdict += " non-bezier-curves";
        for (const bezier::bench::SamplePoint& s : truth.points) {
          const bool expected = region::keeps(op, s.in_a, s.in_b);
          const bool got = r.winding(Geom::Point(s.p.x, s.p.y)) % 2 != 0;
          wrong += expected != got ? 1 : 0;
        }
        if (std::fabs(std::fabs(area) - ours) > area_tolerance) verdict += " AREA";
        if (wrong > 0) verdict += " POINTS";
      } catch (const Geom::Errors&) {
        // PathIntersectionGraph's own failure: it throws an error code, not an exception.
        verdict += " threw GEOM_ERR_INTERSECGRAPH";
      } catch (const std::exception& e) {
        verdict += std::string(" threw: ") + e.what();
      }
      if (!ours_ok) verdict += " (ours not ok)";
      if (verdict.empty()) verdict = " ok";
      wrong_lines += verdict == " ok" ? 0 : 1;
      std::printf("%s | %s | %.17g | %.17g | %d / %zu |%s\n", c.name.c_str(),
                  bezier::bench::operation_name(op), ours, area, wrong, truth.points.size(), verdict.c_str());
    }
  }
  std::printf("lines not ok: %d of %d\n", wrong_lines, lines);
  return 0;
}
