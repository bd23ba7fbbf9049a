// Path against path (core/path/path_intersections.hpp) on two glyph-like closed outlines of
// 64 cubics each, against the two-curve kernel alone on the segment pairs whose control
// boxes meet (the pairs the path search runs it on): what the sweep, the per-pair setup
// and the joint bookkeeping add.
//
//   ninja -C build bezier_bench && build/tests/bezier_bench --benchmark_filter='PathOutlines'
//
// Each outline is a closed curve r(θ) = 1 + a sin(f θ + φ) + 0.05 cos(g θ) through 64
// points at equal steps of θ, each span a cubic with Catmull-Rom tangents (the inner
// control points a sixth of the neighbours' difference away): smooth at every joint, like
// a glyph's contour. The first has a = 0.15, f = 5, φ = 0, g = 11; the second a = 0.12,
// f = 7, φ = 0.5, g = 13, moved by (0.02, -0.01): two wavy rings over the same circle that
// cross each other wherever their waves do (the counters give the figures).

#include <benchmark/benchmark.h>

#include <cmath>
#include <utility>
#include <vector>

#include "core/intersect/intersect.hpp"
#include "core/path/path_intersections.hpp"
#include "core/path/segment_boxes.hpp"

namespace {

using bezier::core::Curve;
using bezier::core::Point2;
using bezier::path::Path;

constexpr int kSegments = 64;

struct Wave {
  double amplitude;
  double frequency;
  double phase;
  double second_frequency;
  Point2 shift;
};

Path outline(const Wave& w) {
  std::vector<Point2> on;
  for (int k = 0; k < kSegments; ++k) {
    const double theta = 2 * M_PI * k / kSegments;
    const double r = 1 + w.amplitude * std::sin(w.frequency * theta + w.phase) +
                     0.05 * std::cos(w.second_frequency * theta);
    on.push_back({r * std::cos(theta) + w.shift.x, r * std::sin(theta) + w.shift.y});
  }
  Path path;
  const auto at = [&](int k) { return on[static_cast<std::size_t>((k + kSegments) % kSegments)]; };
  for (int k = 0; k < kSegments; ++k) {
    const Point2 p0 = at(k), p1 = at(k + 1);
    const Point2 c1 = p0 + (at(k + 1) - at(k - 1)) / 6.0;
    const Point2 c2 = p1 - (at(k + 2) - at(k)) / 6.0;
    path.segments.emplace_back(std::vector<Point2>{p0, c1, c2, p1});
  }
  path.subpaths.push_back({0, static_cast<std::size_t>(kSegments), true});
  return path;
}

constexpr Wave kFirst{0.15, 5, 0.0, 11, {0.0, 0.0}};
constexpr Wave kSecond{0.12, 7, 0.5, 13, {0.02, -0.01}};

void BM_PathOutlinesIntersect(benchmark::State& state) {
  const Path a = outline(kFirst);
  const Path b = outline(kSecond);
  bezier::path::PathIntersectionResult r;
  for (auto _ : state) {
    r = bezier::path::intersect(a, b, {});
    benchmark::DoNotOptimize(r);
  }
  state.counters["intersections"] = static_cast<double>(r.intersections.size());
  state.counters["pairs"] = static_cast<double>(r.stats.candidate_pairs);
}
BENCHMARK(BM_PathOutlinesIntersect)->Unit(benchmark::kMicrosecond);

void BM_PathOutlinesKernelOnMeetingPairs(benchmark::State& state) {
  const Path a = outline(kFirst);
  const Path b = outline(kSecond);
  std::vector<bezier::core::Rect> boxes_a, boxes_b;
  for (const Curve& c : a.segments) boxes_a.push_back(bezier::path::control_box(c));
  for (const Curve& c : b.segments) boxes_b.push_back(bezier::path::control_box(c));
  bezier::core::WorkBudget sweep_budget;
  const auto pairs = bezier::path::meeting_boxes(boxes_a, boxes_b, sweep_budget).pairs;
  std::size_t found = 0;
  for (auto _ : state) {
    found = 0;
    for (const auto& [i, j] : pairs) {
      const auto r = bezier::core::intersect(a.segments[i], b.segments[j]);
      found += r.intersections.size();
      benchmark::DoNotOptimize(r);
    }
  }
  state.counters["intersections"] = static_cast<double>(found);
  state.counters["pairs"] = static_cast<double>(pairs.size());
}
BENCHMARK(BM_PathOutlinesKernelOnMeetingPairs)->Unit(benchmark::kMicrosecond);

}  // namespace
