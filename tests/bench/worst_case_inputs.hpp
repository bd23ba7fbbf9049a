#pragma once

// The costliest requests we know at the default limits (api/limits.hpp: max_degree 20,
// max_t_values 10000, max_work 22000000 units): request bodies for api::handle, built from
// closed forms and seeded random curves, timed by tests/bench/worst_case_bench.cpp.
//
// The curves:
//   * random(seed, n): control points uniform in [0,1]^2 from mulberry32 (BENCHMARKS.md,
//     "Benchmark input");
//   * chebyshev(n): T_n(2t - 1), whose Bernstein coefficients are
//     (-1)^(n-k) C(2n, 2k) / C(n, k) (Farouki & Rajan 1988 give the conversion; checked
//     against T_2: 1, -3, 1); it oscillates n times between -1 and 1 on [0, 1] with
//     coefficients up to C(40, 20) / C(20, 10) ~ 7.5e5 at n = 20: heavily cancelling;
//   * (1 - 2t)^n: Bernstein coefficients (-1)^k, one root of multiplicity n at t = 1/2;
//   * A∘φ: a curve composed with a polynomial reparametrisation φ in Bernstein form,
//     computed exactly in rationals (exact_compose, tests/support/exact_bezier.hpp) and
//     rounded once per coordinate:
//     the same point set as A traced at another speed (non-linear when φ is), or, when φ is
//     not monotone, a curve that retraces itself.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/base/curve.hpp"
#include "core/bernstein/degree.hpp"
#include "core/curve/polar.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::test::worst_case {

using core::Curve;
using core::Point2;

/// One request: where it goes and its body.
struct Request {
  std::string name;
  std::string path;
  std::string body;
};

inline Curve random_curve(std::uint32_t seed, int degree) {
  Mulberry32 rng(seed);
  std::vector<Point2> pts(static_cast<std::size_t>(degree) + 1);
  for (Point2& p : pts) p = {rng.next(), rng.next()};
  return Curve(std::move(pts));
}

/// Bernstein coefficients of T_n(2t - 1), rounded once each.
inline std::vector<double> chebyshev(int n) {
  std::vector<double> c;
  for (int k = 0; k <= n; ++k) {
    const Rational v = Rational(binom(2 * n, 2 * k)) / Rational(binom(n, k));
    c.push_back(((n - k) % 2 == 0 ? v : -v).to_double());
  }
  return c;
}

/// Bernstein coefficients of t on [0, 1] at degree n: k / n.
inline std::vector<double> identity(int n) {
  std::vector<double> c;
  for (int k = 0; k <= n; ++k) c.push_back(static_cast<double>(k) / n);
  return c;
}

inline Curve from_coordinates(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<Point2> pts;
  for (std::size_t i = 0; i < x.size(); ++i) pts.push_back({x[i], y[i]});
  return Curve(std::move(pts));
}

/// A∘φ for φ given by its Bernstein coefficients (degree d): a curve of degree n d, its
/// control points rounded once from the exact composition.
inline Curve compose(const Curve& a, const std::vector<double>& phi) {
  const BernsteinPoly q(phi.begin(), phi.end());
  std::vector<Point2> pts;
  for (const RPoint2& p : exact_compose(exact_points(a), q))
    pts.push_back({p.x.to_double(), p.y.to_double()});
  return Curve(std::move(pts));
}

/// The curve moved by (dx, dy).
inline Curve translated(const Curve& c, double dx, double dy) {
  std::vector<Point2> pts;
  for (const Point2& p : c.points()) pts.push_back({p.x + dx, p.y + dy});
  return Curve(std::move(pts));
}

/// Every y coordinate moved up by one ulp.
inline Curve ulp_perturbed(const Curve& c) {
  std::vector<Point2> pts;
  for (const Point2& p : c.points()) pts.push_back({p.x, std::nextafter(p.y, 2.0)});
  return Curve(std::move(pts));
}

inline nlohmann::json points_json(const Curve& c) {
  nlohmann::json pts = nlohmann::json::array();
  for (const Point2& p : c.points()) pts.push_back({p.x, p.y});
  return pts;
}

inline nlohmann::json points3_json(const Curve& c, double z_scale) {
  nlohmann::json pts = nlohmann::json::array();
  for (const Point2& p : c.points()) pts.push_back({p.x, p.y, z_scale * (p.x - p.y)});
  return pts;
}

/// The named curves the requests are built from.
struct Curves {
  Curve random20 = random_curve(20, 20);
  Curve random10 = random_curve(10, 10);
  Curve random6 = random_curve(6, 6);
  Curve random3 = random_curve(3, 3);
  Curve wave = from_coordinates(identity(20), chebyshev(20));    // (t, T_20(2t-1))
  Curve wave_t = from_coordinates(chebyshev(20), identity(20));  // (T_20(2s-1), s)
  Curve wave15 = from_coordinates(identity(15), chebyshev(15));  // 225 crossings with wave15_t
  Curve wave15_t = from_coordinates(chebyshev(15), identity(15));
  Curve lissajous = from_coordinates(chebyshev(20), core::elevate_degree(chebyshev(19), 20));
  Curve contact20 = [] {  // (t, (1-2t)^20)
    std::vector<double> y;
    for (int k = 0; k <= 20; ++k) y.push_back(k % 2 == 0 ? 1.0 : -1.0);
    return from_coordinates(identity(20), y);
  }();
  Curve axis20 = from_coordinates(identity(20), std::vector<double>(21, 0.0));  // the x axis
  Curve retrace_slow = compose(random10, {0.0, 0.25, 1.0});  // A10 at another, non-linear, speed
  Curve retrace_fast = compose(random10, {0.0, 0.75, 1.0});
  Curve palindrome = compose(random10, {0.0, 2.0, 0.0});  // A10 there and back: B(1-t) = B(t)
  Curve fold = compose(random6, {0.0, 1.2, -0.2, 0.6});   // A6 forth, back, forth again
  Curve zigzag = [] {                                     // collinear, doubling back 20 times
    std::vector<Point2> pts;
    for (int k = 0; k <= 20; ++k) pts.push_back(k % 2 == 0 ? Point2{0.0, 0.0} : Point2{1.0, 2.0});
    return Curve(std::move(pts));
  }();
};

inline std::string two_curves(const Curve& a, const Curve& b, const std::string& method,
                              double tolerance = 1e-12, int fat_curve_degree = 3) {
  nlohmann::json body = {{"curves", {{{"points", points_json(a)}}, {{"points", points_json(b)}}}},
                         {"method", method}};
  if (tolerance != 1e-12) body["tolerance"] = tolerance;
  if (fat_curve_degree != 3) body["fat_curve_degree"] = fat_curve_degree;
  return body.dump();
}

/// Every method the API offers, with the hybrid method's two fat-curve degrees: (name in
/// the benchmark, method, fat-curve degree).
struct MethodVariant {
  const char* name;
  const char* method;
  int fat_curve_degree;
};
inline constexpr MethodVariant kMethodVariants[] = {{"hybrid", "hybrid", 3},
                                                    {"hybrid_fat2", "hybrid", 2},
                                                    {"bezier-clipping", "bezier-clipping", 3},
                                                    {"subdivision", "subdivision", 3}};

/// Requests whose magnitudes span many orders within one pair (found as requests that ran
/// for seconds; docs/FUZZING.md lists what the fuzz target work_bound_fuzzer found):
///  * steep_parabola: a parabola 1e14 tall against a line rising 1e6 across it, which it
///    crosses where both run nearly parallel (subdivision keeps a column of 135 000
///    undecided boxes along the crossing);
///  * wide_cubic: a cubic reaching 1e9 against the diagonal of the unit square.
inline std::vector<std::pair<std::string, std::pair<Curve, Curve>>> hostile_magnitude_pairs() {
  return {{"steep_parabola", {Curve({{2, -2}, {-1, 1e14}, {-1, -1}}), Curve({{-0.5, 0}, {-2, 1e6}})}},
          {"wide_cubic", {Curve({{0, 1}, {1e9, 1}, {0, -1e9}, {0, -2}}), Curve({{0, 0}, {1, 1}})}}};
}

inline std::string one_curve(const Curve& a) {
  return nlohmann::json{{"curves", {{{"points", points_json(a)}}}}}.dump();
}

/// Every request, in the order the benchmark registers them.
inline std::vector<Request> requests() {
  const Curves c;
  std::vector<Request> r;

  // /evaluate and /polar: the most parameters with the most work per parameter.
  std::vector<double> ts(10000), far(10000);
  Mulberry32 rng(99);
  for (double& t : ts) t = rng.next();
  for (double& t : far) t = rng.uniform(-1e15, 1e15);
  r.push_back({"evaluate/deg20_samples10000", "/evaluate",
               nlohmann::json{{"points", points_json(c.random20)}, {"samples", 10000}}.dump()});
  r.push_back(
      {"evaluate/deg20_samples10000_deriv20", "/evaluate",
       nlohmann::json{{"points", points_json(c.random20)}, {"samples", 10000}, {"derivatives", 20}}
           .dump()});
  r.push_back(
      {"evaluate/deg20_samples10000_deriv20_3d", "/evaluate",
       nlohmann::json{
           {"points", points3_json(c.random20, 1.0)}, {"samples", 10000}, {"derivatives", 20}}
           .dump()});
  // The most derivatives the t-values x (derivatives + 1) <= max_t_values rule allows.
  r.push_back({"evaluate/deg20_samples476_deriv20_3d", "/evaluate",
               nlohmann::json{
                   {"points", points3_json(c.random20, 1.0)}, {"samples", 476}, {"derivatives", 20}}
                   .dump()});
  r.push_back(
      {"evaluate/deg20_t10000_deriv20_split", "/evaluate",
       nlohmann::json{
           {"points", points_json(c.random20)}, {"t", ts}, {"derivatives", 20}, {"split", 0.5}}
           .dump()});
  r.push_back({"evaluate/deg20_t10000_far_deriv20", "/evaluate",
               nlohmann::json{{"points", points_json(c.random20)}, {"t", far}, {"derivatives", 20}}
                   .dump()});
  r.push_back({"polar/deg20_t0x19_samples10000_3d", "/polar",
               nlohmann::json{{"points", points3_json(c.random20, 1.0)},
                              {"t0", std::vector<double>(ts.begin(), ts.begin() + 19)},
                              {"samples", 10000}}
                   .dump()});
  r.push_back({"polar/deg20_t0_samples10000", "/polar",
               nlohmann::json{{"points", points_json(c.random20)}, {"t0", 0.3}, {"samples", 10000}}
                   .dump()});

  // /intersections, two curves, every method.
  const std::pair<const char*, std::pair<const Curve*, const Curve*>> pairs_[] = {
      {"identical_deg20", {&c.random20, &c.random20}},
      {"ulp_apart_deg20", {&c.random20, nullptr}},
      {"retrace_nonlinear_deg20", {&c.retrace_slow, &c.retrace_fast}},
      {"wave_grid_400", {&c.wave, &c.wave_t}},
      {"wave_grid_225_deg15", {&c.wave15, &c.wave15_t}},
      {"contact_order20", {&c.contact20, &c.axis20}},
  };
  const Curve ulp = ulp_perturbed(c.random20);
  const Curve reversed = core::reversed(c.random20);
  const Curve piece = core::portion(c.random20, 0.25, 0.75);
  for (const char* method : {"hybrid", "bezier-clipping", "subdivision"}) {
    const std::string m = method;
    for (const auto& [name, curves] : pairs_) {
      const Curve& b = curves.second ? *curves.second : ulp;
      r.push_back(
          {"intersections/" + m + "/" + name, "/intersections", two_curves(*curves.first, b, m)});
    }
    r.push_back({"intersections/" + m + "/reversed_deg20", "/intersections",
                 two_curves(c.random20, reversed, m)});
    r.push_back({"intersections/" + m + "/piece_deg20", "/intersections",
                 two_curves(c.random20, piece, m)});
    for (const double gap : {1e-12, 1e-9, 1e-6}) {
      char name[64];
      std::snprintf(name, sizeof name, "/gap_%.0e_deg20", gap);
      r.push_back({"intersections/" + m + name, "/intersections",
                   two_curves(c.random20, translated(c.random20, 0.0, gap), m)});
    }
    // Even two cubics: a copy 1e-12 above its original (too close to be resolved as
    // crossings, too far to be an overlap).
    for (const double gap : {1e-12, 1e-9}) {
      char name[64];
      std::snprintf(name, sizeof name, "/gap_%.0e_cubic", gap);
      r.push_back({"intersections/" + m + name, "/intersections",
                   two_curves(c.random3, translated(c.random3, 0.0, gap), m)});
    }
  }
  r.push_back({"intersections/hybrid/wave_grid_400_tol_min", "/intersections",
               two_curves(c.wave, c.wave_t, "hybrid", 0x1p-46)});
  {
    // A degree-12 curve whose last nine control points coincide (work_bound_fuzzer's F34):
    // most boxes next to the diagonal start a Newton run.
    std::vector<Point2> pts = {{-1e-323, -5e-324}, {-1e-323, 6.0}, {-8.0, -4.0}, {-181.74, 0.0}};
    pts.resize(13, Point2{0.0, 0.0});
    const Curve degenerate(std::move(pts));
    r.push_back({"self/f34_degenerate_deg12", "/intersections", one_curve(degenerate)});
    r.push_back({"loop_area/f34_degenerate_deg12", "/loop-area",
                 nlohmann::json{{"points", points_json(degenerate)}}.dump()});
  }
  // The default method's heaviest requests again with fat curves of degree 2.
  r.push_back({"intersections/hybrid_fat2/wave_grid_400", "/intersections",
               two_curves(c.wave, c.wave_t, "hybrid", 1e-12, 2)});
  r.push_back({"intersections/hybrid_fat2/contact_order20", "/intersections",
               two_curves(c.contact20, c.axis20, "hybrid", 1e-12, 2)});
  for (const auto& [name, curves] : hostile_magnitude_pairs()) {
    for (const MethodVariant& m : kMethodVariants) {
      r.push_back({"intersections/" + std::string(m.name) + "/" + name, "/intersections",
                   two_curves(curves.first, curves.second, m.method, 1e-12, m.fat_curve_degree)});
    }
  }

  // Fuzz finding F7 (docs/FUZZING.md): a degree-20 curve with one control point apart against
  // a point, and a quartic spanning 1e15 whose pairs the certification searches.
  {
    nlohmann::json spike = nlohmann::json::array({{1.0, 0.0}});
    for (int k = 0; k < 20; ++k) spike.push_back({0.0, 0.0});
    r.push_back(
        {"intersections/hybrid/f7_spike_deg20_vs_point", "/intersections",
         nlohmann::json{{"curves", {{{"points", spike}}, {{"points", {{0.0, 0.0}, {0.0, 0.0}}}}}}}
             .dump()});
    const nlohmann::json wide = {
        {1, 0.5}, {0.5, -6.9e14}, {6.9e14, -6.9e14}, {-9807.5, -0.61}, {-7.4e-16, -0.61}};
    r.push_back(
        {"self/f7_wide_quartic_subdivision", "/intersections",
         nlohmann::json{{"curves", {{{"points", wide}}}}, {"method", "subdivision"}}.dump()});
  }

  // Self-intersections (/intersections with one curve) and /loop-area on the same curves.
  const std::pair<const char*, const Curve*> singles[] = {
      {"random_deg20", &c.random20},       {"lissajous_20_19", &c.lissajous},
      {"palindrome_deg20", &c.palindrome}, {"fold_deg18", &c.fold},
      {"zigzag_deg20", &c.zigzag},         {"wave_deg20", &c.wave},
  };
  for (const auto& [name, curve] : singles) {
    r.push_back({std::string("self/") + name, "/intersections", one_curve(*curve)});
    r.push_back({std::string("loop_area/") + name, "/loop-area",
                 nlohmann::json{{"points", points_json(*curve)}}.dump()});
  }
  return r;
}

}  // namespace bezier::test::worst_case
