// The measuring kernels (core/measure/) on the shared benchmark input (BENCHMARKS.md, "Benchmark
// input"): the mulberry32 stream with seed 1, after the 20000 intersection pairs (320000 draws),
// gives curves of the degree asked for, x and y of each control point in turn; /nearest's target
// is the next two draws.
//
//   ninja -C build bezier_bench && build/tests/bezier_bench --benchmark_filter='Length|Bounds|Nearest'
//
// The argument is the degree (3: the shared random cubics; 7: degree-7 curves from the same
// stream). Each benchmark cycles through 1024 curves.

#include <benchmark/benchmark.h>

#include <vector>

#include "core/measure/arc_length.hpp"
#include "core/measure/bounds.hpp"
#include "core/measure/nearest.hpp"
#include "tests/support/mulberry32.hpp"

namespace {

using bezier::core::Curve;
using bezier::core::Point2;

constexpr std::size_t kCurves = 1024;

struct Case {
  Curve curve;
  Point2 target;
};

std::vector<Case> shared_cases(int degree) {
  bezier::test::Mulberry32 rng(1);
  for (int i = 0; i < 20000 * 16; ++i) rng.next();
  std::vector<Case> cases;
  for (std::size_t c = 0; c < kCurves; ++c) {
    std::vector<Point2> points(static_cast<std::size_t>(degree) + 1);
    for (Point2& p : points) {
      p.x = rng.next();
      p.y = rng.next();
    }
    const Point2 target{rng.next(), rng.next()};
    cases.push_back({Curve(std::move(points)), target});
  }
  return cases;
}

void BM_Length(benchmark::State& state) {
  const auto cases = shared_cases(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::arc_length(cases[i].curve, 0.0, 1.0).length);
    i = (i + 1) % kCurves;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Length)->Arg(3)->Arg(7);

void BM_Bounds(benchmark::State& state) {
  const auto cases = shared_cases(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::bounds(cases[i].curve, 0.0, 1.0).max);
    i = (i + 1) % kCurves;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Bounds)->Arg(3)->Arg(7);

void BM_Nearest(benchmark::State& state) {
  const auto cases = shared_cases(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::nearest(cases[i].curve, cases[i].target, 0.0, 1.0).t);
    i = (i + 1) % kCurves;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Nearest)->Arg(3)->Arg(7);

}  // namespace
