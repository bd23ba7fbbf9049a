// Self-intersection and loop area: the kernel against the seed's sampling method,
// same binary, same run.
//
//   ninja -C build bezier_bench && build/tests/bezier_bench --benchmark_filter='Loops'
//
// Inputs: the seed's degree-7 example, and random self-intersecting cubics drawn from
// mulberry32 seed 1 after the 20000 intersection pairs (BENCHMARKS.md, "Benchmark input": 320000
// draws skipped, then 8 draws per cubic P0x P0y .. P3x P3y, kept when the loop lies on [0, 1]).

#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/curve/area.hpp"
#include "core/cubic/double_point.hpp"
#include "core/loop/loop_area.hpp"
#include "core/self_intersect/self_intersection.hpp"
#include "tests/support/mulberry32.hpp"

namespace {

using bezier::core::Curve;
using bezier::core::Point2;

const Curve& degree7_example() {
  static const Curve curve({{0, 0}, {1, 1}, {2, 3}, {1, 4}, {0, 4}, {-1, 3}, {0, 1}, {1, 0}});
  return curve;
}

std::vector<Curve> make_loop_cubics(std::size_t count) {
  bezier::test::Mulberry32 rng(1);
  for (int i = 0; i < 20000 * 16; ++i) rng.next();
  std::vector<Curve> cubics;
  while (cubics.size() < count) {
    std::vector<Point2> p(4);
    for (Point2& q : p) q = {rng.next(), rng.next()};
    Curve c(std::move(p));
    const auto dp = bezier::core::cubic_double_point(c);
    if (dp && dp->on_segment && !(dp->t1 == 0.0 && dp->t2 == 1.0)) cubics.push_back(std::move(c));
  }
  return cubics;
}

const std::vector<Curve>& loop_cubics() {
  static const std::vector<Curve> cubics = make_loop_cubics(1000);
  return cubics;
}

// ---------------------------------------------------------------------------------------
// The baseline: seed 000's method, written out here. 1000 uniform samples, the closest
// pair at least kGap samples apart (nearer samples are always close, so "non-adjacent"
// needs a window), Newton on B(v) - B(u) from that pair, and the loop area by Green's
// theorem with a fixed 20-point Gauss-Legendre rule plus the chord. Finds one loop at most,
// and the rule stops being exact above degree 20.

struct Jet {
  Point2 point;
  Point2 d1;
};

// Plain de Casteljau with the first derivative (the seed's evaluation, no allocation).
Jet plain_jet(const Curve& c, double t) {
  Point2 w[32];
  const int n = c.degree();
  for (int i = 0; i <= n; ++i) w[i] = c[i];
  for (int level = n; level > 1; --level) {
    for (int i = 0; i < level; ++i) w[i] = (1.0 - t) * w[i] + t * w[i + 1];
  }
  return {(1.0 - t) * w[0] + t * w[1], n * (w[1] - w[0])};
}

// Gauss-Legendre nodes and weights on [-1, 1]: roots of P_20 by Newton's method from
// Tricomi's initial guesses, w_i = 2 / ((1 - x_i^2) P_20'(x_i)^2) (Abramowitz & Stegun 25.4.29).
struct GaussLegendre {
  double x[20];
  double w[20];
};

GaussLegendre gauss_legendre_20() {
  constexpr int n = 20;
  GaussLegendre gl{};
  for (int i = 0; i < n; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::fabs(dx) < 1e-16) break;
    }
    gl.x[i] = x;
    gl.w[i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
  return gl;
}

struct BaselineLoop {
  double t1 = 0.0;
  double t2 = 0.0;
  double area = 0.0;
};

BaselineLoop sampling_loop_area(const Curve& c, const GaussLegendre& gl) {
  constexpr int kSamples = 1000;
  constexpr int kGap = 10;
  Point2 s[kSamples];
  for (int i = 0; i < kSamples; ++i) s[i] = plain_jet(c, i / (kSamples - 1.0)).point;
  double best = std::numeric_limits<double>::infinity();
  int bi = 0, bj = 0;
  for (int i = 0; i < kSamples; ++i) {
    for (int j = i + kGap; j < kSamples; ++j) {
      const Point2 d = s[j] - s[i];
      const double d2 = d.x * d.x + d.y * d.y;
      if (d2 < best) {
        best = d2;
        bi = i;
        bj = j;
      }
    }
  }
  double u = bi / (kSamples - 1.0), v = bj / (kSamples - 1.0);
  for (int it = 0; it < 8; ++it) {
    const Jet ju = plain_jet(c, u), jv = plain_jet(c, v);
    const Point2 f = jv.point - ju.point;
    const double det = bezier::core::cross(-ju.d1, jv.d1);
    if (det == 0.0) break;
    u += bezier::core::cross(-f, jv.d1) / det;
    v += bezier::core::cross(-ju.d1, -f) / det;
  }
  // 1/2 ∫_u^v cross(B, B') dt by the 20-point rule, plus the chord B(v) -> B(u).
  double integral = 0.0;
  for (int k = 0; k < 20; ++k) {
    const double t = 0.5 * (u + v) + 0.5 * (v - u) * gl.x[k];
    const Jet j = plain_jet(c, t);
    integral += gl.w[k] * bezier::core::cross(j.point, j.d1);
  }
  const double area = 0.25 * (v - u) * integral +
                      0.5 * bezier::core::cross(plain_jet(c, v).point, plain_jet(c, u).point);
  return {u, v, area};
}

// ---------------------------------------------------------------------------------------

void BM_Loops_Degree7_LoopArea(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(bezier::core::loop_area(degree7_example()));
}
BENCHMARK(BM_Loops_Degree7_LoopArea);

void BM_Loops_Degree7_SelfIntersections(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(bezier::core::self_intersections(degree7_example()));
}
BENCHMARK(BM_Loops_Degree7_SelfIntersections);

void BM_Loops_Degree7_SamplingBaseline(benchmark::State& state) {
  const GaussLegendre gl = gauss_legendre_20();
  for (auto _ : state) benchmark::DoNotOptimize(sampling_loop_area(degree7_example(), gl));
}
BENCHMARK(BM_Loops_Degree7_SamplingBaseline);

void BM_Loops_Cubic_SelfIntersections(benchmark::State& state) {
  const auto& cubics = loop_cubics();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::self_intersections(cubics[i]));
    i = i + 1 == cubics.size() ? 0 : i + 1;
  }
}
BENCHMARK(BM_Loops_Cubic_SelfIntersections);

void BM_Loops_Cubic_SelfIntersectionsGeneral(benchmark::State& state) {
  const auto& cubics = loop_cubics();
  bezier::core::SelfIntersectionOptions options;
  options.cubic_closed_form = false;
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::self_intersections(cubics[i], options));
    i = i + 1 == cubics.size() ? 0 : i + 1;
  }
}
BENCHMARK(BM_Loops_Cubic_SelfIntersectionsGeneral);

void BM_Loops_Cubic_LoopArea(benchmark::State& state) {
  const auto& cubics = loop_cubics();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(bezier::core::loop_area(cubics[i]));
    i = i + 1 == cubics.size() ? 0 : i + 1;
  }
}
BENCHMARK(BM_Loops_Cubic_LoopArea);

void BM_Loops_Cubic_SamplingBaseline(benchmark::State& state) {
  const GaussLegendre gl = gauss_legendre_20();
  const auto& cubics = loop_cubics();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sampling_loop_area(cubics[i], gl));
    i = i + 1 == cubics.size() ? 0 : i + 1;
  }
}
BENCHMARK(BM_Loops_Cubic_SamplingBaseline);

}  // namespace
