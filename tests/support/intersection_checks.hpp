#pragma once

// Checks shared by the intersection tests: the contract of Intersection, coverage of a
// parameter pair by an answer, every method and order, and exact points of quadratics and
// the implicit equation of the parabola one lies on (for crossings proved in rationals).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "core/base/curve.hpp"
#include "core/intersect/intersect.hpp"
#include "tests/support/exact.hpp"

namespace bezier::test {

using core::Curve;
using core::Intersection;
using core::IntersectionKind;
using core::IntersectionResult;
using core::IntersectMethod;
using core::IntersectOptions;
using core::IntersectStatus;
using core::intersect;

/// A point in exact rationals.
using RationalPoint = std::array<Rational, 2>;

/// q(t) of a quadratic in exact rationals (t and the control points as the doubles they are).
inline RationalPoint exact_point(const Curve& q, double t) {
  const Rational tr(t), one(1), two(2);
  const Rational b0 = (one - tr) * (one - tr), b1 = two * tr * (one - tr), b2 = tr * tr;
  return {b0 * Rational(q[0].x) + b1 * Rational(q[1].x) + b2 * Rational(q[2].x),
          b0 * Rational(q[0].y) + b1 * Rational(q[1].y) + b2 * Rational(q[2].y)};
}

/// The implicit equation of the parabola a quadratic q lies on, at x, in exact rationals:
/// A1^2 - 4 A0 A2 (Ai the signed area of the triangle x P_j P_k, {i, j, k} = {0, 1, 2}:
/// barycentric coordinates, and tau_1^2 = 4 tau_0 tau_2 on a quadratic). It changes sign
/// where a curve crosses the parabola.
inline Rational on_parabola(const Curve& q, const RationalPoint& x) {
  const auto area = [](const RationalPoint& a, const RationalPoint& b, const RationalPoint& c) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
  };
  const RationalPoint p0{Rational(q[0].x), Rational(q[0].y)},
      p1{Rational(q[1].x), Rational(q[1].y)}, p2{Rational(q[2].x), Rational(q[2].y)};
  const Rational a0 = area(x, p1, p2), a1 = area(p0, x, p2), a2 = area(p0, p1, x);
  return a1 * a1 - Rational(4) * a0 * a2;
}

/// Whether (t, s) lies in the box of a reported intersection or in a reported overlap.
inline bool covered(const IntersectionResult& r, double t, double s) {
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
inline void expect_no_common_point(const Curve& f, const Curve& g) {
  for_every_option(f, g, IntersectOptions{}.tolerance,
                   [](const IntersectionResult& r, const IntersectOptions&, bool) {
                     ASSERT_EQ(r.status, IntersectStatus::ok);
                     EXPECT_TRUE(r.intersections.empty());
                     EXPECT_TRUE(r.overlaps.empty());
                   });
}

// The contract of Intersection (result.hpp): intervals narrower than the tolerance whenever
// `resolved`, the estimate inside them, the point finite.
inline void expect_intersection_contract(const IntersectionResult& r, double tolerance) {
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
inline void expect_one_exact_end_root(const Curve& f, const Curve& g, double t, double s,
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

}  // namespace bezier::test
