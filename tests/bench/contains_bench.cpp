// POST /contains's kernel (core/region/winding.hpp) per target on a glyph-like closed
// outline of 64 cubics: targets spread over the outline's box (most are decided by the
// segments' boxes alone, those near the outline by subdivision), and targets on the
// outline (each subdivided down to the band, the costliest ordinary case).
//
//   ninja -C build bezier_bench && build/tests/bezier_bench --benchmark_filter='Contains'
//
// The outline is the first of path_bench.cpp's: r(θ) = 1 + 0.15 sin(5 θ) + 0.05 cos(11 θ)
// through 64 points at equal steps of θ, each span a cubic with Catmull-Rom tangents. The
// spread targets are a 32 x 32 grid over [-1.3, 1.3]², moved off the grid's symmetry by an
// irrational-looking offset; the boundary targets are B(1/3) of each segment, rounded.

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/curve/evaluate.hpp"
#include "core/region/winding.hpp"

namespace {

using bezier::core::Curve;
using bezier::core::Point2;

constexpr int kOutlineSegments = 64;

bezier::region::Region wavy_outline() {
  std::vector<Point2> on;
  for (int k = 0; k < kOutlineSegments; ++k) {
    const double theta = 2 * M_PI * k / kOutlineSegments;
    const double r = 1 + 0.15 * std::sin(5 * theta) + 0.05 * std::cos(11 * theta);
    on.push_back({r * std::cos(theta), r * std::sin(theta)});
  }
  const auto at = [&](int k) {
    return on[static_cast<std::size_t>((k + kOutlineSegments) % kOutlineSegments)];
  };
  std::vector<Curve> curves;
  for (int k = 0; k < kOutlineSegments; ++k) {
    const Point2 p0 = at(k), p1 = at(k + 1);
    const Point2 c1 = p0 + (at(k + 1) - at(k - 1)) / 6.0;
    const Point2 c2 = p1 - (at(k + 2) - at(k)) / 6.0;
    curves.emplace_back(std::vector<Point2>{p0, c1, c2, p1});
  }
  return bezier::region::region_from_curves(std::move(curves), bezier::region::FillRule::nonzero);
}

void run(benchmark::State& state, const bezier::region::Region& region,
         const std::vector<Point2>& targets) {
  const bezier::region::RegionWinding prepared(region);
  std::int64_t inside = 0, spent = 0;
  for (auto _ : state) {
    spent = 0;
    for (const Point2 q : targets) {
      bezier::core::WorkBudget work;
      const auto w = prepared.at(q, work);
      spent += work.spent();
      inside += w && bezier::region::inside(*w, region.fill_rule) ? 1 : 0;
    }
    benchmark::DoNotOptimize(inside);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(targets.size()));
  // The work units charged per target (the units of the work cap), to set against the time.
  state.counters["work_units_per_target"] =
      static_cast<double>(spent) / static_cast<double>(targets.size());
}

void BM_Contains_Outline64_SpreadTargets(benchmark::State& state) {
  const auto region = wavy_outline();
  std::vector<Point2> targets;
  for (int i = 0; i < 32; ++i) {
    for (int j = 0; j < 32; ++j) {
      targets.push_back({-1.3 + 2.6 * (i + 0.3183) / 32, -1.3 + 2.6 * (j + 0.5772) / 32});
    }
  }
  run(state, region, targets);
}
BENCHMARK(BM_Contains_Outline64_SpreadTargets);

void BM_Contains_Outline64_BoundaryTargets(benchmark::State& state) {
  const auto region = wavy_outline();
  std::vector<Point2> targets;
  for (const Curve& c : region.path.segments) targets.push_back(bezier::core::evaluate(c, 1.0 / 3));
  run(state, region, targets);
}
BENCHMARK(BM_Contains_Outline64_BoundaryTargets);

}  // namespace
