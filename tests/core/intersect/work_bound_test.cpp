// The work budget bounds every phase of intersect() (core/intersect/work_cost.hpp), on the
// requests of hostile magnitudes that ran for seconds at the API's default budget (and that
// tests/bench/worst_case_inputs.hpp times): by every method, the answer is complete or
// capped, the work reported exceeds the budget by at most one step's charges, and the CPU
// time stays far below a second (a wide margin: no timing is measured here, only a bound
// no bounded request comes near on any machine).

#include <gtest/gtest.h>

#include <cstdint>
#include <ctime>
#include <string>
#include <vector>

#include "api/limits.hpp"
#include "core/intersect/intersect.hpp"
#include "core/intersect/work_cost.hpp"
#include "tests/core/intersect/exact_roots.hpp"

namespace bezier::core {
namespace {

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// A bound no request of a few hundred milliseconds' worth of budget comes near.
constexpr double kGenerousCpuSeconds = 2.0;

/// The most one step of the search can charge beyond the check that admits it: the step,
/// the subdivision tests, two implicit clips, the coincidence test at its most evaluations
/// (five projections of 30 Gauss-Newton steps and two evaluations each) and a reported box.
std::int64_t one_step_at_most(int m, int n) {
  return step_cost(m, n, true) + subdivision_test_cost(m, n) + implicit_clip_cost(m) +
         implicit_clip_cost(n) + coincidence_test_cost(m, n, 5 * 32) + kCandidateCost;
}

struct Variant {
  const char* name;
  IntersectMethod method;
  int fat_curve_degree;
};
constexpr Variant kVariants[] = {{"hybrid", IntersectMethod::hybrid, 3},
                                 {"hybrid_fat2", IntersectMethod::hybrid, 2},
                                 {"bezier-clipping", IntersectMethod::bezier_clipping, 3},
                                 {"subdivision", IntersectMethod::subdivision, 3}};

/// Runs every method on f and g at the API's default budget and checks the bounds; when the
/// answer is complete and the curves are known to cross, it holds the exact crossing.
void expect_bounded(const Curve& f, const Curve& g, bool crossing_known) {
  const std::int64_t budget = api::Limits{}.max_work;
  for (const Variant& v : kVariants) {
    SCOPED_TRACE(v.name);
    IntersectOptions options;
    options.method = v.method;
    options.fat_curve_degree = v.fat_curve_degree;
    options.max_work = budget;
    const double start = thread_cpu_seconds();
    const IntersectionResult r = intersect(f, g, options);
    const double cpu = thread_cpu_seconds() - start;
    EXPECT_LT(cpu, kGenerousCpuSeconds);
    EXPECT_LE(r.stats.work, budget + one_step_at_most(f.degree(), g.degree()));
    ASSERT_TRUE(r.status == IntersectStatus::ok || r.status == IntersectStatus::work_cap_reached);
    if (r.status != IntersectStatus::ok) continue;
    if (crossing_known) {
      EXPECT_FALSE(r.intersections.empty());
    }
    for (const Intersection& x : r.intersections) {
      const auto root = test::exact_newton(f, g, x.t, x.s);
      ASSERT_TRUE(root.has_value());
      EXPECT_TRUE(test::contains(x.t_interval, root->t));
      EXPECT_TRUE(test::contains(x.s_interval, root->s));
    }
  }
}

// A parabola 1e14 tall against a line rising 1e6 over its length: the line
// 1e6 (x + 1/2) + 1.5 y = 0 is positive at f(0) = (2, -2) and negative at f(1) = (-1, -1), and
// f meets it at y near 333 333, inside g. The two run within 1.5e-6 rad of each other there,
// and subdivision keeps a column of undecided boxes along the crossing: grouping them pair
// by pair took seconds after the search had already run out of budget.
TEST(WorkBound, SteepParabolaAgainstASteepLine) {
  expect_bounded(Curve({{2, -2}, {-1, 1e14}, {-1, -1}}), Curve({{-0.5, 0}, {-2, 1e6}}), true);
}

// A cubic reaching 1e9 against the diagonal of the unit square, which it crosses near (1, 1)
// (f(0) = (0, 1) lies above the diagonal's line y = x, f(1) = (0, -2) below it).
TEST(WorkBound, WideCubicAgainstTheDiagonal) {
  expect_bounded(Curve({{0, 1}, {1e9, 1}, {0, -1e9}, {0, -2}}), Curve({{0, 0}, {1, 1}}), true);
}

// A quadratic reaching 3e129 against a quartic reaching 1e237 (found by work_bound_fuzzer):
// the search spends its budget at the precision floor, where the coincidence test projected
// five points onto the other curve with up to 30 Gauss-Newton steps each, charged as one step.
TEST(WorkBound, CoincidenceTestsAtThePrecisionFloor) {
  expect_bounded(Curve({{2.0, -2.0}, {-1.0, 0.0}, {-3.2364e+129, -7.0}}),
                 Curve({{0.0, -0.5},
                        {0.0, 7.0},
                        {0.0, 1e+237},
                        {9.999999999999996e+236, 9.999999999999992e+236},
                        {9.999999999999989e+236, 8.0}}),
                 false);
}

}  // namespace
}  // namespace bezier::core
