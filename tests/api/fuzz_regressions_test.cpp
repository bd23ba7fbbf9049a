// Regression tests for what fuzzing found (docs/FUZZING.md lists the findings, the fuzz
// target and the input that found each), through the API and in the kernel. Each test is
// named after its finding. The expected values are the contracts of the headers (and, for
// F6, the double point in closed form), never numbers copied from a run.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <ctime>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "api/handler.hpp"
#include "core/cubic/classify.hpp"
#include "core/cubic/double_point.hpp"
#include "core/cubic/predicates.hpp"
#include "core/curve/evaluate.hpp"
#include "core/intersect/intersect.hpp"
#include "core/self_intersect/self_intersection.hpp"
#include "tests/core/cubic/classify_oracle.hpp"
#include "tests/support/exact.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

// Whether a null sits inside an array of `value`: where nlohmann writes a NaN or an
// infinity (JSON has neither). No 200 answer documents a null inside an array.
bool has_null_in_array(const json& value, bool in_array = false) {
  if (value.is_null()) return in_array;
  if (value.is_array()) {
    for (const auto& e : value) {
      if (has_null_in_array(e, true)) return true;
    }
  } else if (value.is_object()) {
    for (const auto& [key, member] : value.items()) {
      if (has_null_in_array(member, false)) return true;
    }
  }
  return false;
}

// A result that overflows the double range must not be answered as a 200 with null in
// place of the number: either every number of the answer is finite, or the request gets
// a problem (422, like any other input whose answer cannot be computed).
void expect_no_overflowed_number(const std::string& path, const std::string& body) {
  const Reply reply = handle(path, body, Limits{});
  const json answer = json::parse(reply.body);
  if (reply.status == 200) {
    EXPECT_FALSE(has_null_in_array(answer)) << path << " " << body << "\n -> " << reply.body;
    for (const char* key : {"area", "signed_area"}) {
      if (answer.contains(key)) {
        EXPECT_TRUE(answer[key].is_number()) << path << " " << body << "\n -> " << reply.body;
      }
    }
  } else {
    EXPECT_EQ(reply.status, 422) << reply.body;
    EXPECT_EQ(reply.content_type, "application/problem+json");
  }
}

// F1, found by api_structured_fuzzer in its first minute (a /polar blossom of a degree-0
// polar curve at 1e190 with t0 = -20224): finite input, non-finite result. The exact
// results here are 2e308 (B(2) of the segment 0 -> 1e308), 2e308 (B' of -1e308 -> 1e308),
// 2e308 (the first polar at t0 = 2) and about 1e400 (the area of a loop 1e200 wide), all
// beyond the largest double (about 1.8e308).
TEST(FuzzRegressions, F1_OverflowingEvaluationIsNotWrittenAsNull) {
  expect_no_overflowed_number("/evaluate", R"({"points":[[0,0],[1e308,0]],"t":2})");
}

TEST(FuzzRegressions, F1_OverflowingDerivativeIsNotWrittenAsNull) {
  expect_no_overflowed_number("/evaluate",
                              R"({"points":[[-1e308,0],[1e308,0]],"t":0.5,"derivatives":1})");
}

TEST(FuzzRegressions, F1_OverflowingPolarIsNotWrittenAsNull) {
  expect_no_overflowed_number("/polar", R"({"points":[[0,0],[1e308,0]],"t0":2})");
}

TEST(FuzzRegressions, F1_OverflowingIntervalAreaIsNotWrittenAsNull) {
  expect_no_overflowed_number(
      "/loop-area", R"({"points":[[0,0],[1e200,1e200],[0,1e200],[1e200,0]],"interval":[0,1]})");
}

// F33, found by work_bound_fuzzer within seconds: a quadratic reaching 3e129 against a
// quartic reaching 1e237, by subdivision. The search spends its budget at the precision
// floor, where each coincidence test projected five points onto the other curve by up to 30
// Gauss-Newton steps and was charged as one step: the request took several times the CPU
// time its units stand for. The test is now charged by its evaluations. Through the API at
// the default limits, by every method: 200 or the work-cap 422, within a CPU time no bounded
// request comes near (a wide margin, not a timing).
TEST(FuzzRegressions, F33_CoincidenceTestsAreChargedByTheirEvaluations) {
  const std::string curves =
      R"("curves":[{"points":[[2.0,-2.0],[-1.0,0.0],[-3.2364e+129,-7.0]]},)"
      R"({"points":[[0.0,-0.5],[0.0,7.0],[0.0,1e+237],)"
      R"([9.999999999999996e+236,9.999999999999992e+236],[9.999999999999989e+236,8.0]]}])";
  for (const char* options : {R"("method":"hybrid")", R"("method":"hybrid","fat_curve_degree":2)",
                              R"("method":"bezier-clipping")", R"("method":"subdivision")"}) {
    const std::string body = "{" + curves + "," + options + "}";
    timespec start{}, end{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &start);
    const Reply reply = handle("/intersections", body, Limits{});
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &end);
    const double cpu = static_cast<double>(end.tv_sec - start.tv_sec) +
                       1e-9 * static_cast<double>(end.tv_nsec - start.tv_nsec);
    EXPECT_TRUE(reply.status == 200 || reply.status == 422) << options << ": " << reply.body;
    EXPECT_LT(cpu, 2.0) << options;
  }
}

// F34, found by work_bound_fuzzer: one curve of degree 12 whose last nine control points
// are the origin (its first four 1e-323, 6, 8 and 181.74 from it), by subdivision. Most boxes
// next to the diagonal start a Newton run, and the parameter boxes were charged too little
// for them: the self-intersection search took half again the time its units stand for. Now
// each Newton iteration is charged as a box and a box's cost covers the run's setup. Through
// the API at the default limits, one curve and /loop-area: 200 or the work-cap 422 within a
// CPU time no bounded request comes near.
TEST(FuzzRegressions, F34_NewtonRunsOfTheSelfIntersectionSearchAreCharged) {
  const std::string points =
      R"([[-1e-323,-5e-324],[-1e-323,6.0],[-8.0,-4.0],[-181.74,0.0],[0.0,0.0],[0.0,0.0],)"
      R"([0.0,0.0],[0.0,0.0],[0.0,0.0],[0.0,0.0],[0.0,0.0],[0.0,0.0],[0.0,0.0]])";
  const std::pair<const char*, std::string> requests[] = {
      {"/intersections", R"({"curves":[{"points":)" + points + R"(}],"method":"subdivision"})"},
      {"/loop-area", R"({"points":)" + points + "}"}};
  for (const auto& [path, body] : requests) {
    timespec start{}, end{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &start);
    const Reply reply = handle(path, body, Limits{});
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &end);
    const double cpu = static_cast<double>(end.tv_sec - start.tv_sec) +
                       1e-9 * static_cast<double>(end.tv_nsec - start.tv_nsec);
    EXPECT_TRUE(reply.status == 200 || reply.status == 422) << path << ": " << reply.body;
    EXPECT_LT(cpu, 2.0) << path;
  }
}

}  // namespace
}  // namespace bezier::api

namespace bezier::core {
namespace {

// Whether (t, s) lies in the box of a reported intersection or in a reported overlap.
using RationalPoint = std::array<bezier::test::Rational, 2>;

/// q(t) of a quadratic in exact rationals (t and the control points as the doubles they are).
RationalPoint exact_point(const Curve& q, double t) {
  using bezier::test::Rational;
  const Rational tr(t), one(1), two(2);
  const Rational b0 = (one - tr) * (one - tr), b1 = two * tr * (one - tr), b2 = tr * tr;
  return {b0 * Rational(q[0].x) + b1 * Rational(q[1].x) + b2 * Rational(q[2].x),
          b0 * Rational(q[0].y) + b1 * Rational(q[1].y) + b2 * Rational(q[2].y)};
}

/// The implicit equation of the parabola a quadratic q lies on, at x, in exact rationals:
/// A1^2 - 4 A0 A2 (Ai the signed area of the triangle x P_j P_k, {i, j, k} = {0, 1, 2}:
/// barycentric coordinates, and tau_1^2 = 4 tau_0 tau_2 on a quadratic). It changes sign
/// where a curve crosses the parabola.
bezier::test::Rational on_parabola(const Curve& q, const RationalPoint& x) {
  using bezier::test::Rational;
  const auto area = [](const RationalPoint& a, const RationalPoint& b, const RationalPoint& c) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
  };
  const RationalPoint p0{Rational(q[0].x), Rational(q[0].y)},
      p1{Rational(q[1].x), Rational(q[1].y)}, p2{Rational(q[2].x), Rational(q[2].y)};
  const Rational a0 = area(x, p1, p2), a1 = area(p0, x, p2), a2 = area(p0, p1, x);
  return a1 * a1 - Rational(4) * a0 * a2;
}

bool covered(const IntersectionResult& r, double t, double s) {
  for (const auto& x : r.intersections) {
    if (x.t_interval.contains(t) && x.s_interval.contains(s)) return true;
  }
  for (const auto& o : r.overlaps) {
    if (o.t_interval.contains(t) && o.s_interval.contains(s)) return true;
  }
  return false;
}

/// Calls check(r, options, swapped) with r the answer for f and g (swapped: for g and f),
/// for every method, both fat-curve degrees and both orders; options.tolerance as given.
template <class Check>
void for_every_option(const Curve& f, const Curve& g, double tolerance, Check check) {
  for (const IntersectMethod method :
       {IntersectMethod::hybrid, IntersectMethod::bezier_clipping, IntersectMethod::subdivision}) {
    for (const int fat_curve_degree : {2, 3}) {
      IntersectOptions options;
      options.method = method;
      options.fat_curve_degree = fat_curve_degree;
      options.tolerance = tolerance;
      for (const bool swapped : {false, true}) {
        SCOPED_TRACE("method " + std::to_string(static_cast<int>(method)) + " fat curve " +
                     std::to_string(fat_curve_degree) + " swapped " + std::to_string(swapped));
        check(swapped ? intersect(g, f, options) : intersect(f, g, options), options, swapped);
      }
    }
  }
}

/// Every method, in both orders, answers that f and g share no point: no intersection, no
/// overlap, and a complete search.
void expect_no_common_point(const Curve& f, const Curve& g) {
  for_every_option(f, g, IntersectOptions{}.tolerance,
                   [](const IntersectionResult& r, const IntersectOptions&, bool) {
                     ASSERT_EQ(r.status, IntersectStatus::ok);
                     EXPECT_TRUE(r.intersections.empty());
                     EXPECT_TRUE(r.overlaps.empty());
                   });
}

// The contract of Intersection (result.hpp): intervals narrower than the tolerance whenever
// `resolved`, the estimate inside them, the point finite.
void expect_intersection_contract(const IntersectionResult& r, double tolerance) {
  for (const auto& x : r.intersections) {
    EXPECT_TRUE(x.t_interval.contains(x.t) && x.s_interval.contains(x.s)) << x.t << " " << x.s;
    EXPECT_TRUE(std::isfinite(x.point.x) && std::isfinite(x.point.y)) << x.t << " " << x.s;
    if (x.resolved) {
      EXPECT_LT(x.t_interval.width(), tolerance)
          << "t in [" << x.t_interval.lo << ", " << x.t_interval.hi << "]";
      EXPECT_LT(x.s_interval.width(), tolerance)
          << "s in [" << x.s_interval.lo << ", " << x.s_interval.hi << "]";
    }
  }
}

// One intersection, no overlap, in both orders of f and g (Bézier clipping, tolerance 1e-9),
// estimated exactly at the end root f(t) = g(s); of the given kind when one is given.
void expect_one_exact_end_root(const Curve& f, const Curve& g, double t, double s,
                               std::optional<IntersectionKind> kind = std::nullopt) {
  IntersectOptions options;
  options.tolerance = 1e-9;
  options.method = IntersectMethod::bezier_clipping;
  for (const bool swapped : {false, true}) {
    SCOPED_TRACE(swapped ? "g, f" : "f, g");
    const IntersectionResult r = swapped ? intersect(g, f, options) : intersect(f, g, options);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.overlaps.empty());
    ASSERT_EQ(r.intersections.size(), 1u);
    EXPECT_TRUE(swapped ? covered(r, s, t) : covered(r, t, s));
    EXPECT_EQ(r.intersections[0].t, swapped ? s : t);
    EXPECT_EQ(r.intersections[0].s, swapped ? t : s);
    if (kind) {
      EXPECT_EQ(r.intersections[0].kind, *kind);
    }
    expect_intersection_contract(r, options.tolerance);
  }
}

// F2, found by intersect_fuzzer: a curve smaller than about 2^-44 of the other is handled
// as a point, its parameter interval is [0, 1] (or a half of it), and the intersection is
// still flagged `resolved`. Here f is the segment y = 2x of length ~2^-48 through the
// origin and g the segment y = x / 2 through it: one transversal crossing, at t = s = 1/2.
TEST(FuzzRegressions, F2_TinyCurveIsNotReportedResolvedWithItsWholeInterval) {
  const Curve f({{-0x1p-50, -0x1p-49}, {0.0, 0.0}, {0x1p-50, 0x1p-49}});
  const Curve g({{-1.0, -0.5}, {1.0, 0.5}});
  IntersectOptions options;
  options.tolerance = 1e-9;
  const IntersectionResult r = intersect(f, g, options);
  ASSERT_EQ(r.status, IntersectStatus::ok);
  ASSERT_EQ(r.intersections.size(), 1u);
  EXPECT_TRUE(covered(r, 0.5, 0.5));
  expect_intersection_contract(r, options.tolerance);
}

// F3, found by intersect_fuzzer (with assertions on, as the fuzz build has them): Bézier
// clipping with a degree-0 curve called fat_curve_operator(0, 0), whose assertion k >= 1
// aborts (release builds, these tests', skip the assertion; the fuzz build checks it). The
// point (0, 0) is the end f(1) of the segment f(t) = (1 - t, 0), so t = 1 exactly, and g's
// parameter is free: one contact, s in [0, 1].
TEST(FuzzRegressions, F3_BezierClippingAcceptsAPointCurve) {
  const Curve f({{1.0, 0.0}, {0.0, 0.0}});
  const Curve g(std::vector<Point2>{{0.0, 0.0}});
  IntersectOptions options;
  options.method = IntersectMethod::bezier_clipping;
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f, options) : intersect(f, g, options);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    ASSERT_EQ(r.intersections.size(), 1u);
    const Intersection& x = r.intersections[0];
    const ParamInterval on_f = swapped ? x.s_interval : x.t_interval;
    const ParamInterval on_g = swapped ? x.t_interval : x.s_interval;
    EXPECT_TRUE(on_f.contains(1.0));
    EXPECT_LT(on_f.width(), options.tolerance);
    EXPECT_EQ(on_g, (ParamInterval{0.0, 1.0}));
    EXPECT_EQ(x.kind, IntersectionKind::degenerate);
    EXPECT_FALSE(x.resolved);
    expect_intersection_contract(r, options.tolerance);
  }
}

// F4, found by intersect_fuzzer: f starts exactly where g ends; g is 2^-29 long and f 2^24, so g
// is within the working frame's line tolerance of f's line and of a point, and the pair goes the
// collinear way. g(s) = (0x1.d4p-30 (1 - s)^2, 0) meets the line x = 0 of f only at s = 1: the
// one intersection is f(0) = g(1) = (0, 0), equal bit for bit. g's positions along f's line were
// all 0, its derivative's roots a cut at s = 1/2, and the two halves gave two contacts that are
// not intersections ((0, 0) and (0, 1/2)) and not the root. Now: one contact, estimated at the
// exact root, in both orders.
TEST(FuzzRegressions, F4_EndPointRootOfATinyCurveIsReported) {
  const Curve f({{0.0, 0.0}, {0.0, -0x1p24}});
  const Curve g({{0x1.d4p-30, 0.0}, {0.0, 0.0}, {0.0, 0.0}});
  expect_one_exact_end_root(f, g, 0.0, 1.0);
}

// F4 again, found by intersect_fuzzer once F4's gate was gone: a single point exactly at an end
// of the other curve. Bézier clipping missed f(1) = (0, 0) of this cubic against the point (0, 0)
// altogether; a closed quadratic through the point (a degree-1 curve with equal points) came back
// with its root t = 0 only. End points equal bit for bit are exact roots, a point curve's
// parameter free: t = 1 (and t = 0 and 1), s in [0, 1].
TEST(FuzzRegressions, F4_PointAtAnEndIsAnExactRoot) {
  const Curve f({{0.0, -4.0}, {-8.0, -4.0}, {-0x1.0000000000001p+2, 0.0}, {0.0, 0.0}});
  const Curve g(std::vector<Point2>{{0.0, 0.0}});
  IntersectOptions options;
  options.method = IntersectMethod::bezier_clipping;
  const IntersectionResult r = intersect(f, g, options);
  ASSERT_EQ(r.status, IntersectStatus::ok);
  ASSERT_EQ(r.intersections.size(), 1u);
  EXPECT_EQ(r.intersections[0].t, 1.0);
  EXPECT_EQ(r.intersections[0].s_interval, (ParamInterval{0.0, 1.0}));
  const IntersectionResult w = intersect(g, f, options);
  ASSERT_EQ(w.intersections.size(), 1u);
  EXPECT_EQ(w.intersections[0].s, 1.0);
  EXPECT_EQ(w.intersections[0].t_interval, (ParamInterval{0.0, 1.0}));

  const Curve closed({{0.0, 0.0}, {1.0, 0x1.01p-29}, {0.0, 0.0}});
  const Curve point({{0.0, 0.0}, {0.0, 0.0}});
  const IntersectionResult c = intersect(closed, point);
  ASSERT_EQ(c.intersections.size(), 2u);
  EXPECT_TRUE(covered(c, 0.0, 0.5));
  EXPECT_TRUE(covered(c, 1.0, 0.5));
}

// F20 (part), found by intersect_fuzzer once F4's gate was gone: g(s) = 0x1.80200021p-2 (1 - s)^3
// is within the overlap tolerance of a point for s near 1, so "g on [0.99992, 1] = f at t = 0"
// passed the overlap verification in one order: an overlap of width 0 in t; nothing in the
// other. The only root is the exact end root f(0) = g(1).
TEST(FuzzRegressions, F20_FlatEndIsNoOverlapOfWidthZero) {
  const Curve f({{0.0, 0.0}, {-0x1.cp+2, 0x1p+2}, {-0x1p+2, 0x1p+3}, {-0x1p+26, 0x1p-29}});
  const Curve g({{0x1.80200021p-2, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}});
  IntersectOptions options;
  options.tolerance = 0x1.12e0be826d695p-30;
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f, options) : intersect(f, g, options);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.overlaps.empty());
    ASSERT_EQ(r.intersections.size(), 1u);
    EXPECT_TRUE(swapped ? covered(r, 1.0, 0.0) : covered(r, 0.0, 1.0));
  }
}

// F20 (c), found by intersect_fuzzer: f(t) = (4t - (4 + 2^19) t^2, -8 t^2) starts where the
// parabola g ends, f(0) = g(1) = (0, 0), and crosses g once more right next to it. With g
// first, hybrid clipping dropped that crossing: the piece of f on s in [0, 2^-17] is closed
// to within its rounding, so its fat line runs along its farthest control point instead of
// its chord, and the band for degree 2 assumed a line through both end points. The second
// crossing is proved here without the kernel: g lies on the parabola h(X) = A1^2 - 4 A0 A2 =
// 0 (Ai the signed area of the triangle X P_j P_k, {i, j, k} = {0, 1, 2}: barycentric
// coordinates, tau_1^2 = 4 tau_0 tau_2 on a quadratic), and h(f(t)) changes sign, in exact
// rationals, between t = 7.6e-6 and 2^-17, where f is within 1e-9 of g(1).
TEST(FuzzRegressions, F26_NearlyCollinearCurvesOfDifferentSizesCrossOnce) {
  // Two quadratics near the line x = 0: f within 2^-31 of it over its 4096 extent (1e-13 of
  // its size), g bent by 2^-30 over its extent of 8 (1e-10 of its own size). The line
  // through f's first control point made the collinear test pass in one order only (one
  // answered two overlaps along the line, the other a crossing); with the line through the
  // two control points farthest apart both orders answered the overlaps. But g is no
  // straight segment to within its own rounding, and two different quadratics share no
  // piece: with the collinear test relative to the smaller curve (as the overlap tests are)
  // both orders answer the one crossing. y_f falls monotonically from 0.031 to -4096, so f
  // has one t for each y, and g crosses the parabola f lies on (A1^2 - 4 A0 A2 = 0, exact)
  // between s = 0.32572355795 and 0.32572355796.
  const Curve f({{0x0p+0, 0x1.ff8ff2p-6}, {0x1.0000000000002p-31, -0x1p+3}, {0x0p+0, -0x1p+12}});
  const Curve g({{0x1p-31, -0x1p+0}, {0x0p+0, 0x1.fep-30}, {-0x1.fep-30, -0x1p+3}});
  const double s_lo = 0.32572355795, s_hi = 0.32572355796;
  ASSERT_LT(
      on_parabola(f, exact_point(g, s_lo)).sign() * on_parabola(f, exact_point(g, s_hi)).sign(), 0);
  // t with y_f(t) = y: the root in [0, 1] of a (1-t)^2 + 2b t(1-t) + c t^2 = y.
  const auto t_at = [&](double y) {
    const double a = f[0].y, b = f[1].y, c = f[2].y;
    const double qa = a - 2 * b + c, qb = 2 * (b - a), qc = a - y;
    return (-qb - std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
  };
  const double t_lo = t_at(evaluate(g, s_hi).y), t_hi = t_at(evaluate(g, s_lo).y);
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.overlaps.empty()) << "swapped " << swapped;
    ASSERT_EQ(r.intersections.size(), 1u) << "swapped " << swapped;
    const Intersection& x = r.intersections[0];
    const double t = swapped ? x.s : x.t, s = swapped ? x.t : x.s;
    EXPECT_TRUE(x.resolved);
    EXPECT_EQ(x.kind, IntersectionKind::transversal);
    EXPECT_LE(s_lo, s);
    EXPECT_LE(s, s_hi);
    EXPECT_NEAR(t, (t_lo + t_hi) / 2, 1e-9);
  }
}

TEST(FuzzRegressions, F26_ASmallCurveBentAboveItsRoundingIsNotOnALargeCurvesLine) {
  // f runs from (0, 0) out along the x axis past x = 2^28 and back to x = 2^-31 (y <= 2^-31);
  // g, about 2^-14 of its size, is the parabola from (0, 2^-13) out to x = -16381.5 and back to
  // (0, 0), tangent to the x axis there. Relative to f's size g lies on the x axis, and
  // both orders took the pair for collinear: a touch at f(0) and g's first end, 2^-13
  // apart, placed at (0, 2^-57) in one order and at (2^-70, 0) in the other. The curves
  // meet only at f(0) = g(1): x_f > 0 on (0, 1] (every control point's x >= 0, P1's > 0)
  // and x_g < 0 on (0, 1) (-2 (1 - s) s 32763 plus 0 at both ends), so a common point has
  // x = 0, t = 0 and s in {0, 1}, and g(0) = (0, 2^-13) is not f(0). Both tangents there
  // are horizontal to within 1e-13: a tangency.
  const Curve f({{0x0p+0, 0x0p+0},
                 {0x1.f404004cp+11, 0x1.000002b001204p-31},
                 {0x1.28p+29, 0x0p+0},
                 {0x1.72b0112011919p-31, 0x0p+0}});
  const Curve g({{0x0p+0, 0x1.000000c02808p-13}, {-0x1.ffecp+14, 0x0p+0}, {0x0p+0, 0x0p+0}});
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.overlaps.empty()) << "swapped " << swapped;
    ASSERT_EQ(r.intersections.size(), 1u) << "swapped " << swapped;
    EXPECT_TRUE(swapped ? covered(r, 1.0, 0.0) : covered(r, 0.0, 1.0));
    EXPECT_EQ(r.intersections[0].kind, IntersectionKind::tangent);
  }
}

TEST(FuzzRegressions, F26_ACurveTheSizeOfAnotherCurvesRoundingIsNoOverlap) {
  // g runs from (1, 0) to (0, 0) along the x axis as (1 - s)^4 (an improper curve: it
  // factors through (1 - s)^2); f starts at (0, 0) and reaches 2^27. Near its start f
  // stays within 2^-40 of the frame (f's size) of g for t up to 9e-5, but it leaves at
  // the angle of (-1, -1/2) to g's direction: no overlap. The overlap tolerance taken
  // relative to the frame alone let g, 2^-27 of it, pass in one order.
  const Curve f(
      {{0x0p+0, 0x0p+0}, {-0x1.ff006bfc6cp-1, -0x1.ff006bfc6cp-2}, {0x1p+27, 0x1.555555554554p+9}});
  const Curve g({{1.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}});
  const IntersectionResult a = intersect(f, g), b = intersect(g, f);
  EXPECT_TRUE(a.overlaps.empty());
  EXPECT_TRUE(b.overlaps.empty());
  EXPECT_EQ(a.status, b.status);
}

TEST(FuzzRegressions, F26_ACurveComingWithin2eMinus9OfAnotherDoesNotMeetIt) {
  // f = (2^-9 t (1 - t), 139264 (1 - t)^2) has x >= 0 on [0, 1], zero only at its ends
  // (0, 139264) and (0, 0). g lies on x = 0 with y = a (1 - s)^2 + c s^2, a = 0x1.fap-30,
  // c = 0x1.8ffep-14, never below a c / (a + c) > 0: it misses both of f's ends, so the
  // curves do not meet. With the frame's tolerance (f's size, 2^17) both orders answered
  // two overlaps.
  const Curve f({{0.0, 0x1.1p+17}, {0x1p-10, 0.0}, {0.0, 0.0}});
  const Curve g({{0.0, 0x1.fap-30}, {0.0, 0.0}, {0.0, 0x1.8ffep-14}});
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    EXPECT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.overlaps.empty()) << "swapped " << swapped;
    EXPECT_TRUE(r.intersections.empty()) << "swapped " << swapped;
  }
}

TEST(FuzzRegressions, F26_AnOverlapReachesTheEndPointTheCurvesShare) {
  // Two quartics with the same first four control points, the last one's y differing by
  // 2^-38 (1e-13 of their size): one overlap of the whole curves, to within the tolerance.
  // They start at (0, 0) bit for bit, so the answer must contain (0, 0); the overlap's end,
  // pinned by Newton's method, stopped at t = 3e-27 in one order and the exact end root
  // was dropped as lying on the overlap.
  std::vector<Point2> points = {{0x0p+0, 0x0p+0},
                                {0x0p+0, 0x1.801090201027fp-31},
                                {-0x1p+0, 0x1.801090201027fp-31},
                                {-0x1.cp+2, -0x1.f6p+7},
                                {-0x1.8p+2, 0x1.1010704010204p+4}};
  const Curve f(points);
  points[4].y = 0x1.1010704010606p+4;
  const Curve g(points);
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    ASSERT_EQ(r.overlaps.size(), 1u) << "swapped " << swapped;
    EXPECT_TRUE(r.intersections.empty()) << "swapped " << swapped;
    EXPECT_TRUE(covered(r, 0.0, 0.0)) << "swapped " << swapped;
  }
}

TEST(FuzzRegressions, F26_ATouchAtTwoEndsIsTheSameInBothOrders) {
  // f runs from (0, 0) to x = -2^26 within 2^-28 of the x axis; g is the segment from
  // (0, 0x1.f2p-22) to (1.31, 0), 2^-26 of f's size. Both lie on the x axis to within the
  // rounding of coordinates of 2^26 (64 n u of them is 1e-6), so the pair is taken as
  // collinear, and the ranges along the axis touch at x = 0, an end of both curves. Each
  // order kept its first curve's end exact and moved the other's parameter to the foot of
  // that point on it: (0, 2^-43) one way, (0, 0) the other.
  const Curve f({{0x0p+0, 0x0p+0}, {0x0p+0, 0x1.ef8p-28}, {-0x1p+26, 0x0p+0}});
  const Curve g({{0x0p+0, 0x1.f2p-22}, {0x1.4fb8000ff8p+0, 0x0p+0}});
  for (const IntersectMethod method :
       {IntersectMethod::hybrid, IntersectMethod::bezier_clipping, IntersectMethod::subdivision}) {
    IntersectOptions options;
    options.method = method;
    const IntersectionResult a = intersect(f, g, options), b = intersect(g, f, options);
    ASSERT_EQ(a.intersections.size(), b.intersections.size());
    EXPECT_TRUE(a.overlaps.empty() && b.overlaps.empty());
    for (std::size_t i = 0; i < a.intersections.size(); ++i) {
      const Intersection &x = a.intersections[i], &y = b.intersections[i];
      EXPECT_EQ(x.t_interval, y.s_interval);
      EXPECT_EQ(x.s_interval, y.t_interval);
      EXPECT_EQ(x.t, 0.0);
      EXPECT_EQ(x.s, 0.0);
    }
  }
}

TEST(FuzzRegressions, F27_ACurveEndingBesideAnotherDoesNotMeetItThere) {
  // f ends at (0, 0x1.4cp-30) coming straight down; g starts at (-0x1.009cfc7c7p-23, 0) and
  // crosses x = 0 at y of about -1.2e-7 (slope -1), 5e-15 of the curves' size 2^24 below
  // f's end: the curves' extensions meet a few ulps of t beyond f's end. The curves do not
  // meet with s < 1e-3: every control point of f has x <= 0 and y >= 0, and y_f = 0 only
  // at t = 0 (the origin). For s in [0, 1e-3], x_g <= 0 only up to s of about 1.7e-15 (g
  // starts 1.2e-7 left of the axis with x_g' about 7e7), and there y_g <= 0 (the term
  // 3 s (1 - s)^2 y_1 with y_1 = -0x1.6a0a00009cfc7p+24 dominates). So a common point
  // would have y = 0: f at the origin, g at its first point, which is not the origin. The
  // fast pieces' rounding (1e-15 of the working scale) hid that gap, and one order
  // reported a box at (1, 2^-49).
  const Curve f({{0x0p+0, 0x0p+0},
                 {-0x1p+24, 0x1p+24},
                 {-0x1.a7a7a7a8p-28, 0x1.307p+24},
                 {0x0p+0, 0x1.4cp-30}});
  const Curve g({{-0x1.009cfc7c7p-23, 0x0p+0},
                 {0x1.6a0a00009cfc7p+24, -0x1.6a0a00009cfc7p+24},
                 {0x1.fffffefep+10, 0x1.fffffefep+9},
                 {-0x1.fbd8p+13, 0x1.001206a8a802p+10}});
  for (const IntersectMethod method :
       {IntersectMethod::hybrid, IntersectMethod::bezier_clipping, IntersectMethod::subdivision}) {
    IntersectOptions options;
    options.method = method;
    options.tolerance = 0x1.0c6f7a0b5ed8dp-20;
    const IntersectionResult a = intersect(f, g, options), b = intersect(g, f, options);
    EXPECT_EQ(a.intersections.size(), b.intersections.size())
        << "method " << static_cast<int>(method);
    for (const Intersection& x : a.intersections) {
      EXPECT_FALSE(x.t > 1 - 1e-3 && x.s < 1e-3) << "method " << static_cast<int>(method);
    }
    for (const Intersection& x : b.intersections) {
      EXPECT_FALSE(x.s > 1 - 1e-3 && x.t < 1e-3) << "method " << static_cast<int>(method);
    }
  }
}

TEST(FuzzRegressions, F20c_CrossingNextToASharedEndPointIsFound) {
  const Curve f({{0.0, 0.0}, {2.0, 0.0}, {-0x1p19, -8.0}});
  const Curve g({{376.5, 0.043}, {0.043, -1.0}, {0.0, 0.0}});
  const auto h_of_f = [&](double t) { return on_parabola(g, exact_point(f, t)); };
  const double t_lo = 7.6e-6, t_hi = 0x1p-17;
  ASSERT_LT(h_of_f(t_lo).sign() * h_of_f(t_hi).sign(), 0);
  for (const IntersectMethod method :
       {IntersectMethod::hybrid, IntersectMethod::bezier_clipping, IntersectMethod::subdivision}) {
    IntersectOptions options;
    options.method = method;
    for (const bool swapped : {false, true}) {
      const IntersectionResult r = swapped ? intersect(g, f, options) : intersect(f, g, options);
      ASSERT_EQ(r.status, IntersectStatus::ok);
      ASSERT_EQ(r.intersections.size(), 2u)
          << "method " << static_cast<int>(method) << " swapped " << swapped;
      EXPECT_TRUE(swapped ? covered(r, 1.0, 0.0) : covered(r, 0.0, 1.0));
      bool crossing = false;
      for (const Intersection& x : r.intersections) {
        const double t = swapped ? x.s : x.t, s = swapped ? x.t : x.s;
        crossing = crossing || (t_lo <= t && t <= t_hi && 1 - 1e-9 < s && s < 1);
      }
      EXPECT_TRUE(crossing) << "method " << static_cast<int>(method) << " swapped " << swapped;
      expect_intersection_contract(r, options.tolerance);
    }
  }
}

TEST(FuzzRegressions, F28_AnOverlapWithinRoundingOfAPointHidesNoCrossing) {
  // f starts at the origin, g at (0, 2.08e-8): f's third control point (1.04e9, 30464) sets
  // the working scale, next to which both starts are within rounding of the origin, and both
  // orders report that as an overlap (f on [0, 9.5e-10] with g on [0, 5.4e-6]). f crosses g's
  // parabola between t_lo and t_hi (a sign change of its implicit equation at f's exact
  // points). There f's x is positive and below 32, and f's y below g's first point y0: on g,
  // x = 32 s^2 and y = y0 (1 - s)^2, so the crossing has 0 < s < 1 (about 0.0047). The
  // overlap's map, verified only on its tiny pieces, was taken to hold on the whole square
  // and hid that crossing in the order (g, f) (F28). Subdivision runs into the work cap in
  // both orders (in the order (f, g) it did before too): halving cannot separate the two
  // starts, within rounding of each other, outside the overlap's own box.
  using bezier::test::Rational;
  const Curve f({{0x0p+0, 0x0p+0}, {-0x1.fc03ff92e794p-1, 0x1.6540001p-26},
                 {0x1.f0000ed34f583p+29, 0x1.dcp+14}});
  const Curve g({{0x0p+0, 0x1.6540000fffffep-26}, {0x0p+0, 0x0p+0}, {0x1.ffffff8084p+4, 0x0p+0}});
  const double t_lo = 8.2e-7, t_hi = 8.25e-7;
  ASSERT_LT(on_parabola(g, exact_point(f, t_lo)).sign() * on_parabola(g, exact_point(f, t_hi)).sign(),
            0);
  for (const double t : {t_lo, t_hi}) {
    const RationalPoint p = exact_point(f, t);
    ASSERT_GT(p[0], Rational(0));
    ASSERT_LT(p[0], Rational(32));
    ASSERT_LT(p[1], Rational(g[0].y));
  }
  for_every_option(f, g, 0x1.19799812dea11p-40,
                   [&](const IntersectionResult& r, const IntersectOptions& options, bool swapped) {
                     // A capped search (subdivision) may say nothing; an answer must hold the
                     // crossing.
                     if (options.method == IntersectMethod::subdivision &&
                         r.status == IntersectStatus::work_cap_reached) {
                       return;
                     }
                     ASSERT_EQ(r.status, IntersectStatus::ok);
                     bool crossing = false;
                     for (const Intersection& x : r.intersections) {
                       const ParamInterval t = swapped ? x.s_interval : x.t_interval;
                       crossing = crossing || (t.lo <= t_hi && t_lo <= t.hi);
                     }
                     EXPECT_TRUE(crossing);
                     expect_intersection_contract(r, options.tolerance);
                   });
}

TEST(FuzzRegressions, F29_ATinyCurveFarFromTheOriginHasAFiniteFrame) {
  // Two vertical segments at x = -7, about 2^-1030 long near y = 2^-1007: the working frame's
  // grid (a sixteenth of the extent) is so fine that -7 / grid overflowed, the origin came
  // out infinite and the frame's exponent overflowed an int (UBSan; F29). They lie on one
  // line and overlap where their y ranges do: f from t = 0 to where it reaches g's end, g
  // from where it reaches f's start to s = 1 (the fractions computed here in rationals).
  using bezier::test::Rational;
  const double y1 = 0x1.9010901270001p-1007, y2 = 0x1.9010c01012701p-1007;
  const double y3 = 0x1.901090126fffep-1007, y4 = 0x1.9010c0101004p-1007;
  const Curve f({{-7.0, y1}, {-7.0, y2}});
  const Curve g({{-7.0, y3}, {-7.0, y4}});
  const double t_hi = ((Rational(y4) - Rational(y1)) / (Rational(y2) - Rational(y1))).to_double();
  const double s_lo = ((Rational(y1) - Rational(y3)) / (Rational(y4) - Rational(y3))).to_double();
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.intersections.empty());
    ASSERT_EQ(r.overlaps.size(), 1u);
    const ParamInterval t = swapped ? r.overlaps[0].s_interval : r.overlaps[0].t_interval;
    const ParamInterval s = swapped ? r.overlaps[0].t_interval : r.overlaps[0].s_interval;
    EXPECT_EQ(t.lo, 0.0);
    EXPECT_NEAR(t.hi, t_hi, 1e-15);
    EXPECT_NEAR(s.lo, s_lo, 1e-15);
    EXPECT_EQ(s.hi, 1.0);
  }
}

TEST(FuzzRegressions, F30_ACurveBesideALineSegmentDoesNotOverlapIt) {
  // f(t) = (2 c t (1 - t), 32768 t^2) with c = 0x1.90005010a01p-31 leaves the y axis for
  // every t in (0, 1); g, a quartic on the y axis (x = 0), has y(s) = a (1 - s)^4 + b s^4
  // with a = 0x1.6cp-23 and b = 0x1.858585858p-2, so 0 < y(s) <= b. A common point needs x = 0
  // on f: t = 0 or 1, the points (0, 0) and (0, 32768), and neither is on g. So there is no
  // intersection and no overlap, in either order. (intersect_fuzzer: g, read as a quadratic
  // through a quadratic to within the frame's tolerance, gave an overlap in one order, its
  // points all within 5e-12 of f but f's piece starting at (0, 0), 8e-8 below g.)
  const Curve f({{0.0, 0.0}, {0x1.90005010a01p-31, 0.0}, {0.0, 0x1p+15}});
  const Curve g({{0.0, 0x1.6cp-23}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0x1.858585858p-2}});
  expect_no_common_point(f, g);
}

TEST(FuzzRegressions, F31_TwoEndsWithinRoundingOfEachOtherAreNoOverlap) {
  // f, 5e7 tall, ends at (a, a), a = 0x1.d9d9d9d9d9dap-3; g, 0.03 long, ends 3e-9 from there.
  // Next to f's scale both end pieces are within rounding of a point, and the order (f, g)
  // reported them as an overlap, the order (g, f) not (F31). Two parabolas share at most four
  // points unless they are the same conic, and g's ends are off f's (the sign of f's implicit
  // equation, in rationals): there is no overlap. Both orders must say so and report the
  // same crossings, mirrored.
  using bezier::test::Rational;
  const double a = 0x1.d9d9d9d9d9dap-3;
  const Curve f({{0.0, -0x1.8p+25}, {0.0, 0x1.d9d5f639d9dap-3}, {a, a}});
  const Curve g({{0x1.d9d9d9d999dap-3, 0x1.99d9d9d9d9dap-3},
                 {0x1.d9d9d9d9d9dap-3, 0x1.d9d9d9d9d606p-3},
                 {0x1.d9d9d14p-3, 0x1.d9d9d0104011p-3}});
  ASSERT_NE(on_parabola(f, exact_point(g, 0.0)).sign(), 0);
  ASSERT_NE(on_parabola(f, exact_point(g, 1.0)).sign(), 0);
  for (const IntersectMethod method : {IntersectMethod::hybrid, IntersectMethod::bezier_clipping}) {
    IntersectOptions options;
    options.method = method;
    options.fat_curve_degree = 2;
    const IntersectionResult r = intersect(f, g, options), w = intersect(g, f, options);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    ASSERT_EQ(w.status, IntersectStatus::ok);
    EXPECT_TRUE(r.overlaps.empty());
    EXPECT_TRUE(w.overlaps.empty());
    ASSERT_EQ(r.intersections.size(), w.intersections.size());
    for (const Intersection& x : r.intersections) {
      bool mirrored = false;
      for (const Intersection& y : w.intersections) {
        mirrored =
            mirrored || (x.t_interval.lo <= y.s_interval.hi && y.s_interval.lo <= x.t_interval.hi &&
                         x.s_interval.lo <= y.t_interval.hi && y.t_interval.lo <= x.s_interval.hi);
      }
      EXPECT_TRUE(mirrored) << "method " << static_cast<int>(method) << " t " << x.t;
    }
    expect_intersection_contract(r, options.tolerance);
    expect_intersection_contract(w, options.tolerance);
  }
}

TEST(FuzzRegressions, F32_AnOverlapEndsWhereBothCurvesAre) {
  // f = (0, 0), (c, h), (X, 0) with c = 0x1.9p-31, h = 0x1.018p-12, X = 0x1.fp+29 has
  // y(t) = 2 h t (1 - t) > 0 inside (0, 1); g, a quartic on the x axis, has x(s) =
  // A (1 - s)^4 + s^4 with A = 0x1.2p+27, so 0 < x(s) <= A < X. A common point needs y = 0
  // on f, t = 0 or 1, and f(0) = (0, 0) has x below g's, f(1) = (X, 0) beyond them: none.
  // f lies within 1.2e-4 of g's line along its 1.5e8 (8e-13 of g's length), and the
  // common-arc search reported an overlap whose end paired f's start (0, 0) with g's point
  // nearest to it, 0.99 away (F32). Every overlap's ends must be points of both curves;
  // here there are none.
  const Curve f({{0.0, 0.0}, {0x1.9p-31, 0x1.018p-12}, {0x1.fp+29, 0.0}});
  const Curve g({{0x1.2p+27, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}});
  expect_no_common_point(f, g);
}

// F21, found by classify_fuzzer: a loop whose double point sits within two ulps of t = 1
// on a cubic with coordinates 2^250 apart. The exact signs say 0 < t1 < t2 < 1; t1 rounded to
// 1 and t2 was clamped below 1, so the pair came out reversed (t1 = 1 > t2). The type is the
// exact rational oracle's; the pair must keep its order and stay strictly inside (0, 1).
TEST(FuzzRegressions, F21_LoopNextToAnEndKeepsItsParametersOrdered) {
  const std::array<Point2, 4> p{
      Point2{-0x1.f2fc8ffffff65p+260, -0x1.62fc8fffffff1p+261}, Point2{0x1.62fc8fffffff1p+261, 0.0},
      Point2{-0x1.1548p+11, -0x1.1548p+10}, Point2{0x1.1548p+10, -0x1.1548p+10}};
  const CubicClassification c = classify(p);
  ASSERT_TRUE(c.exact);
  EXPECT_EQ(c.type, bezier::test::exact_type(p));
  ASSERT_EQ(c.type, CubicType::loop);
  ASSERT_TRUE(c.self_intersection.has_value());
  const CubicDoublePoint& d = *c.self_intersection;
  EXPECT_TRUE(d.on_segment);
  EXPECT_LT(0.0, d.t1);
  EXPECT_LT(d.t1, d.t2);
  EXPECT_LT(d.t2, 1.0);
}

// F22, found by classify_fuzzer (assertions on): finite coordinates more than the largest
// double apart. The differences P_i - P_0 overflow to infinity and the filter's finiteness
// assertion, written on their sum (inf - inf = NaN), aborted; release builds took the exact
// path, which rescales. The type must be the exact oracle's (the assertion itself is checked
// by the fuzz build only: this build has none).
TEST(FuzzRegressions, F22_CoordinatesFartherApartThanTheLargestDoubleAreClassified) {
  const std::array<std::array<Point2, 4>, 4> cubics{{
      {Point2{1.5e308, -1.5e308}, Point2{-1.5e308, 1.5e308}, Point2{-1e308, -1e308},
       Point2{1e308, 1e308}},  // differences -inf and +inf: their sum was NaN
      {Point2{-1.5e308, 0.0}, Point2{1.5e308, 1e300}, Point2{0.0, 1e308}, Point2{1e300, -1e308}},
      {Point2{-1.7e308, -1.7e308}, Point2{1.7e308, 1.7e308}, Point2{1.7e308, -1.7e308},
       Point2{-1.7e308, 1.7e308}},
      {Point2{1e308, 0.0}, Point2{-1e308, 1e308}, Point2{-1e308, -1e308}, Point2{1e308, 1e299}},
  }};
  for (const auto& p : cubics) {
    const CubicClassification c = classify(p);
    EXPECT_TRUE(c.exact);
    EXPECT_EQ(c.type, bezier::test::exact_type(p));
  }
}

// F23, found by classify_fuzzer: a loop on a cubic with coordinates near the largest double.
// The double point, the mean of B(t1) and B(t2), was computed as half their sum, which
// overflowed to -inf. Both points lie in the control points' convex hull, so their mean does:
// it must be finite and inside the control points' bounding box.
TEST(FuzzRegressions, F23_DoublePointNearTheLargestDoubleIsFinite) {
  const std::array<Point2, 4> p{Point2{0.0, -0x1.7000001f00108p+1023},
                                Point2{-0x1.7000001f0efefp+1023, 0x1.7000001f0efefp+1023},
                                Point2{-0x1.7000001f0efefp+1023, -0x1.fffffffcp-50},
                                Point2{0.0, 0.0}};
  const CubicClassification c = classify(p);
  ASSERT_TRUE(c.self_intersection.has_value());
  const Point2 d = c.self_intersection->point;
  double x_lo = p[0].x, x_hi = p[0].x, y_lo = p[0].y, y_hi = p[0].y;
  for (const Point2& q : p) {
    x_lo = std::min(x_lo, q.x);
    x_hi = std::max(x_hi, q.x);
    y_lo = std::min(y_lo, q.y);
    y_hi = std::max(y_hi, q.y);
  }
  EXPECT_TRUE(std::isfinite(d.x) && std::isfinite(d.y));
  EXPECT_TRUE(x_lo <= d.x && d.x <= x_hi && y_lo <= d.y && d.y <= y_hi);
}

// F5, found by intersect_fuzzer: subnormal coordinates. Two segments 1e-310 long meeting
// at the origin, f(1) = g(0) = (0, 0): the kernel answered (1, 1) with a NaN point (the
// working frame's power-of-two scale overflowed). Fixed meanwhile by 1107d08 (scale
// clamped to normal doubles); kept as a regression test.
TEST(FuzzRegressions, F5_SubnormalCoordinatesGiveFinitePointsAndTheRightRoot) {
  const Curve f({{1e-310, 0.0}, {0.0, 0.0}});
  const Curve g({{0.0, 0.0}, {0.0, 1e-310}});
  const IntersectionResult r = intersect(f, g);
  ASSERT_EQ(r.status, IntersectStatus::ok);
  EXPECT_TRUE(covered(r, 1.0, 0.0));
  expect_intersection_contract(r, IntersectOptions{}.tolerance);
}

// F5b (F5 again after 1107d08), found by intersect_fuzzer: coordinates a few subnormal steps
// from zero. A point (a degree-1 curve with equal points) at the origin and the segment
// g(s) = (-4 (1 - s) 2^-1074, 0) ending there: the working frame's grid (a sixteenth of the
// extent) underflowed to 0 and its origin became NaN, so the search spent the whole work
// budget and reported NaN points. The answer: s = 1 exactly, t free, the point the origin.
TEST(FuzzRegressions, F5b_SegmentFourSubnormalStepsLong) {
  const Curve f({{0.0, 0.0}, {0.0, 0.0}});
  const Curve g({{-0x0.0000000000004p-1022, 0.0}, {0.0, 0.0}});
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    ASSERT_EQ(r.intersections.size(), 1u);
    EXPECT_TRUE(swapped ? covered(r, 1.0, 0.5) : covered(r, 0.5, 1.0));
    const Intersection& x = r.intersections[0];
    EXPECT_LT((swapped ? x.t_interval : x.s_interval).width(), IntersectOptions{}.tolerance);
    EXPECT_EQ(swapped ? x.s_interval : x.t_interval, (ParamInterval{0.0, 1.0}));
    // Within a subnormal step of the origin (the mean of f(t) and g(s), rounded).
    EXPECT_LE(std::fabs(x.point.x), 0x1p-1074);
    EXPECT_EQ(x.point.y, 0.0);
    expect_intersection_contract(r, IntersectOptions{}.tolerance);
  }
}

// F5 through the API: a NaN point would be written as null (or, since F1's fix, turn a
// valid request into a 422); the answer is the intersection at the origin.
TEST(FuzzRegressions, F5_SubnormalSegmentsThroughTheApi) {
  const api::Reply reply = api::handle(
      "/intersections",
      R"({"curves":[{"points":[[1e-310,0],[0,0]]},{"points":[[0,0],[0,1e-310]]}]})", api::Limits{});
  ASSERT_EQ(reply.status, 200) << reply.body;
  const auto answer = nlohmann::json::parse(reply.body);
  ASSERT_EQ(answer["intersections"].size(), 1u) << reply.body;
  EXPECT_EQ(answer["intersections"][0]["point"], nlohmann::json::parse("[0.0, 0.0]")) << reply.body;
}

// F6, found by self_intersection_fuzzer: the cubic closed form's Newton polish walks away
// from an ill-conditioned double point (a nearly collinear cubic) and still counts as
// converged. In closed form (cubic_double_point.hpp's derivation): with a = P1 − P0,
// b = P2 − 2P1 + P0, c = P3 − 3P2 + 3P1 − P0, t + s = −(a × c)/(b × c) = 6/5 and
// t s = 6/25 whatever the 2^-50 offset, so t, s = 3/5 ∓ √3/5, and the point is
// (−19/125, 19/125) up to the offset.
TEST(FuzzRegressions, F6_ClosedFormDoublePointIsNotPolishedAway) {
  const Curve c({{1.0, -1.0}, {-1.0, 1.0}, {-1.0, 1.0 - 0x1p-50}, {0.0, 0.0}});
  const SelfIntersectionResult r = self_intersections(c);
  ASSERT_EQ(r.pairs.size(), 1u);
  EXPECT_NEAR(r.pairs[0].t, 0.6 - std::sqrt(3.0) / 5, 1e-9);
  EXPECT_NEAR(r.pairs[0].s, 0.6 + std::sqrt(3.0) / 5, 1e-9);
  EXPECT_NEAR(r.pairs[0].point.x, -19.0 / 125, 1e-9);
  EXPECT_NEAR(r.pairs[0].point.y, 19.0 / 125, 1e-9);
}

// F6 again, next to a cusp: the cusp cubic (0,0), (1,1), (0,1), (1,0) with P3 moved 3 ulps
// to the left has a loop of parameter width about 1.6e-8 (the perturbation's square root,
// 2 sqrt(3 * 2^-53 / ...)); the polish moved it to 0.433 .. 0.567, where B(t) and B(s) are
// 2.4e-3 apart. The pair must be a double point, and narrow.
TEST(FuzzRegressions, F6_DoublePointNextToACuspIsNotPolishedAway) {
  const Curve c({{0.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}, {0x1.ffffffffffffdp-1, 0.0}});
  const SelfIntersectionResult r = self_intersections(c);
  for (const auto& p : r.pairs) {
    const Point2 a = evaluate(c, p.t), b = evaluate(c, p.s);
    EXPECT_LT(std::fmax(std::fabs(a.x - b.x), std::fabs(a.y - b.y)), 1e-12) << p.t << " " << p.s;
    EXPECT_LT(p.s - p.t, 1e-6) << p.t << " " << p.s;
  }
}

// F12, found by self_intersection_fuzzer comparing the methods after 86fab32: the general method
// (subdivision) missed the loop of this cubic and reported status ok. The loop is certain: the
// closed form decides it exactly (cubic_double_point.hpp), at t about 0.04 and s about 0.998,
// where the branches cross at an angle of 9e-8. (The search's Newton stopped at its plain
// rounding floor, 2e-14 off the root along the branches, where |B(t) - B(s)| exceeded the
// distance tolerance.) Both methods give the closed form's pair, to the parameters' accuracy.
TEST(FuzzRegressions, F12_GeneralMethodFindsTheLoopTheClosedFormFinds) {
  const std::array<Point2, 4> p = {Point2{1.0, 0.5}, Point2{-8.0, -4.0},
                                   Point2{0x1.12d00000080afp+29, 0x1.785p+13}, Point2{0.0, 0.0}};
  const auto dp = cubic_double_point(std::span<const Point2, 4>(p));
  ASSERT_TRUE(dp.has_value() && dp->on_segment);
  SelfIntersectionOptions general;
  general.cubic_closed_form = false;
  for (const auto& options : {general, SelfIntersectionOptions{}}) {
    const SelfIntersectionResult r =
        self_intersections(Curve(std::vector<Point2>(p.begin(), p.end())), options);
    ASSERT_EQ(r.status, SelfIntersectionStatus::ok);
    ASSERT_EQ(r.pairs.size(), 1u);
    EXPECT_NEAR(r.pairs[0].t, dp->t1, 1e-13);
    EXPECT_NEAR(r.pairs[0].s, dp->t2, 1e-13);
  }
}

// F13, found by intersect_fuzzer (UBSan): coordinates next to the largest double. The working
// frame's origin, rounded to its grid, was beyond the largest double, so the offsets were infinite
// and `std::ilogb(m) + 1` overflowed an int (undefined behaviour; in release the search spent the
// whole work budget). The answer: f(t) = (1.79e308 t, -1.79e308) ends where g (a point) is, t = 1,
// s free.
TEST(FuzzRegressions, F13_CoordinatesNextToTheLargestDouble) {
  const Curve f({{0.0, -1.79e308}, {1.79e308, -1.79e308}});
  const Curve g({{1.79e308, -1.79e308}, {1.79e308, -1.79e308}});
  const IntersectionResult r = intersect(f, g);
  ASSERT_EQ(r.status, IntersectStatus::ok);
  ASSERT_EQ(r.intersections.size(), 1u);
  EXPECT_TRUE(covered(r, 1.0, 0.5));
  const Intersection& x = r.intersections[0];
  EXPECT_LT(x.t_interval.width(), IntersectOptions{}.tolerance);
  EXPECT_EQ(x.s_interval, (ParamInterval{0.0, 1.0}));
  EXPECT_NEAR(x.point.x, 1.79e308, 1.79e308 * 1e-15);
  EXPECT_EQ(x.point.y, -1.79e308);
  expect_intersection_contract(r, IntersectOptions{}.tolerance);
}

// F15, found by self_intersection_fuzzer: coordinates spanning more than 2^400: the cubic's
// closed form is not exact (CubicPredicates::exact false), and the pair it gave was no double
// point: (0, 1) on an open curve, |B(0) − B(1)| = 0.027 on a curve of size 8. The exact double
// point (rational elimination of s + t and s t, done off-line) is at t = 1.3e-6, s = 1.0011: off
// the segment, so there is no pair (the general method finds the curve collinear to within its
// tolerance).
TEST(FuzzRegressions, F15_InexactClosedFormGivesDoublePoints) {
  const Curve c({{0x1.c18000418p-6, 0x0.00000838p-1022},
                 {-4.0, 0x1.383832e61e7afp-935},
                 {-8.0, 0x1.fp-1016},
                 {0x0.6p-1022, 0.0}});
  const SelfIntersectionResult r = self_intersections(c);
  EXPECT_TRUE(r.pairs.empty());
  for (const auto& p : r.pairs) {
    const Point2 a = evaluate(c, p.t), b = evaluate(c, p.s);
    EXPECT_LT(std::fmax(std::fabs(a.x - b.x), std::fabs(a.y - b.y)), 1e-12 * scale(c))
        << p.t << " " << p.s;
  }
}

// F16, found by self_intersection_fuzzer: pairs outside the unit square, and the trivial pair of
// a closed curve leaking out (the polish after the end snapping moved parameters past the ends;
// next to a flat seam Newton and the contact stage settled on pairs the search could not tell
// from (0, 1)). Every pair must have 0 <= t < s <= 1 and never be (0, 1).
void expect_pairs_in_the_unit_square(const SelfIntersectionResult& r) {
  for (const auto& p : r.pairs) {
    EXPECT_TRUE(0.0 <= p.t && p.t < p.s && p.s <= 1.0) << p.t << " " << p.s;
    EXPECT_FALSE(p.t == 0.0 && p.s == 1.0);
  }
}

// (a) A cubic that almost closes (P3 a few ulps from P0) gave (-7.9e-16, 1 + 1.6e-13). Its double
// point, decided exactly by the closed form, lies just off the segment: no pair, by either method.
TEST(FuzzRegressions, F16_LoopClosingJustOffTheSegmentIsNoPair) {
  const std::array<Point2, 4> p = {Point2{0x1.020202020202p-21, 0x1.020202020202p-21},
                                   Point2{0x1.0e1df20202006p-21, 0.0},
                                   Point2{0x1.020202020202p-21, 0x1.003ec54545454p-21},
                                   Point2{0x1.020202020201fp-21, 0x1.020202020201cp-21}};
  const auto dp = cubic_double_point(std::span<const Point2, 4>(p));
  ASSERT_TRUE(dp.has_value());
  ASSERT_TRUE(cubic_predicates(std::span<const Point2, 4>(p)).exact);
  EXPECT_FALSE(dp->on_segment);
  SelfIntersectionOptions general;
  general.cubic_closed_form = false;
  for (const auto& options : {general, SelfIntersectionOptions{}}) {
    const SelfIntersectionResult r =
        self_intersections(Curve(std::vector<Point2>(p.begin(), p.end())), options);
    expect_pairs_in_the_unit_square(r);
    EXPECT_TRUE(r.pairs.empty()) << r.pairs.size();
  }
}

// (b) A closed quintic (P0 = P5 = (0, 0)) gave (-9e-25, 1), the trivial pair with t below 0. It
// has one real self-intersection (resultant of the two coordinates' divided differences, exact
// rationals, off-line; then Newton in 60 digits): a tiny loop next to the seam at t = 1.2e-13,
// s = 1 - 5.3e-9, 3e-8 across on a curve of scale 7e7, far below the distance tolerance (2^-44
// of the scale), so by the documented resolution part of the trivial pair. A pair reported must
// be that one.
TEST(FuzzRegressions, F16_TrivialPairOfAClosedCurveStaysOut) {
  const Curve c({{0.0, 0.0},
                 {-0x1.fp+14, 0x1.fp+14},
                 {-0x1p+26, 0x1.e48d4484a48p+6},
                 {0x1.4000024243224p-9, 0x1p+26},
                 {-0x1.6f6f6f6facp-1, 0x1.ef3p-23},
                 {0.0, 0.0}});
  const SelfIntersectionResult r = self_intersections(c);
  expect_pairs_in_the_unit_square(r);
  for (const auto& p : r.pairs) {
    EXPECT_NEAR(p.t, 1.20878799514914e-13, 1e-20);
    EXPECT_NEAR(p.s, 0.99999999465311446884, 1e-16);
  }
}

// (c) A closed degree-20 curve whose last 13 points are the origin gave (0, 0.9978): the trivial
// pair moved along the flat end (B(s) is 2e-32 there), and its s moved by 4e-6 when the curve was
// scaled by 2^6. The curve has no self-intersection (B = t (1 - t)^13 Q(t); off-line, in 60-digit
// arithmetic, its log-polar image sampled densely towards both ends does not cross itself), at
// any scale.
TEST(FuzzRegressions, F16_FlatSeamGivesNoPair) {
  std::vector<Point2> flat_end = {{0.0, 0.0},
                                  {0x1.d93f794p+10, 0.0},
                                  {0.0, 0.0},
                                  {0x1p+20, 0.0},
                                  {0.0, 0.0},
                                  {0x1.bca0b868p-19, -0x1.e291f459f9e29p-11},
                                  {-0x1.e291f459f9e29p-12, 0x1.01a9f4561e0f6p+3},
                                  {0x1.1ap-30, 0.0}};
  flat_end.resize(21, Point2{0.0, 0.0});
  for (const int k : {0, 6}) {
    std::vector<Point2> scaled;
    for (const Point2 p : flat_end) scaled.push_back({std::ldexp(p.x, k), std::ldexp(p.y, k)});
    const SelfIntersectionResult r = self_intersections(Curve(scaled));
    EXPECT_EQ(r.status, SelfIntersectionStatus::ok);
    EXPECT_TRUE(r.pairs.empty()) << k << ": " << r.pairs.size();
  }
}

// F18, found by self_intersection_fuzzer: a degree-20 curve's double point at t = 0.000195
// reported twice, out of order, the copies 1.4e-9 apart in s (above the 1e-10 merge distance),
// the second 1.8e-9 off the curve's other branch. The curve has two double points (off-line, in
// 60-digit arithmetic: a dense polyline's crossings, then Newton), each to be reported once,
// sorted, to the accuracy of the parameters.
TEST(FuzzRegressions, F18_DoublePointReportedOnce) {
  const Curve c({{1.0, 1.0},
                 {-0x1.fffffep+7, -0x1.fffffep+7},
                 {-0x1.fffffep+6, 0x1.fffffep+6},
                 {-0x1.fffffe0000002p+7, -0x1.fffffe0000002p+7},
                 {-0x1.fffffe0000001p+7, -0x1.fffffe0000001p+6},
                 {1.0, -0x1p+29},
                 {-0x1.cp+2, 2.0},
                 {0x1.ffffffffffffep+0, -0x1.cp+2},
                 {2.0, 0x1.0000000000004p+0},
                 {0x1.ddd8p+5, -0x1.44291044p+16},
                 {-0x1.fffffe0000002p+7, 0x1.fffffe0000002p+7},
                 {-0x1.44437a04p-12, -0x1.fffffe0000002p+7},
                 {0x1.dddddf7f79778p-2, 0x1.dddddf7f79778p-3},
                 {0.0, 0x1.872bb1f1ap+21},
                 {0x1.03b0010c40009p-31, -0x1.82787c0000185p-1},
                 {0x1.1ap-30, 0.0},
                 {0.0, 0.0},
                 {0.0, 0.0},
                 {0.0, 0.0},
                 {0.0, 0.0},
                 {0.0, 0.0}});
  const SelfIntersectionResult r = self_intersections(c);
  ASSERT_EQ(r.status, SelfIntersectionStatus::ok);
  ASSERT_EQ(r.pairs.size(), 2u);
  EXPECT_NEAR(r.pairs[0].t, 0.000195093157093225009292, 1e-15);
  EXPECT_NEAR(r.pairs[0].s, 0.990241764320379987666646, 1e-13);
  EXPECT_NEAR(r.pairs[1].t, 0.005234862227017755711484, 1e-15);
  EXPECT_NEAR(r.pairs[1].s, 0.608300438515885438595626, 1e-13);
}

// F19, found by intersect_fuzzer (swap symmetry): g starts on the segment f, at
// x = 0x1.3p-23, and leaves it at an angle of 2^-22 (g's slope 2^-19 / (8 + 0x1.3p-23)). In
// the order (f, g) the answer was an overlap t in [0, 2.2e-9], s in [0, 1.8e-8]; in the order
// (g, f) the single crossing. Two distinct lines cross once: at f(t) = g(0), t = 0x1.3p-29
// exactly, transversally (the overlap test's tolerance on the lines' directions was 2^-20).
TEST(FuzzRegressions, F19_SwappingTheCurvesGivesTheSameKindOfAnswer) {
  const Curve f({{0.0, 0.0}, {64.0, 0.0}});
  const Curve g({{0x1.3p-23, 0.0}, {-8.0, 0x1p-19}});
  IntersectOptions options;
  options.tolerance = 0x1.0624dd2f1a9fcp-10;
  options.method = IntersectMethod::bezier_clipping;
  options.fat_curve_degree = 3;
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f, options) : intersect(f, g, options);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.overlaps.empty());
    ASSERT_EQ(r.intersections.size(), 1u);
    EXPECT_TRUE(swapped ? covered(r, 0.0, 0x1.3p-29) : covered(r, 0x1.3p-29, 0.0));
    EXPECT_EQ(r.intersections[0].kind, IntersectionKind::transversal);
    EXPECT_TRUE(r.intersections[0].resolved);
    expect_intersection_contract(r, options.tolerance);
  }
}

// The largest |B(t) − B(s)| over the pairs, relative to the curve's scale.
double worst_relative_gap(const Curve& c, const SelfIntersectionResult& r) {
  double worst = 0.0;
  for (const auto& p : r.pairs) {
    const Point2 a = evaluate(c, p.t), b = evaluate(c, p.s);
    worst = std::fmax(worst, std::fmax(std::fabs(a.x - b.x), std::fabs(a.y - b.y)) / scale(c));
  }
  return worst;
}

// F8, found by self_intersection_fuzzer: next to an end where B' vanishes (here P3 = P4 =
// P5, so B(s) − B(1) = O((1 − s)^3)) the general method accepts a pair far from any double
// point: |B(t) − B(s)| = 0.74 on a curve of scale 2208 (reported as transversal).
TEST(FuzzRegressions, F8_PairsNextToAFlatEndAreDoublePoints) {
  const Curve c({{0.0, 0x1.2afp-25},
                 {0x1.2afp-25, -0x1.14p+11},
                 {0x1.2affb3030fbp+7, 0x1.1p-31},
                 {0.0, 0.0},
                 {0.0, 0.0},
                 {0.0, 0.0}});
  const SelfIntersectionResult r = self_intersections(c);
  ASSERT_EQ(r.status, SelfIntersectionStatus::ok);
  EXPECT_LT(worst_relative_gap(c, r), 1e-9);
}

// F9, found by self_intersection_fuzzer: with coordinates spanning more than 2^400 the
// classification is not exact, and the cubic with P2 = P3 (B'(1) = 0: a cusp at t = 1 by
// DESIGN §1, whatever the other points) came out as loop-at-end with t1 = t2 = 1, which
// self_intersections() passed on as the pair (1, 1).
TEST(FuzzRegressions, F9_CuspAtTheEndIsNotALoopOfWidthZero) {
  const std::array<Point2, 4> p = {Point2{-8.0, 0x1.0000000d6fbfcp-895},
                                   Point2{0x1.0000000d6fbfcp-896, 0x1.0000000d6fbf8p-895},
                                   Point2{0.0, 0.0}, Point2{0.0, 0.0}};
  const CubicClassification k = classify(std::span<const Point2, 4>(p));
  EXPECT_EQ(k.type, CubicType::cusp);
  if (k.self_intersection) {
    EXPECT_LT(k.self_intersection->t1, k.self_intersection->t2);
  }
  const SelfIntersectionResult r =
      self_intersections(Curve(std::vector<Point2>(p.begin(), p.end())));
  for (const auto& pair : r.pairs) {
    EXPECT_LT(pair.t, pair.s);
  }
}

// F10, found by intersect_fuzzer: two curves on the line y = −x, f from (1, −1) to
// (−1/2, 1/2) with P1 = P2 = P3 (f'(1) = 0) and g from (−1/2, 1/2) to (0, 0). g lies on f:
// the overlap is t in [t0, 1] (f(t0) = (0, 0): f(t) = P0 + (1 − (1 − t)^3)(P3 − P0), so
// 1 − t0 = 3^(-1/3)) with s in [0, 1] reversed, and f(1) = g(0) bit for bit. The double root of
// f's derivative at t = 1, found 5e-8 inside, cut f there: the overlap stopped 5e-8 short of
// t = 1 and a cloud of three zero-width contacts sat next to it; (1, 0) was in none of them.
// Now: the one overlap, ending exactly at (1, 0), and nothing else, in both orders.
TEST(FuzzRegressions, F10_OverlapReachesAFlatEnd) {
  const Curve f({{1.0, -1.0}, {-0.5, 0.5}, {-0.5, 0.5}, {-0.5, 0.5}});
  const Curve g({{-0.5, 0.5}, {-0.5, 0.5}, {0.0, 0.0}, {0.0, 0.0}});
  const double t0 = 1.0 - std::cbrt(1.0 / 3.0);
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    EXPECT_TRUE(r.intersections.empty());
    ASSERT_EQ(r.overlaps.size(), 1u);
    const Overlap& o = r.overlaps[0];
    const ParamInterval on_f = swapped ? o.s_interval : o.t_interval;
    const ParamInterval on_g = swapped ? o.t_interval : o.s_interval;
    EXPECT_NEAR(on_f.lo, t0, 1e-12);
    EXPECT_EQ(on_f.hi, 1.0);
    EXPECT_EQ(on_g, (ParamInterval{0.0, 1.0}));
    EXPECT_TRUE(o.reversed);
    EXPECT_TRUE(swapped ? covered(r, 0.0, 1.0) : covered(r, 1.0, 0.0));
  }
}

// F14, found by intersect_fuzzer (wide inputs): an estimate one subnormal step outside its
// zero-width interval. f, 2^-900 long, lies on the segment g(s) = (0, 2^64 s), from s = 3 2^-1074
// to s = 2^-964; in the working frame f's positions along the line are one number, so the pair
// came as a touch with s in [3 2^-1074, 3 2^-1074] and the estimate s/2 + s/2 = 4 2^-1074 (and
// t = s = 0, no root, in the other order). Now f touches with all of its parameters: a contact
// holding every (t, s) of the coincidence, in both orders.
TEST(FuzzRegressions, F14_SubnormalEstimateInsideItsInterval) {
  const Curve f({{0.0, 0x3p-1010}, {0.0, 0x1p-900}});
  const Curve g({{0.0, 0.0}, {0.0, 0x1p64}});
  for (const bool swapped : {false, true}) {
    const IntersectionResult r = swapped ? intersect(g, f) : intersect(f, g);
    ASSERT_EQ(r.status, IntersectStatus::ok);
    ASSERT_EQ(r.intersections.size() + r.overlaps.size(), 1u);
    // f(0) = g(3 2^-1074), f(1) = g(2^-964) and f(1/2) = g((2^-964 + 3 2^-1074) / 2).
    for (const auto& [t, s] : {std::pair{0.0, 0x3p-1074}, std::pair{1.0, 0x1p-964},
                               std::pair{0.5, 0x1p-965 + 0x3p-1075}}) {
      EXPECT_TRUE(swapped ? covered(r, s, t) : covered(r, t, s)) << t << " " << s;
    }
    expect_intersection_contract(r, IntersectOptions{}.tolerance);
  }
}

// F11, found by intersect_fuzzer: g touches the segment f at f's end with third-order
// contact (P0, P1, P2 of g on the line y = 1, so g's y is 1 − s^3): one contact, f(1) = g(0)
// exactly, where f' = (−2, 0) and g'(0) = 3 (P1 − P0) are parallel and nonzero (tangent). The
// curves agree to within rounding along a stretch next to it, where the search leaves boxes at
// the precision floor with holes between them: two (unresolved) contacts 7e-6 apart, placed
// differently in the two orders. Now one contact, at the exact root, in both orders.
TEST(FuzzRegressions, F11_HighOrderContactIsReportedOnce) {
  const Curve f({{1.0, 1.0}, {-1.0, 1.0}});
  const Curve g({{-1.0, 1.0}, {0x1.fc38p+6, 1.0}, {-1.0, 1.0}, {0.0, 0.0}});
  expect_one_exact_end_root(f, g, 1.0, 0.0, IntersectionKind::tangent);
}

}  // namespace
}  // namespace bezier::core
