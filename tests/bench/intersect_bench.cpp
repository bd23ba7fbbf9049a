// Curve-curve intersection throughput on the shared benchmark input
// (BENCHMARKS.md, "Benchmark input"): 20000 pairs of cubics from mulberry32 seed 1, 16 draws per
// pair in the order a0x a0y .. a3y b0x .. b3y. Certified libraries find 16178 intersections on
// them.
//
//   ninja -C build bezier_bench && build/tests/bezier_bench --benchmark_filter=Intersect
//
// Each iteration intersects all pairs; `time_per_pair` is the mean CPU time per pair and
// `intersections` the number found (counted over one pass, so it is comparable with 16178),
// per method at the default tolerance 1e-12. Also random pairs of degree 7 and 10 (control
// points uniform in [0,1]^2 from mulberry32 seeds 7 and 10), which cross many times.

#include <benchmark/benchmark.h>

#include <vector>

#include "core/intersect/intersect.hpp"
#include "tests/support/mulberry32.hpp"

namespace {

using bezier::core::Curve;
using bezier::core::IntersectMethod;
using bezier::core::Point2;

struct Pair {
  Curve a;
  Curve b;
};

std::vector<Pair> random_pairs(std::uint32_t seed, int degree, int count) {
  bezier::test::Mulberry32 rng(seed);
  std::vector<Pair> pairs;
  pairs.reserve(static_cast<std::size_t>(count));
  const auto curve = [&] {
    std::vector<Point2> pts(static_cast<std::size_t>(degree) + 1);
    for (Point2& p : pts) {
      p.x = rng.next();
      p.y = rng.next();
    }
    return Curve(std::move(pts));
  };
  for (int i = 0; i < count; ++i) {
    Curve a = curve();
    Curve b = curve();
    pairs.push_back({std::move(a), std::move(b)});
  }
  return pairs;
}

void run(benchmark::State& state, const std::vector<Pair>& pairs, IntersectMethod method) {
  bezier::core::IntersectOptions options;
  options.method = method;
  options.fat_curve_degree = static_cast<int>(state.range(0));
  std::int64_t found = 0, steps = 0, failed = 0;
  for (auto _ : state) {
    found = steps = failed = 0;
    for (const Pair& p : pairs) {
      const auto r = bezier::core::intersect(p.a, p.b, options);
      found += static_cast<std::int64_t>(r.intersections.size());
      steps += r.stats.iterations;
      failed += r.status != bezier::core::IntersectStatus::ok;
      benchmark::DoNotOptimize(r);
    }
  }
  const double n = static_cast<double>(pairs.size());
  state.counters["intersections"] = static_cast<double>(found);
  state.counters["steps_per_pair"] = static_cast<double>(steps) / n;
  state.counters["not_ok"] = static_cast<double>(failed);
  // CPU seconds per pair (printed with an SI prefix: "2.7u" is 2.7 microseconds).
  state.counters["time_per_pair"] = benchmark::Counter(
      n, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

const std::vector<Pair>& cubic_pairs() {
  static const std::vector<Pair> pairs = random_pairs(1, 3, 20000);
  return pairs;
}

void BM_IntersectCubicPairs_Hybrid(benchmark::State& state) {
  run(state, cubic_pairs(), IntersectMethod::hybrid);
}
void BM_IntersectCubicPairs_BezierClipping(benchmark::State& state) {
  run(state, cubic_pairs(), IntersectMethod::bezier_clipping);
}
void BM_IntersectCubicPairs_Subdivision(benchmark::State& state) {
  run(state, cubic_pairs(), IntersectMethod::subdivision);
}
// Arg: fat_curve_degree (3 is the default).
BENCHMARK(BM_IntersectCubicPairs_Hybrid)->Arg(3)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IntersectCubicPairs_BezierClipping)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IntersectCubicPairs_Subdivision)->Arg(2)->Unit(benchmark::kMillisecond);

const std::vector<Pair>& degree7_pairs() {
  static const std::vector<Pair> pairs = random_pairs(7, 7, 1000);
  return pairs;
}
const std::vector<Pair>& degree10_pairs() {
  static const std::vector<Pair> pairs = random_pairs(10, 10, 200);
  return pairs;
}

void BM_IntersectDegree7_Hybrid(benchmark::State& state) {
  run(state, degree7_pairs(), IntersectMethod::hybrid);
}
void BM_IntersectDegree7_BezierClipping(benchmark::State& state) {
  run(state, degree7_pairs(), IntersectMethod::bezier_clipping);
}
void BM_IntersectDegree10_Hybrid(benchmark::State& state) {
  run(state, degree10_pairs(), IntersectMethod::hybrid);
}
void BM_IntersectDegree10_BezierClipping(benchmark::State& state) {
  run(state, degree10_pairs(), IntersectMethod::bezier_clipping);
}
BENCHMARK(BM_IntersectDegree7_Hybrid)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IntersectDegree7_BezierClipping)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IntersectDegree10_Hybrid)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IntersectDegree10_BezierClipping)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace
