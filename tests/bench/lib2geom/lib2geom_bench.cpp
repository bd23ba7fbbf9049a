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
//
// Measuring: 1024 curves of degree 3 (the shared random cubics) or 7 from the
// benchmark input stream (BENCHMARKS.md) after the 20000 intersection pairs, x and y of each control point in
// turn, each followed by a /nearest target (the next two draws): the inputs of
// tests/bench/measure_bench.cpp. Whole interval [0, 1]; time per curve.
//   * length: ours core::arc_length at relative tolerance 1e-12 (the API's) and looser;
//     lib2geom's bezier_length (what BezierCurve::length and Path::length call; the 4-point
//     overload for cubics): control polygon against chord, halving with the tolerance
//     (absolute; the curves have lengths near 1) until they agree, returning their mean,
//     at most 8 levels deep (256 pieces), so asking below its reach costs the full 511
//     nodes. Counters max_rel_err and median_rel_err: |result - reference| / reference over
//     the 1024 curves, the reference being adaptive Gauss-Legendre in long double
//     (ReferenceLength below); for ours, bound_violations counts the curves whose
//     reference lies outside the error_bound reported.
//   * nearest, one target: ours core::nearest; lib2geom's nearest_time(Point, D2<Bezier>),
//     the roots of (B - q) · B' by its Bézier root finder. Counters: farther_than_other
//     (curves where the returned point is farther than the other library's by more than
//     1e-9: a local minimum reported) and max_excess (the largest such difference), both
//     distances from core::evaluate at the returned t.
//   * bounds: ours core::bounds; lib2geom's bounds_exact(D2<Bezier>) (roots of each
//     coordinate's derivative, then the values there). Counter max_face_diff: the largest
//     |lib2geom face - our face|.

#include <benchmark/benchmark.h>

#include <2geom/basic-intersection.h>
#include <2geom/bezier-curve.h>
#include <2geom/bezier.h>
#include <2geom/d2.h>
#include <2geom/nearest-time.h>
#include <2geom/point.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <utility>
#include <vector>

#include "core/curve/evaluate.hpp"
#include "core/intersect/intersect.hpp"
#include "core/measure/arc_length.hpp"
#include "core/measure/bounds.hpp"
#include "core/measure/nearest.hpp"
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

// ---------------------------------------------------------------------------------------
// Measuring: length, nearest, bounds

constexpr std::size_t kMeasureCurves = 1024;

// Gauss-Legendre nodes and weights of order n on [-1, 1] in long double: Newton's method on
// P_n (three-term recurrence) from cos(pi (i + 3/4) / (n + 1/2)), w = 2 / ((1 - x^2) P_n'(x)^2).
struct GaussRule {
  std::vector<long double> x;
  std::vector<long double> w;
};

GaussRule gauss_legendre(int n) {
  GaussRule rule;
  for (int i = 0; i < n; ++i) {
    long double x = std::cos(std::numbers::pi_v<long double> * (i + 0.75L) / (n + 0.5L));
    long double derivative = 0.0L;
    for (int iteration = 0; iteration < 100; ++iteration) {
      long double p_prev = 1.0L, p = x;
      for (int k = 2; k <= n; ++k) {
        const long double next = ((2 * k - 1) * x * p - (k - 1) * p_prev) / k;
        p_prev = p;
        p = next;
      }
      derivative = n * (x * p - p_prev) / (x * x - 1.0L);
      const long double step = p / derivative;
      x -= step;
      if (std::fabs(step) <= 1e-19L) break;
    }
    rule.x.push_back(x);
    rule.w.push_back(2.0L / ((1.0L - x * x) * derivative * derivative));
  }
  return rule;
}

// ∫_0^1 |B'(t)| dt in long double: the hodograph n (P_{i+1} - P_i) evaluated by de Casteljau,
// integrated by 10- and 20-point Gauss-Legendre on each piece, a piece halved until
// |G20 - G10| <= 1e-17 × (control polygon length) × (its width), 60 levels at most. G20 is
// exact for polynomials of degree 39 and G10 for 19, so where they agree to that the G20
// value is far more accurate than the tolerance; a cusp (|B'| like |t - t0|) is cornered by
// the halving. Independent of core::arc_length: other rules, other splitting, other
// precision.
class ReferenceLength {
 public:
  explicit ReferenceLength(const Curve& curve) {
    const auto pts = curve.points();
    const long double n = static_cast<long double>(pts.size() - 1);
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      hx_.push_back(n * (static_cast<long double>(pts[i + 1].x) - pts[i].x));
      hy_.push_back(n * (static_cast<long double>(pts[i + 1].y) - pts[i].y));
      polygon_ += std::hypot(static_cast<long double>(pts[i + 1].x) - pts[i].x,
                             static_cast<long double>(pts[i + 1].y) - pts[i].y);
    }
  }

  long double operator()() const { return piece(0.0L, 1.0L, 0); }

 private:
  long double speed(long double t) const {
    std::array<long double, 32> x{}, y{};
    const std::size_t m = hx_.size();
    std::copy(hx_.begin(), hx_.end(), x.begin());
    std::copy(hy_.begin(), hy_.end(), y.begin());
    for (std::size_t r = 1; r < m; ++r) {
      for (std::size_t i = 0; i + r < m; ++i) {
        x[i] += t * (x[i + 1] - x[i]);
        y[i] += t * (y[i + 1] - y[i]);
      }
    }
    return std::hypot(x[0], y[0]);
  }

  long double rule(const GaussRule& g, long double a, long double b) const {
    const long double half = (b - a) / 2, mid = (a + b) / 2;
    long double sum = 0.0L;
    for (std::size_t i = 0; i < g.x.size(); ++i) sum += g.w[i] * speed(mid + half * g.x[i]);
    return half * sum;
  }

  long double piece(long double a, long double b, int depth) const {
    static const GaussRule g10 = gauss_legendre(10), g20 = gauss_legendre(20);
    const long double coarse = rule(g10, a, b), fine = rule(g20, a, b);
    if (std::fabs(fine - coarse) <= 1e-17L * polygon_ * (b - a) || depth >= 60) return fine;
    const long double m = (a + b) / 2;
    return piece(a, m, depth + 1) + piece(m, b, depth + 1);
  }

  std::vector<long double> hx_, hy_;
  long double polygon_ = 0.0L;
};

struct MeasureCase {
  Curve curve;
  Point2 target;
  std::vector<Geom::Point> points;  // the same control points for lib2geom
  Geom::D2<Geom::Bezier> d2;
  double reference_length = 0.0;
};

// As tests/bench/measure_bench.cpp: the benchmark input stream (BENCHMARKS.md) after the 20000 pairs.
const std::vector<MeasureCase>& measure_cases(int degree) {
  static std::vector<std::unique_ptr<std::vector<MeasureCase>>> cache(32);
  auto& slot = cache[static_cast<std::size_t>(degree)];
  if (!slot) {
    bezier::test::Mulberry32 rng(1);
    for (int i = 0; i < 20000 * 16; ++i) rng.next();
    auto cases = std::make_unique<std::vector<MeasureCase>>();
    for (std::size_t c = 0; c < kMeasureCurves; ++c) {
      Curve curve = random_curve(rng, degree);
      const Point2 target{rng.next(), rng.next()};
      std::vector<double> xs, ys;
      for (const Point2& p : curve.points()) {
        xs.push_back(p.x);
        ys.push_back(p.y);
      }
      const double reference = static_cast<double>(ReferenceLength(curve)());
      std::vector<Geom::Point> points = to_geom(curve);
      cases->push_back({std::move(curve), target, std::move(points),
                        Geom::D2<Geom::Bezier>{Geom::Bezier(xs), Geom::Bezier(ys)}, reference});
    }
    slot = std::move(cases);
  }
  return *slot;
}

// max_rel_err and median_rel_err of `lengths` against the reference lengths.
void length_error_counters(benchmark::State& state, const std::vector<MeasureCase>& cases,
                           const std::vector<double>& lengths) {
  std::vector<double> errors;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    errors.push_back(std::fabs(lengths[i] - cases[i].reference_length) / cases[i].reference_length);
  }
  std::sort(errors.begin(), errors.end());
  state.counters["max_rel_err"] = errors.back();
  state.counters["median_rel_err"] = errors[errors.size() / 2];
}

// Ours. Args: degree, -log10(relative tolerance). Counters besides the errors:
// bound_violations (curves whose |length - reference| exceeds the error_bound reported),
// max_rel_bound (the largest error_bound / length) and not_ok (tolerance not met).
void BM_Length_Ours(benchmark::State& state) {
  const auto& cases = measure_cases(static_cast<int>(state.range(0)));
  bezier::core::ArcLengthOptions options;
  options.relative_tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::arc_length(cases[i].curve, 0.0, 1.0, options).length);
    i = (i + 1) % kMeasureCurves;
  }
  std::vector<double> lengths;
  std::int64_t violations = 0, not_ok = 0;
  double max_bound = 0.0;
  for (const MeasureCase& c : cases) {
    const auto measured = bezier::core::arc_length(c.curve, 0.0, 1.0, options);
    lengths.push_back(measured.length);
    violations += std::fabs(measured.length - c.reference_length) > measured.error_bound;
    not_ok += measured.tolerance_met ? 0 : 1;
    max_bound = std::max(max_bound, measured.error_bound / measured.length);
  }
  length_error_counters(state, cases, lengths);
  state.counters["bound_violations"] = static_cast<double>(violations);
  state.counters["max_rel_bound"] = max_bound;
  state.counters["not_ok"] = static_cast<double>(not_ok);
}
BENCHMARK(BM_Length_Ours)
    ->ArgNames({"degree", "tol_exp"})
    ->ArgsProduct({{3, 7}, {12, 10, 8, 6, 4}})
    ->Unit(benchmark::kMicrosecond);

double lib2geom_length(const MeasureCase& c, double tolerance) {
  if (c.points.size() == 4) return Geom::bezier_length(c.points[0], c.points[1], c.points[2], c.points[3], tolerance);
  return Geom::bezier_length(c.points, tolerance);
}

// lib2geom. Args: degree, -log10(tolerance).
void BM_Length_Lib2geom(benchmark::State& state) {
  const auto& cases = measure_cases(static_cast<int>(state.range(0)));
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(lib2geom_length(cases[i], tolerance));
    i = (i + 1) % kMeasureCurves;
  }
  std::vector<double> lengths;
  for (const MeasureCase& c : cases) lengths.push_back(lib2geom_length(c, tolerance));
  length_error_counters(state, cases, lengths);
}
BENCHMARK(BM_Length_Lib2geom)
    ->ArgNames({"degree", "tol_exp"})
    ->ArgsProduct({{3, 7}, {12, 8, 6, 4, 2}})
    ->Unit(benchmark::kMicrosecond);

double distance_at(const MeasureCase& c, double t) {
  const Point2 d = bezier::core::evaluate(c.curve, t) - c.target;
  return std::hypot(d.x, d.y);
}

double lib2geom_nearest(const MeasureCase& c) {
  return Geom::nearest_time(Geom::Point(c.target.x, c.target.y), c.d2, 0.0, 1.0);
}

// farther_than_other and max_excess: this library's distances against the other's.
void nearest_counters(benchmark::State& state, const std::vector<MeasureCase>& cases, bool ours) {
  std::int64_t farther = 0;
  double max_excess = 0.0;
  for (const MeasureCase& c : cases) {
    const double d_ours = distance_at(c, bezier::core::nearest(c.curve, c.target, 0.0, 1.0).t);
    const double d_lib2geom = distance_at(c, lib2geom_nearest(c));
    const double excess = ours ? d_ours - d_lib2geom : d_lib2geom - d_ours;
    farther += excess > 1e-9;
    max_excess = std::max(max_excess, excess);
  }
  state.counters["farther_than_other"] = static_cast<double>(farther);
  state.counters["max_excess"] = max_excess;
}

void BM_Nearest_Ours(benchmark::State& state) {
  const auto& cases = measure_cases(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::nearest(cases[i].curve, cases[i].target, 0.0, 1.0).t);
    i = (i + 1) % kMeasureCurves;
  }
  nearest_counters(state, cases, true);
}
BENCHMARK(BM_Nearest_Ours)->ArgName("degree")->Arg(3)->Arg(7)->Unit(benchmark::kMicrosecond);

void BM_Nearest_Lib2geom(benchmark::State& state) {
  const auto& cases = measure_cases(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(lib2geom_nearest(cases[i]));
    i = (i + 1) % kMeasureCurves;
  }
  nearest_counters(state, cases, false);
}
BENCHMARK(BM_Nearest_Lib2geom)->ArgName("degree")->Arg(3)->Arg(7)->Unit(benchmark::kMicrosecond);

// max_face_diff: the largest |lib2geom face - our face| (the same in both benchmarks).
void bounds_counters(benchmark::State& state, const std::vector<MeasureCase>& cases) {
  double max_diff = 0.0;
  for (const MeasureCase& c : cases) {
    const auto ours = bezier::core::bounds(c.curve, 0.0, 1.0);
    const Geom::OptRect theirs = Geom::bounds_exact(c.d2);
    max_diff = std::max({max_diff, std::fabs((*theirs)[Geom::X].min() - ours.min.x),
                         std::fabs((*theirs)[Geom::X].max() - ours.max.x),
                         std::fabs((*theirs)[Geom::Y].min() - ours.min.y),
                         std::fabs((*theirs)[Geom::Y].max() - ours.max.y)});
  }
  state.counters["max_face_diff"] = max_diff;
}

void BM_Bounds_Ours(benchmark::State& state) {
  const auto& cases = measure_cases(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::bounds(cases[i].curve, 0.0, 1.0).max);
    i = (i + 1) % kMeasureCurves;
  }
  bounds_counters(state, cases);
}
BENCHMARK(BM_Bounds_Ours)->ArgName("degree")->Arg(3)->Arg(7)->Unit(benchmark::kMicrosecond);

void BM_Bounds_Lib2geom(benchmark::State& state) {
  const auto& cases = measure_cases(static_cast<int>(state.range(0)));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(Geom::bounds_exact(cases[i].d2));
    i = (i + 1) % kMeasureCurves;
  }
  bounds_counters(state, cases);
}
BENCHMARK(BM_Bounds_Lib2geom)->ArgName("degree")->Arg(3)->Arg(7)->Unit(benchmark::kMicrosecond);
}  // namespace
