// Every boolean result of the region benchmark inputs, written bit for bit, so that a change
// meant to leave answers alone (a faster step of the boolean operations or of the searches
// under them) can be checked by comparing two runs:
//
//   build/tests/bezier_region_boolean_dump > before.txt    # on the old tree
//   build/tests/bezier_region_boolean_dump > after.txt     # on the new one
//   cmp before.txt after.txt
//
// The inputs (tests/bench/region_bench_shapes.hpp): the 8 glyph-outline pairs of 20, 50 and 100
// cubics by union, intersection, difference and xor, and each pair's first outline simplified;
// the hard cases by the four operations and simplify (nonzero or evenodd as each case says);
// and the union of the first 50-cubic pair under every work cap from half its work up to its
// work (steps of 37, the last 40 one by one), so that where the cap is met is compared too.
// Per result: status, work, area and contour count, then each contour (segment range, area)
// and each segment (source, segment, t0, t1, control points), every number as %a.
//
// With arguments `OP N...` (OP union or intersection) it runs only that operation on the pairs
// of N cubics, once, and writes one line per pair (status, work, area): the workload to count
// instructions on (valgrind --tool=callgrind).

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/path/svg_path_data.hpp"
#include "core/region/boolean.hpp"
#include "core/region/region.hpp"
#include "tests/bench/region_bench_shapes.hpp"

namespace {

namespace region = bezier::region;
using bezier::core::Point2;

constexpr std::int64_t kWork = 1000000000;

region::Region region_of(const bezier::bench::CubicOutline& points) {
  std::vector<bezier::core::Curve> curves;
  for (std::size_t k = 0; k + 3 < points.size(); k += 3) {
    curves.emplace_back(std::vector<Point2>{points[k], points[k + 1], points[k + 2], points[k + 3]});
  }
  return region::region_from_curves(std::move(curves), region::FillRule::nonzero);
}

void print_summary(const std::string& label, const region::BooleanResult& r) {
  std::printf("%s status=%d work=%lld area=%a contours=%zu segments=%zu\n", label.c_str(),
              static_cast<int>(r.status), static_cast<long long>(r.work), r.area,
              r.contours.size(), r.segments.size());
}

void print(const std::string& label, const region::BooleanResult& r) {
  print_summary(label, r);
  for (const region::ResultContour& c : r.contours) {
    std::printf(" contour %zu %zu %a\n", c.first_segment, c.end_segment, c.area);
  }
  for (const region::ResultSegment& s : r.segments) {
    std::printf("  segment %d %zu %a %a:", static_cast<int>(s.source), s.segment, s.t0, s.t1);
    for (const Point2 p : s.curve.points()) std::printf(" %a %a", p.x, p.y);
    std::printf("\n");
  }
}

constexpr region::BooleanOperation kOperations[] = {
    region::BooleanOperation::union_, region::BooleanOperation::intersection,
    region::BooleanOperation::difference, region::BooleanOperation::xor_};
constexpr const char* kOperationNames[] = {"union", "intersection", "difference", "xor"};

void dump_all() {
  for (const int n : bezier::bench::kPairCubicCounts) {
    const auto pairs = bezier::bench::outline_pairs(n, bezier::bench::kPairsPerCount);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const region::Region a = region_of(pairs[i].a), b = region_of(pairs[i].b);
      const std::string pair = "cubics " + std::to_string(n) + " pair " + std::to_string(i) + " ";
      for (int o = 0; o < 4; ++o) {
        print(pair + kOperationNames[o], region::boolean_operation(kOperations[o], a, b, kWork));
      }
      print(pair + "simplify", region::simplify(a, kWork));
    }
  }
  for (const bezier::bench::HardCase& c : bezier::bench::hard_cases()) {
    const region::FillRule rule = c.evenodd ? region::FillRule::evenodd : region::FillRule::nonzero;
    const region::Region a =
        region::region_from_path(bezier::path::parse_svg_path_data(c.a, 1000000).path, rule);
    const region::Region b =
        region::region_from_path(bezier::path::parse_svg_path_data(c.b, 1000000).path, rule);
    for (int o = 0; o < 4; ++o) {
      print(c.name + " " + kOperationNames[o], region::boolean_operation(kOperations[o], a, b, kWork));
    }
    print(c.name + " simplify", region::simplify(a, kWork));
  }
  const auto pairs = bezier::bench::outline_pairs(50, 1);
  const region::Region a = region_of(pairs[0].a), b = region_of(pairs[0].b);
  const std::int64_t full = region::boolean_operation(kOperations[0], a, b, kWork).work;
  for (std::int64_t cap = full / 2; cap <= full; cap += cap < full - 40 ? 37 : 1) {
    print_summary("cap " + std::to_string(cap),
                  region::boolean_operation(kOperations[0], a, b, cap));
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 1) {
    dump_all();
    return 0;
  }
  const bool is_union = std::strcmp(argv[1], "union") == 0;
  if (!is_union && std::strcmp(argv[1], "intersection") != 0) {
    std::fprintf(stderr, "usage: %s [union|intersection N...]\n", argv[0]);
    return 2;
  }
  for (int k = 2; k < argc; ++k) {
    const int n = std::atoi(argv[k]);
    const auto pairs = bezier::bench::outline_pairs(n, bezier::bench::kPairsPerCount);
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const region::BooleanResult r = region::boolean_operation(
          is_union ? kOperations[0] : kOperations[1], region_of(pairs[i].a),
          region_of(pairs[i].b), kWork);
      print_summary(std::string(argv[1]) + " cubics " + std::to_string(n) + " pair " +
                        std::to_string(i), r);
    }
  }
  return 0;
}
