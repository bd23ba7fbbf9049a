// Classification throughput on the shared benchmark input (BENCHMARKS.md, "Benchmark input"): the
// mulberry32 stream with seed 1, after the 20000 intersection pairs (320000 draws), gives single
// cubics, 8 draws each in the order x0 y0 x1 y1 x2 y2 x3 y3.
//
//   ninja -C build bezier_bench && build/tests/bezier_bench --benchmark_filter=Classify
//
// Reports ns per classification (the target: <= 50 ns; Paper.js takes 80-100 ns
// on this machine).

#include <benchmark/benchmark.h>

#include <array>
#include <vector>

#include "core/cubic/classify.hpp"
#include "core/cubic/predicates.hpp"
#include "tests/support/mulberry32.hpp"

namespace {

using bezier::core::Point2;
using Cubic = std::array<Point2, 4>;

std::vector<Cubic> shared_cubics(std::size_t count) {
  bezier::test::Mulberry32 rng(1);
  for (int i = 0; i < 20000 * 16; ++i) rng.next();
  std::vector<Cubic> cubics(count);
  for (Cubic& c : cubics) {
    for (Point2& p : c) {
      p.x = rng.next();
      p.y = rng.next();
    }
  }
  return cubics;
}

// Full classification: type, canonical point, inflections, cusp, double point. The
// argument is the number of distinct cubics cycled through: 4096 (256 KiB, from L2) and
// 256 (16 KiB, from L1).
void BM_Classify(benchmark::State& state) {
  const std::size_t count = static_cast<std::size_t>(state.range(0));
  const std::vector<Cubic> cubics = shared_cubics(count);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto c = bezier::core::classify(std::span<const Point2, 4>(cubics[i]));
    benchmark::DoNotOptimize(c);
    i = (i + 1) & (count - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Classify)->Arg(4096)->Arg(256);

// The predicates alone (the filter, and the exact path when it is unsure).
void BM_ClassifyPredicates(benchmark::State& state) {
  const std::vector<Cubic> cubics = shared_cubics(4096);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto p = bezier::core::cubic_predicates(std::span<const Point2, 4>(cubics[i]));
    benchmark::DoNotOptimize(p);
    i = (i + 1) & 4095;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ClassifyPredicates);

// Cubics exactly on an edge (cusp, loop at start, inflection at t = 1) always take the
// exact expansion-arithmetic path: the price of exactness where it is needed.
void BM_ClassifyOnAnEdge(benchmark::State& state) {
  const std::vector<Cubic> cubics = {
      Cubic{Point2{0, 0}, Point2{0, 1}, Point2{1, 1}, Point2{-1, 0}},
      Cubic{Point2{0, 0}, Point2{0, 1}, Point2{1, 1}, Point2{-3, -6}},
      Cubic{Point2{0, 0}, Point2{0, 1}, Point2{1, 1}, Point2{0.5, 1}},
      Cubic{Point2{3, -1}, Point2{2.5, 1}, Point2{4, 1.5}, Point2{0.5, -2}},
  };
  std::size_t i = 0;
  for (auto _ : state) {
    const auto c = bezier::core::classify(std::span<const Point2, 4>(cubics[i]));
    benchmark::DoNotOptimize(c);
    i = (i + 1) & 3;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ClassifyOnAnEdge);

}  // namespace
