// Arc length at equal accuracy: our core::arc_length against lib2geom's bezier_length on the
// measuring curves of lib2geom_bench.cpp (1024 curves of degree 3, the shared random cubics,
// or 7, from the benchmark input stream of BENCHMARKS.md after the 20000 intersection pairs;
// whole interval [0, 1]; time per curve). Part of bezier_lib2geom_bench (CMakeLists.txt):
//
//   bezier_lib2geom_bench --benchmark_filter='BM_Length_' --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true --benchmark_enable_random_interleaving=true
//
// lib2geom's tolerance is absolute and says little about the error it reaches, so the
// comparison is made at the error reached. For lib2geom at tolerance 10^-tol_exp, its relative
// error on each curve is measured against our length at relative tolerance 1e-12 (whose
// error_bound is at most 1e-12 of the length, far below the errors compared here;
// lib2geom_bench.cpp checks those lengths against an independent long-double quadrature).
// Ours then runs at a relative tolerance equal to lib2geom's largest error over the curves
// (match 0), or to its median error (match 1). Our error_bound is at most that tolerance
// times the length, so where the bound holds our error on every curve is at most lib2geom's
// largest (match 0) or median (match 1) error: at least the same accuracy.
// Counters (both benchmarks): lib2geom_max_rel_err, lib2geom_median_rel_err, and for ours
// tolerance (the relative tolerance asked), max_rel_err, median_rel_err and bound_violations
// (curves whose distance from the reference exceeds the error_bound reported plus the
// reference's own).

#include <benchmark/benchmark.h>

#include <2geom/bezier-curve.h>
#include <2geom/point.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/measure/arc_length.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/mulberry32.hpp"

namespace {

using bezier::core::ArcLengthOptions;
using bezier::core::Curve;
using bezier::core::Point2;

constexpr std::size_t kCurves = 1024;

struct LengthCase {
  Curve curve;
  std::vector<Geom::Point> points;  // the same control points for lib2geom
  double reference = 0.0;           // ours at relative tolerance 1e-12
  double reference_bound = 0.0;     // its error_bound
};

const std::vector<LengthCase>& length_cases(int degree) {
  static std::vector<std::unique_ptr<std::vector<LengthCase>>> cache(32);
  auto& slot = cache[static_cast<std::size_t>(degree)];
  if (!slot) {
    bezier::test::Mulberry32 rng(1);
    for (int i = 0; i < 20000 * 16; ++i) rng.next();
    auto cases = std::make_unique<std::vector<LengthCase>>();
    for (std::size_t c = 0; c < kCurves; ++c) {
      Curve curve = bezier::test::random_curve<Point2>(rng, degree, 0.0, 1.0);
      rng.next();  // the /nearest target of lib2geom_bench.cpp's cases
      rng.next();
      std::vector<Geom::Point> points;
      for (const Point2& p : curve.points()) points.emplace_back(p.x, p.y);
      const auto reference = bezier::core::arc_length(curve, 0.0, 1.0);
      cases->push_back({std::move(curve), std::move(points), reference.length, reference.error_bound});
    }
    slot = std::move(cases);
  }
  return *slot;
}

double lib2geom_length(const LengthCase& c, double tolerance) {
  if (c.points.size() == 4) return Geom::bezier_length(c.points[0], c.points[1], c.points[2], c.points[3], tolerance);
  return Geom::bezier_length(c.points, tolerance);
}

struct ErrorSummary {
  double max = 0.0;
  double median = 0.0;
};

ErrorSummary relative_errors(const std::vector<LengthCase>& cases, const std::vector<double>& lengths) {
  std::vector<double> errors;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    errors.push_back(std::fabs(lengths[i] - cases[i].reference) / cases[i].reference);
  }
  std::sort(errors.begin(), errors.end());
  return {errors.back(), errors[errors.size() / 2]};
}

ErrorSummary lib2geom_errors(const std::vector<LengthCase>& cases, double tolerance) {
  std::vector<double> lengths;
  for (const LengthCase& c : cases) lengths.push_back(lib2geom_length(c, tolerance));
  return relative_errors(cases, lengths);
}

void lib2geom_counters(benchmark::State& state, const ErrorSummary& theirs) {
  state.counters["lib2geom_max_rel_err"] = theirs.max;
  state.counters["lib2geom_median_rel_err"] = theirs.median;
}

// Args: degree, -log10(lib2geom's tolerance).
void BM_Length_EqualAccuracy_Lib2geom(benchmark::State& state) {
  const auto& cases = length_cases(static_cast<int>(state.range(0)));
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(lib2geom_length(cases[i], tolerance));
    i = (i + 1) % kCurves;
  }
  lib2geom_counters(state, lib2geom_errors(cases, tolerance));
}
BENCHMARK(BM_Length_EqualAccuracy_Lib2geom)
    ->ArgNames({"degree", "tol_exp"})
    ->ArgsProduct({{3, 7}, {2, 4, 6}})
    ->Unit(benchmark::kMicrosecond);

// Args: degree, -log10(lib2geom's tolerance), match (0: lib2geom's largest error, 1: its
// median error, as our relative tolerance).
void BM_Length_EqualAccuracy_Ours(benchmark::State& state) {
  const auto& cases = length_cases(static_cast<int>(state.range(0)));
  const ErrorSummary theirs = lib2geom_errors(cases, std::pow(10.0, -static_cast<double>(state.range(1))));
  ArcLengthOptions options;
  options.relative_tolerance = state.range(2) == 0 ? theirs.max : theirs.median;
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::arc_length(cases[i].curve, 0.0, 1.0, options).length);
    i = (i + 1) % kCurves;
  }
  std::vector<double> lengths;
  std::int64_t violations = 0;
  for (const LengthCase& c : cases) {
    const auto measured = bezier::core::arc_length(c.curve, 0.0, 1.0, options);
    lengths.push_back(measured.length);
    violations += std::fabs(measured.length - c.reference) > measured.error_bound + c.reference_bound;
  }
  const ErrorSummary ours = relative_errors(cases, lengths);
  lib2geom_counters(state, theirs);
  state.counters["tolerance"] = options.relative_tolerance;
  state.counters["max_rel_err"] = ours.max;
  state.counters["median_rel_err"] = ours.median;
  state.counters["bound_violations"] = static_cast<double>(violations);
}
BENCHMARK(BM_Length_EqualAccuracy_Ours)
    ->ArgNames({"degree", "tol_exp", "match"})
    ->ArgsProduct({{3, 7}, {2, 4, 6}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
