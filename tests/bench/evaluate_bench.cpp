// Evaluation and polars: B(t) at one t and at 1000 t for degrees 3, 7
// and 20, uniform sampling, derivatives, subdivision, first polar, blossom and portion.
//
//   ninja -C build bezier_bench && build/tests/bezier_bench --benchmark_filter='Evaluate|Polar'
//
// Inputs: control points uniform in [0,1]^2 (or [0,1]^3) from mulberry32 seeded with the
// degree (as intersect_bench's degree-7 and degree-10 pairs), then 1024 parameters uniform
// in [0,1] from the same stream. The one-t benchmarks cycle through those parameters, so
// nothing is hoisted out of the loop. `items_per_second` counts evaluations (points).
//
// BM_Evaluate_PlainCasteljau is the uncompensated de Casteljau on a stack array, written
// out here: what the compensation (CasteljauRow) and its heap row cost over the textbook
// algorithm. lib2geom's evaluation is compared in tests/bench/lib2geom/ (optional target).

#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "core/curve/derivative.hpp"
#include "core/curve/evaluate.hpp"
#include "core/curve/polar.hpp"
#include "core/curve/subdivide.hpp"
#include "tests/support/mulberry32.hpp"

namespace {

using bezier::core::BasicCurve;
using bezier::core::Curve;
using bezier::core::Curve3;
using bezier::core::Point2;
using bezier::core::Point3;

constexpr std::size_t kParameterCount = 1024;  // a power of two: cycling is a mask

struct Input2 {
  Curve curve;
  std::vector<double> ts;
};

struct Input3 {
  Curve3 curve;
  std::vector<double> ts;
};

Input2 input2(int degree) {
  bezier::test::Mulberry32 rng(static_cast<std::uint32_t>(degree));
  std::vector<Point2> points(static_cast<std::size_t>(degree) + 1);
  for (Point2& p : points) p = {rng.next(), rng.next()};
  std::vector<double> ts(kParameterCount);
  for (double& t : ts) t = rng.next();
  return {Curve(std::move(points)), std::move(ts)};
}

Input3 input3(int degree) {
  bezier::test::Mulberry32 rng(static_cast<std::uint32_t>(degree));
  std::vector<Point3> points(static_cast<std::size_t>(degree) + 1);
  for (Point3& p : points) p = {rng.next(), rng.next(), rng.next()};
  std::vector<double> ts(kParameterCount);
  for (double& t : ts) t = rng.next();
  return {Curve3(std::move(points)), std::move(ts)};
}

int degree_arg(const benchmark::State& state) { return static_cast<int>(state.range(0)); }

// The textbook algorithm: n rounds of P_i <- (1 - t) P_i + t P_{i+1} on a stack copy.
// Plain double arrays: Point2's member initialisers would zero all 32 entries per call.
Point2 plain_casteljau(const Curve& curve, double t) {
  double x[32], y[32];  // only the first n + 1 are written and read (degree <= 31)
  const int n = curve.degree();
  for (int i = 0; i <= n; ++i) {
    x[i] = curve[i].x;
    y[i] = curve[i].y;
  }
  for (int level = n; level > 0; --level) {
    for (int i = 0; i < level; ++i) {
      x[i] = (1.0 - t) * x[i] + t * x[i + 1];
      y[i] = (1.0 - t) * y[i] + t * y[i + 1];
    }
  }
  return {x[0], y[0]};
}

// ---------------------------------------------------------------------------------------
// B(t)

// One point: the cost of a single /evaluate with one t, kernel only.
void BM_Evaluate_OneT(benchmark::State& state) {
  const Input2 in = input2(degree_arg(state));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::evaluate(in.curve, in.ts[i]));
    i = (i + 1) & (kParameterCount - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Evaluate_OneT)->Arg(3)->Arg(7)->Arg(20);

// 1000 given parameters in one call sequence (a `t` array of 1000 values).
void BM_Evaluate_1000T(benchmark::State& state) {
  const Input2 in = input2(degree_arg(state));
  for (auto _ : state) {
    for (std::size_t i = 0; i < 1000; ++i) benchmark::DoNotOptimize(bezier::core::evaluate(in.curve, in.ts[i]));
  }
  state.SetItemsProcessed(state.iterations() * 1000);
}
BENCHMARK(BM_Evaluate_1000T)->Arg(3)->Arg(7)->Arg(20);

// `samples: 1000`: uniform_parameters + evaluate, the result collected in a vector.
void BM_Evaluate_Sample1000(benchmark::State& state) {
  const Input2 in = input2(degree_arg(state));
  for (auto _ : state) benchmark::DoNotOptimize(bezier::core::sample(in.curve, 1000));
  state.SetItemsProcessed(state.iterations() * 1000);
}
BENCHMARK(BM_Evaluate_Sample1000)->Arg(3)->Arg(7)->Arg(20);

// The uncompensated baseline (see the file comment).
void BM_Evaluate_PlainCasteljau(benchmark::State& state) {
  const Input2 in = input2(degree_arg(state));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(plain_casteljau(in.curve, in.ts[i]));
    i = (i + 1) & (kParameterCount - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Evaluate_PlainCasteljau)->Arg(3)->Arg(7)->Arg(20);

// 3-D points (/evaluate and /polar take them too).
void BM_Evaluate3_OneT(benchmark::State& state) {
  const Input3 in = input3(degree_arg(state));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::evaluate(in.curve, in.ts[i]));
    i = (i + 1) & (kParameterCount - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Evaluate3_OneT)->Arg(3)->Arg(20);

// ---------------------------------------------------------------------------------------
// Derivatives and subdivision

// B'(t) .. B^(k)(t) at one t: args degree, k. (20, 20) is /evaluate's costliest per-t work
// at the default limits (max_degree 20, derivatives <= max_degree).
void BM_Evaluate_DerivativesAt(benchmark::State& state) {
  const Input2 in = input2(degree_arg(state));
  const int order = static_cast<int>(state.range(1));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::derivatives_at(in.curve, in.ts[i], order));
    i = (i + 1) & (kParameterCount - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Evaluate_DerivativesAt)->Args({3, 1})->Args({3, 2})->Args({7, 2})->Args({20, 2})->Args({20, 20});

void BM_Evaluate_Subdivide(benchmark::State& state) {
  const Input2 in = input2(degree_arg(state));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::subdivide(in.curve, in.ts[i]));
    i = (i + 1) & (kParameterCount - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Evaluate_Subdivide)->Arg(3)->Arg(7)->Arg(20);

// ---------------------------------------------------------------------------------------
// Polars

// The first polar at t0: a curve of degree n - 1.
void BM_Polar_First(benchmark::State& state) {
  const Input2 in = input2(degree_arg(state));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::first_polar(in.curve, in.ts[i]));
    i = (i + 1) & (kParameterCount - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Polar_First)->Arg(3)->Arg(7)->Arg(20);

// A /polar request with one t0 and one t: the first polar, then its point at t.
void BM_Polar_FirstAndPoint(benchmark::State& state) {
  const Input2 in = input2(degree_arg(state));
  std::size_t i = 0;
  for (auto _ : state) {
    const Curve p = bezier::core::first_polar(in.curve, in.ts[i]);
    benchmark::DoNotOptimize(bezier::core::evaluate(p, in.ts[(i + 1) & (kParameterCount - 1)]));
    i = (i + 1) & (kParameterCount - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Polar_FirstAndPoint)->Arg(3)->Arg(7)->Arg(20);

// The blossom b(u_1, ..., u_n): n distinct arguments, one point.
void BM_Polar_Blossom(benchmark::State& state) {
  const Input2 in = input2(degree_arg(state));
  const auto n = static_cast<std::size_t>(in.curve.degree());
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::blossom(in.curve, std::span<const double>(in.ts).subspan(i, n)));
    i = (i + n) & (kParameterCount / 2 - 1);  // stays below 512, so i + n <= 1024
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Polar_Blossom)->Arg(3)->Arg(7)->Arg(20);

// The piece [a, b] reparametrised to [0, 1] by blossoming: n + 1 blossoms, O(n^3).
void BM_Polar_Portion(benchmark::State& state) {
  const Input2 in = input2(degree_arg(state));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::portion(in.curve, in.ts[i], in.ts[i + 1]));
    i = (i + 2) & (kParameterCount - 1);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Polar_Portion)->Arg(3)->Arg(7)->Arg(20);

}  // namespace
