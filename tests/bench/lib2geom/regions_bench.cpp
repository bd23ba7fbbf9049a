// Regions against lib2geom 1.2.2: boolean operations and point membership on the same inputs,
// in the same executable as lib2geom_bench.cpp (build: CMakeLists.txt beside this file).
//
//   bezier_lib2geom_bench --benchmark_filter='Regions_|Contains_' --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true --benchmark_enable_random_interleaving=true
//
// Booleans: the pairs of glyph-like outlines of tests/bench/region_bench_shapes.hpp, 8 pairs of
// 20, 50 and 100 cubics each; time per pair.
//   * ours: region::boolean_operation (union or intersection, nonzero), from the Regions built
//     once outside the timed loop;
//   * lib2geom: Geom::PathIntersectionGraph(a, b) then getUnion() or getIntersection() (the
//     graph is built inside the timed loop: it is the intersection step), from PathVectors of
//     CubicBeziers built once.
// Counters: for lib2geom, max_rel_area_diff (the largest |area - ours| / ours over the pairs,
// its area by Green's theorem on its result's Bézier curves) and invalid (pairs whose graph
// reported !valid()); for ours, not_ok (pairs whose status was not ok).
//
// Contains: tests/bench/contains_bench.cpp's 64-cubic outline and targets (its 32 x 32 grid,
// and B(1/3) of each segment); time per target.
//   * ours: RegionWinding (prepared once) .at(target) and the nonzero rule, as /contains;
//   * lib2geom: PathVector::winding(target) != 0.
// Counter disagreements: spread targets where lib2geom's answer differs from ours (on the
// boundary targets the answers mean nothing: ours says `boundary`).

#include <benchmark/benchmark.h>

#include <2geom/bezier-curve.h>
#include <2geom/intersection-graph.h>
#include <2geom/path.h>
#include <2geom/pathvector.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/curve/evaluate.hpp"
#include "core/region/boolean.hpp"
#include "core/region/region.hpp"
#include "core/region/winding.hpp"
#include "tests/bench/lib2geom/region_geom.hpp"
#include "tests/bench/region_bench_shapes.hpp"
#include "tests/bench/region_case_truth.hpp"

namespace {

using bezier::bench::CubicOutline;
using bezier::core::Point2;
namespace region = bezier::region;

constexpr std::int64_t kWork = 1000000000;

region::Region region_of(const CubicOutline& points) {
  std::vector<bezier::core::Curve> curves;
  for (std::size_t k = 0; k + 3 < points.size(); k += 3) {
    curves.emplace_back(std::vector<Point2>{points[k], points[k + 1], points[k + 2], points[k + 3]});
  }
  return region::region_from_curves(std::move(curves), region::FillRule::nonzero);
}

struct PreparedPairs {
  std::vector<region::Region> ours_a, ours_b;
  std::vector<Geom::PathVector> geom_a, geom_b;
};

const PreparedPairs& prepared_pairs(int cubics) {
  static std::vector<std::pair<int, PreparedPairs>> cache;
  for (const auto& [n, p] : cache) {
    if (n == cubics) return p;
  }
  PreparedPairs p;
  for (const auto& pair : bezier::bench::outline_pairs(cubics, bezier::bench::kPairsPerCount)) {
    p.ours_a.push_back(region_of(pair.a));
    p.ours_b.push_back(region_of(pair.b));
    p.geom_a.push_back(bezier::bench::geom_outline(pair.a));
    p.geom_b.push_back(bezier::bench::geom_outline(pair.b));
  }
  cache.emplace_back(cubics, std::move(p));
  return cache.back().second;
}

region::BooleanOperation op_of(int code) {
  return code == 0 ? region::BooleanOperation::union_ : region::BooleanOperation::intersection;
}

void BM_Regions_Ours(benchmark::State& state) {
  const PreparedPairs& pairs = prepared_pairs(static_cast<int>(state.range(0)));
  const region::BooleanOperation op = op_of(static_cast<int>(state.range(1)));
  int not_ok = 0;
  for (auto _ : state) {
    not_ok = 0;
    for (std::size_t i = 0; i < pairs.ours_a.size(); ++i) {
      const region::BooleanResult r = region::boolean_operation(op, pairs.ours_a[i], pairs.ours_b[i], kWork);
      not_ok += r.status == region::BooleanStatus::ok ? 0 : 1;
      benchmark::DoNotOptimize(r.area);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pairs.ours_a.size()));
  state.counters["not_ok"] = not_ok;
  state.counters["us_per_pair"] = benchmark::Counter(
      static_cast<double>(pairs.ours_a.size()) * 1e-6, benchmark::Counter::kIsIterationInvariantRate |
                                                           benchmark::Counter::kInvert);
}

void BM_Regions_Lib2geom(benchmark::State& state) {
  const PreparedPairs& pairs = prepared_pairs(static_cast<int>(state.range(0)));
  const int code = static_cast<int>(state.range(1));
  for (auto _ : state) {
    for (std::size_t i = 0; i < pairs.geom_a.size(); ++i) {
      Geom::PathIntersectionGraph graph(pairs.geom_a[i], pairs.geom_b[i]);
      Geom::PathVector r = code == 0 ? graph.getUnion() : graph.getIntersection();
      benchmark::DoNotOptimize(r.size());
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pairs.geom_a.size()));
  // Quality, outside the timed loop.
  double worst = 0;
  int invalid = 0;
  for (std::size_t i = 0; i < pairs.geom_a.size(); ++i) {
    Geom::PathIntersectionGraph graph(pairs.geom_a[i], pairs.geom_b[i]);
    invalid += graph.valid() ? 0 : 1;
    const Geom::PathVector r = code == 0 ? graph.getUnion() : graph.getIntersection();
    const double ours = region::boolean_operation(op_of(code), pairs.ours_a[i], pairs.ours_b[i], kWork).area;
    worst = std::max(worst, std::fabs(bezier::bench::geom_area(r) - ours) / std::fabs(ours));
  }
  state.counters["max_rel_area_diff"] = worst;
  state.counters["invalid"] = invalid;
  state.counters["us_per_pair"] = benchmark::Counter(
      static_cast<double>(pairs.geom_a.size()) * 1e-6, benchmark::Counter::kIsIterationInvariantRate |
                                                           benchmark::Counter::kInvert);
}

void pair_args(benchmark::internal::Benchmark* b) {
  b->ArgNames({"cubics", "op"});  // op 0: union, 1: intersection
  for (const int op : {0, 1}) {
    for (const int n : bezier::bench::kPairCubicCounts) b->Args({n, op});
  }
  b->Unit(benchmark::kMicrosecond);
}
BENCHMARK(BM_Regions_Ours)->Apply(pair_args);
BENCHMARK(BM_Regions_Lib2geom)->Apply(pair_args);

std::vector<Point2> contains_targets(bool on_boundary, const CubicOutline& outline) {
  if (!on_boundary) return bezier::bench::contains_spread_targets();
  std::vector<Point2> targets;
  for (std::size_t k = 0; k + 3 < outline.size(); k += 3) {
    const bezier::core::Curve c({outline[k], outline[k + 1], outline[k + 2], outline[k + 3]});
    targets.push_back(bezier::core::evaluate(c, 1.0 / 3));
  }
  return targets;
}

void BM_Contains_Ours_Outline64(benchmark::State& state) {
  const CubicOutline outline = bezier::bench::contains_outline();
  const region::Region r = region_of(outline);
  const std::vector<Point2> targets = contains_targets(state.range(0) == 1, outline);
  const region::RegionWinding prepared(r);
  std::int64_t inside = 0;
  for (auto _ : state) {
    for (const Point2 q : targets) {
      bezier::core::WorkBudget work(kWork);
      const auto w = prepared.at(q, work);
      inside += w && region::inside(*w, r.fill_rule) ? 1 : 0;
    }
    benchmark::DoNotOptimize(inside);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(targets.size()));
}

void BM_Contains_Lib2geom_Outline64(benchmark::State& state) {
  const CubicOutline outline = bezier::bench::contains_outline();
  const Geom::PathVector pv = bezier::bench::geom_outline(outline);
  const std::vector<Point2> targets = contains_targets(state.range(0) == 1, outline);
  std::int64_t inside = 0;
  for (auto _ : state) {
    for (const Point2 q : targets) inside += pv.winding(Geom::Point(q.x, q.y)) != 0 ? 1 : 0;
    benchmark::DoNotOptimize(inside);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(targets.size()));
  if (state.range(0) == 0) {
    const region::Region r = region_of(outline);
    int disagreements = 0;
    for (const Point2 q : targets) {
      const auto w = region::winding(r, q, kWork);
      const bool ours = w && region::inside(*w, r.fill_rule);
      disagreements += ours != (pv.winding(Geom::Point(q.x, q.y)) != 0) ? 1 : 0;
    }
    state.counters["disagreements"] = disagreements;
  }
}

void contains_args(benchmark::internal::Benchmark* b) {
  b->ArgName("on_outline")->Arg(0)->Arg(1);
}
BENCHMARK(BM_Contains_Ours_Outline64)->Apply(contains_args);
BENCHMARK(BM_Contains_Lib2geom_Outline64)->Apply(contains_args);

}  // namespace
