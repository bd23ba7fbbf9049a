// Our kernel against lib2geom 1.2.2 (Inkscape's 2Geom, Debian lib2geom-dev) on the same
// inputs, in one executable. Build: see CMakeLists.txt beside this file.
//
//   bezier_lib2geom_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//       --benchmark_enable_random_interleaving=true
//
// Intersections: the 20000 random cubic pairs of the shared benchmark input (BENCHMARKS.md;
// mulberry32 seed 1, 16 draws a pair: a0x a0y .. a3y b0x .. b3y); certified libraries find 16178
// intersections on them.
//   * ours: core::intersect with the API defaults (hybrid, fat-curve degree 3, intervals
//     narrower than 1e-12, certified), and the same at tolerance 1e-8 and with Bézier
//     clipping;
//   * lib2geom: Geom::find_intersections(xs, std::vector<Point>, std::vector<Point>,
//     precision), which is find_intersections_bezier_clipping (Sederberg-Nishita). Its
//     `precision` is the parameter-interval width it stops at, clamped from below to
//     MAX_PRECISION = 1e-8 in bezier-clipping.cpp, so 1e-12 runs as 1e-8; the default is
//     EPSILON = 1e-6. It returns interval midpoints, uncertified.
// Counters: us_per_pair (time per pair), intersections (over one pass: compare with 16178),
// pairs_differing (pairs whose count differs from ours at the defaults), max_param_error
// (largest |t - t_ours| or |s - s_ours| over roots matched to ours), max_residual
// (largest |A(t) - B(s)|, coordinates in [0, 1)). Quality is measured once, outside the
// timed loop.
//
// Evaluation: a curve of degree 3, 7 or 20 with control points uniform in [0,1]^2 from
// mulberry32 seeded with the degree, at 1024 parameters uniform in [0,1] from the same
// stream (as tests/bench/evaluate_bench.cpp).
//   * ours: core::evaluate (compensated de Casteljau, within one rounding);
//   * lib2geom: D2<Bezier>::valueAt (inline Horner-like bernstein_value_at, both
//     coordinates), and BezierCurve::pointAt through a Geom::Curve reference (how a Path's
//     curves are evaluated: one virtual call).
// Counter max_err_ulps: the largest distance, in ulps, from the correctly rounded exact value
// (rational de Casteljau, tests/support/exact_bezier.hpp) over the 1024 parameters.

#include <benchmark/benchmark.h>

#include <2geom/basic-intersection.h>
#include <2geom/bezier-curve.h>
#include <2geom/bezier.h>
#include <2geom/d2.h>
#include <2geom/point.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "core/curve/evaluate.hpp"
#include "core/intersect/intersect.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/mulberry32.hpp"

namespace {

using bezier::core::Curve;
using bezier::core::IntersectMethod;
using bezier::core::IntersectOptions;
using bezier::core::Point2;

// ---------------------------------------------------------------------------------------
// Inputs

struct Pair {
  Curve a;
  Curve b;
  std::vector<Geom::Point> a2;  // the same control points for lib2geom
  std::vector<Geom::Point> b2;
};

std::vector<Geom::Point> to_geom(const Curve& c) {
  std::vector<Geom::Point> pts;
  for (const Point2& p : c.points()) pts.emplace_back(p.x, p.y);
  return pts;
}

Curve random_curve(bezier::test::Mulberry32& rng, int degree) {
  std::vector<Point2> pts(static_cast<std::size_t>(degree) + 1);
  for (Point2& p : pts) p = {rng.next(), rng.next()};
  return Curve(std::move(pts));
}

const std::vector<Pair>& cubic_pairs() {
  static const std::vector<Pair> pairs = [] {
    bezier::test::Mulberry32 rng(1);
    std::vector<Pair> v;
    v.reserve(20000);
    for (int i = 0; i < 20000; ++i) {
      Curve a = random_curve(rng, 3);
      Curve b = random_curve(rng, 3);
      std::vector<Geom::Point> a2 = to_geom(a), b2 = to_geom(b);
      v.push_back({std::move(a), std::move(b), std::move(a2), std::move(b2)});
    }
    return v;
  }();
  return pairs;
}

using Roots = std::vector<std::pair<double, double>>;  // (t, s) per intersection

// Our roots at the API defaults: the reference for pairs_differing and max_param_error.
const std::vector<Roots>& reference_roots() {
  static const std::vector<Roots> roots = [] {
    std::vector<Roots> all;
    for (const Pair& p : cubic_pairs()) {
      Roots r;
      for (const auto& x : bezier::core::intersect(p.a, p.b, IntersectOptions{}).intersections) r.emplace_back(x.t, x.s);
      all.push_back(std::move(r));
    }
    return all;
  }();
  return roots;
}

// ---------------------------------------------------------------------------------------
// Intersections

void quality_counters(benchmark::State& state, const std::vector<Roots>& found) {
  const auto& pairs = cubic_pairs();
  const auto& reference = reference_roots();
  std::int64_t total = 0, differing = 0;
  double max_param = 0.0, max_residual = 0.0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    total += static_cast<std::int64_t>(found[i].size());
    differing += found[i].size() != reference[i].size();
    for (const auto& [t, s] : found[i]) {
      const Point2 d = bezier::core::evaluate(pairs[i].a, t) - bezier::core::evaluate(pairs[i].b, s);
      max_residual = std::max(max_residual, std::hypot(d.x, d.y));
      double nearest = INFINITY;
      for (const auto& [rt, rs] : reference[i]) nearest = std::min(nearest, std::max(std::fabs(t - rt), std::fabs(s - rs)));
      if (nearest < 1e-3) max_param = std::max(max_param, nearest);  // matched to one of ours
    }
  }
  state.counters["intersections"] = static_cast<double>(total);
  state.counters["pairs_differing"] = static_cast<double>(differing);
  state.counters["max_param_error"] = max_param;
  state.counters["max_residual"] = max_residual;
}

void per_pair_counter(benchmark::State& state) {
  const double n = static_cast<double>(cubic_pairs().size());
  state.counters["us_per_pair"] =
      benchmark::Counter(n * 1e-6, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Ours. Args: method (0 hybrid, 1 Bézier clipping), -log10(tolerance).
void BM_CubicPairs_Ours(benchmark::State& state) {
  const auto& pairs = cubic_pairs();
  (void)reference_roots();  // built before timing
  IntersectOptions options;
  options.method = state.range(0) == 0 ? IntersectMethod::hybrid : IntersectMethod::bezier_clipping;
  options.tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
  for (auto _ : state) {
    for (const Pair& p : pairs) benchmark::DoNotOptimize(bezier::core::intersect(p.a, p.b, options));
  }
  std::vector<Roots> found;
  for (const Pair& p : pairs) {
    Roots r;
    for (const auto& x : bezier::core::intersect(p.a, p.b, options).intersections) r.emplace_back(x.t, x.s);
    found.push_back(std::move(r));
  }
  quality_counters(state, found);
  per_pair_counter(state);
}
BENCHMARK(BM_CubicPairs_Ours)
    ->ArgNames({"clip", "tol_exp"})
    ->Args({0, 12})
    ->Args({0, 8})
    ->Args({1, 12})
    ->Unit(benchmark::kMillisecond);

// lib2geom. Arg: -log10(precision); 12 runs as 1e-8 (lib2geom's floor, see above).
void BM_CubicPairs_Lib2geom(benchmark::State& state) {
  const auto& pairs = cubic_pairs();
  (void)reference_roots();
  const double precision = std::pow(10.0, -static_cast<double>(state.range(0)));
  Roots xs;
  for (auto _ : state) {
    for (const Pair& p : pairs) {
      Geom::find_intersections(xs, p.a2, p.b2, precision);
      benchmark::DoNotOptimize(xs.data());
    }
  }
  std::vector<Roots> found;
  for (const Pair& p : pairs) {
    Roots r;
    Geom::find_intersections(r, p.a2, p.b2, precision);
    found.push_back(std::move(r));
  }
  quality_counters(state, found);
  per_pair_counter(state);
}
BENCHMARK(BM_CubicPairs_Lib2geom)->ArgName("prec_exp")->Arg(6)->Arg(12)->Unit(benchmark::kMillisecond);

// ---------------------------------------------------------------------------------------
// Evaluation

constexpr std::size_t kParameterCount = 1024;

struct EvalInput {
  Curve curve;
  std::vector<double> ts;
  std::vector<Point2> exact;  // B(t_i) correctly rounded
  Geom::D2<Geom::Bezier> d2;
  std::unique_ptr<Geom::Curve> path_curve;
};

const EvalInput& eval_input(int degree) {
  static std::vector<std::unique_ptr<EvalInput>> cache(32);
  auto& slot = cache[static_cast<std::size_t>(degree)];
  if (!slot) {
    bezier::test::Mulberry32 rng(static_cast<std::uint32_t>(degree));
    Curve curve = random_curve(rng, degree);
    std::vector<double> ts(kParameterCount);
    for (double& t : ts) t = rng.next();
    std::vector<double> xs, ys;
    for (const Point2& p : curve.points()) {
      xs.push_back(p.x);
      ys.push_back(p.y);
    }
    const Geom::D2<Geom::Bezier> d2{Geom::Bezier(xs), Geom::Bezier(ys)};
    std::vector<Point2> exact;
    const auto points = bezier::test::exact_points(curve);
    for (const double t : ts) exact.push_back(bezier::test::to_double(bezier::test::exact_evaluate(points, t)));
    auto path_curve = std::make_unique<Geom::BezierCurve>(d2);
    slot = std::make_unique<EvalInput>(EvalInput{std::move(curve), std::move(ts), std::move(exact), d2, std::move(path_curve)});
  }
  return *slot;
}

// Distance in ulps between two finite doubles of the same sign (0 when equal).
double ulps(double a, double b) {
  if (a == b) return 0.0;
  if ((a < 0) != (b < 0)) return INFINITY;
  const auto ia = std::bit_cast<std::int64_t>(std::fabs(a)), ib = std::bit_cast<std::int64_t>(std::fabs(b));
  return static_cast<double>(ia > ib ? ia - ib : ib - ia);
}

template <class Eval>
void eval_accuracy(benchmark::State& state, const EvalInput& in, Eval eval) {
  double worst = 0.0;
  for (std::size_t i = 0; i < kParameterCount; ++i) {
    const Point2 p = eval(in.ts[i]);
    worst = std::max({worst, ulps(p.x, in.exact[i].x), ulps(p.y, in.exact[i].y)});
  }
  state.counters["max_err_ulps"] = worst;
  state.SetItemsProcessed(state.iterations());
}

void BM_Eval_Ours(benchmark::State& state) {
  const EvalInput& in = eval_input(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::evaluate(in.curve, in.ts[i]));
    i = (i + 1) & (kParameterCount - 1);
  }
  eval_accuracy(state, in, [&](double t) { return bezier::core::evaluate(in.curve, t); });
}
BENCHMARK(BM_Eval_Ours)->ArgName("degree")->Arg(3)->Arg(7)->Arg(20);

void BM_Eval_Lib2geom_D2Bezier(benchmark::State& state) {
  const EvalInput& in = eval_input(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(in.d2.valueAt(in.ts[i]));
    i = (i + 1) & (kParameterCount - 1);
  }
  eval_accuracy(state, in, [&](double t) {
    const Geom::Point p = in.d2.valueAt(t);
    return Point2{p[Geom::X], p[Geom::Y]};
  });
}
BENCHMARK(BM_Eval_Lib2geom_D2Bezier)->ArgName("degree")->Arg(3)->Arg(7)->Arg(20);

void BM_Eval_Lib2geom_CurvePointAt(benchmark::State& state) {
  const EvalInput& in = eval_input(static_cast<int>(state.range(0)));
  const Geom::Curve& curve = *in.path_curve;
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(curve.pointAt(in.ts[i]));
    i = (i + 1) & (kParameterCount - 1);
  }
  eval_accuracy(state, in, [&](double t) {
    const Geom::Point p = curve.pointAt(t);
    return Point2{p[Geom::X], p[Geom::Y]};
  });
}
BENCHMARK(BM_Eval_Lib2geom_CurvePointAt)->ArgName("degree")->Arg(3)->Arg(7)->Arg(20);

// 1000 parameters in a row (lib2geom has no batch evaluation either).
void BM_Eval1000_Ours(benchmark::State& state) {
  const EvalInput& in = eval_input(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    for (std::size_t i = 0; i < 1000; ++i) benchmark::DoNotOptimize(bezier::core::evaluate(in.curve, in.ts[i]));
  }
  state.SetItemsProcessed(state.iterations() * 1000);
}
BENCHMARK(BM_Eval1000_Ours)->ArgName("degree")->Arg(3)->Arg(20);

void BM_Eval1000_Lib2geom_D2Bezier(benchmark::State& state) {
  const EvalInput& in = eval_input(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    for (std::size_t i = 0; i < 1000; ++i) benchmark::DoNotOptimize(in.d2.valueAt(in.ts[i]));
  }
  state.SetItemsProcessed(state.iterations() * 1000);
}
BENCHMARK(BM_Eval1000_Lib2geom_D2Bezier)->ArgName("degree")->Arg(3)->Arg(20);

}  // namespace
