// Properties of intersect() on seeded random curves (mulberry32 as BENCHMARKS.md's "Benchmark input"; the seed is in
// every failure message): swapping the curves swaps t and s, reversing a curve maps t to
// 1 - t, an affine map of both curves keeps the parameters, every reported point has
// |f(t) - g(s)| within a few ulps, the three methods agree, and every interval contains
// the exact root (located by Newton's method in rationals).
//
// Two intervals computed for the same root both contain it, so they must overlap: that is
// how results of different computations are matched here (the estimates can differ by the
// root's conditioning times the rounding, which is unbounded near tangencies).

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/intersect/intersect.hpp"
#include "tests/core/intersect/exact_roots.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

Curve random_curve(test::Mulberry32& rng, int degree) {
  std::vector<Point2> pts(static_cast<std::size_t>(degree) + 1);
  for (Point2& p : pts) {
    // On a 2^-20 grid, so that the affine maps below are exact.
    p.x = std::ldexp(std::floor(rng.next() * 0x1p20), -20);
    p.y = std::ldexp(std::floor(rng.next() * 0x1p20), -20);
  }
  return Curve(std::move(pts));
}

bool overlapping(ParamInterval a, ParamInterval b) {
  return a.lo <= b.hi && b.lo <= a.hi;
}

ParamInterval flipped(ParamInterval iv) {
  return {1.0 - iv.hi, 1.0 - iv.lo};
}

/// Every intersection of `a` has one in `b` whose intervals overlap (after mapping a's
/// intervals by `map`), and the counts are equal.
template <class Map>
void expect_same_roots(const IntersectionResult& a, const IntersectionResult& b, Map map) {
  ASSERT_EQ(a.intersections.size(), b.intersections.size());
  for (const Intersection& x : a.intersections) {
    const auto [t, s] = map(x);
    int matches = 0;
    for (const Intersection& y : b.intersections) {
      matches += overlapping(t, y.t_interval) && overlapping(s, y.s_interval);
    }
    EXPECT_EQ(matches, 1) << "t = " << x.t << ", s = " << x.s;
  }
}

struct Pair {
  Curve f;
  Curve g;
  std::string name;
};

std::vector<Pair> random_pairs(std::uint32_t seed, int count) {
  test::Mulberry32 rng(seed);
  std::vector<Pair> pairs;
  for (int i = 0; i < count; ++i) {
    const int nf = 1 + static_cast<int>(rng.next() * 5), ng = 1 + static_cast<int>(rng.next() * 5);
    Curve f = random_curve(rng, nf);
    Curve g = random_curve(rng, ng);
    pairs.push_back({std::move(f), std::move(g),
                     "seed " + std::to_string(seed) + " pair " + std::to_string(i) + " degrees " +
                         std::to_string(nf) + ", " + std::to_string(ng)});
  }
  return pairs;
}

const std::vector<Pair>& pairs() {
  static const std::vector<Pair> p = random_pairs(2024, 300);
  return p;
}

TEST(IntersectProperties, SwappingTheCurvesSwapsTAndS) {
  for (const Pair& p : pairs()) {
    SCOPED_TRACE(p.name);
    const IntersectionResult a = intersect(p.f, p.g), b = intersect(p.g, p.f);
    ASSERT_EQ(a.status, IntersectStatus::ok);
    expect_same_roots(a, b, [](const Intersection& x) {
      return std::pair{x.s_interval, x.t_interval};
    });
  }
}

TEST(IntersectProperties, ReversingACurveMapsTToOneMinusT) {
  for (const Pair& p : pairs()) {
    SCOPED_TRACE(p.name);
    const IntersectionResult a = intersect(p.f, p.g), b = intersect(reversed(p.f), p.g);
    expect_same_roots(a, b, [](const Intersection& x) {
      return std::pair{flipped(x.t_interval), x.s_interval};
    });
    const IntersectionResult c = intersect(p.f, reversed(p.g));
    expect_same_roots(a, c, [](const Intersection& x) {
      return std::pair{x.t_interval, flipped(x.s_interval)};
    });
  }
}

TEST(IntersectProperties, AnAffineMapOfBothCurvesKeepsTheParameters) {
  // (x, y) -> (3x - 2y + 5, x + 4y - 1) / 4: exact on the 2^-20 grid, so the mapped curves
  // have exactly the same roots.
  const auto map = [](const Curve& c) {
    std::vector<Point2> pts;
    for (const Point2 q : c.points())
      pts.push_back({(3 * q.x - 2 * q.y + 5) / 4, (q.x + 4 * q.y - 1) / 4});
    return Curve(std::move(pts));
  };
  for (const Pair& p : pairs()) {
    SCOPED_TRACE(p.name);
    const IntersectionResult a = intersect(p.f, p.g), b = intersect(map(p.f), map(p.g));
    expect_same_roots(a, b, [](const Intersection& x) {
      return std::pair{x.t_interval, x.s_interval};
    });
  }
}

TEST(IntersectProperties, ReportedPointsAreOnBothCurves) {
  // Exactly, in rationals, at the double estimates: |f(t) - g(s)| within a few ulps of the
  // scale, and the point within as much of f(t) and of g(s). (For a transversal root the
  // point comes from Newton's last compensated evaluation moved along the tangents by the
  // last step, which has to be the step actually taken.)
  for (const Pair& p : pairs()) {
    SCOPED_TRACE(p.name);
    double scale = 0.0;
    for (const Curve* c : {&p.f, &p.g}) {
      for (const Point2 q : c->points()) scale = std::fmax(scale, max_abs_coordinate(q));
    }
    for (const Intersection& x : intersect(p.f, p.g).intersections) {
      if (x.kind != IntersectionKind::transversal) continue;  // tangencies: see hard cases
      EXPECT_LE(test::exact_gap(p.f, p.g, x.t, x.s), 8 * 0x1p-52 * scale) << x.t << " " << x.s;
      const test::RPoint2 a = test::exact_evaluate(test::exact_points(p.f), test::Rational(x.t));
      const test::RPoint2 b = test::exact_evaluate(test::exact_points(p.g), test::Rational(x.s));
      for (const test::RPoint2& on : {a, b}) {
        const test::Rational dx = abs(on.x - test::Rational(x.point.x));
        const test::Rational dy = abs(on.y - test::Rational(x.point.y));
        EXPECT_LE((dx < dy ? dy : dx).to_double(), 8 * 0x1p-52 * scale) << x.t << " " << x.s;
      }
    }
  }
}

TEST(IntersectProperties, TheThreeMethodsAgree) {
  for (const Pair& p : pairs()) {
    SCOPED_TRACE(p.name);
    IntersectOptions clip, sub, quadratic_fat;
    clip.method = IntersectMethod::bezier_clipping;
    sub.method = IntersectMethod::subdivision;
    quadratic_fat.fat_curve_degree = 2;
    const IntersectionResult a = intersect(p.f, p.g);
    const auto same = [](const Intersection& x) { return std::pair{x.t_interval, x.s_interval}; };
    expect_same_roots(a, intersect(p.f, p.g, clip), same);
    expect_same_roots(a, intersect(p.f, p.g, sub), same);
    expect_same_roots(a, intersect(p.f, p.g, quadratic_fat), same);
  }
}

TEST(IntersectProperties, IntervalsContainTheExactRoot) {
  // Newton's method in rationals from the estimate converges to the true root (the
  // Jacobian at a transversal root is regular); the guaranteed intervals must hold it.
  int checked = 0;
  for (const Pair& p : pairs()) {
    SCOPED_TRACE(p.name);
    if (p.f.degree() > 3 || p.g.degree() > 3) continue;  // keep the rationals small
    for (const Intersection& x : intersect(p.f, p.g).intersections) {
      if (x.kind != IntersectionKind::transversal) continue;
      const auto root = test::exact_newton(p.f, p.g, x.t, x.s);
      ASSERT_TRUE(root.has_value());
      EXPECT_TRUE(test::contains(x.t_interval, root->t))
          << x.t_interval.lo << " " << x.t_interval.hi;
      EXPECT_TRUE(test::contains(x.s_interval, root->s))
          << x.s_interval.lo << " " << x.s_interval.hi;
      // The estimate is the root correctly rounded, or next to it.
      EXPECT_LE(std::fabs(x.t - root->t.to_double()),
                2 * std::nextafter(x.t, 2.0) - 2 * x.t + 1e-300);
      EXPECT_LT(x.t_interval.width(), 1e-12);
      ++checked;
    }
  }
  EXPECT_GT(checked, 50);
}

TEST(IntersectProperties, ResultsAreSortedAndInsideTheSquare) {
  for (const Pair& p : pairs()) {
    SCOPED_TRACE(p.name);
    const IntersectionResult r = intersect(p.f, p.g);
    for (std::size_t i = 0; i < r.intersections.size(); ++i) {
      const Intersection& x = r.intersections[i];
      EXPECT_TRUE(0.0 <= x.t_interval.lo && x.t_interval.hi <= 1.0);
      EXPECT_TRUE(0.0 <= x.s_interval.lo && x.s_interval.hi <= 1.0);
      EXPECT_TRUE(x.t_interval.contains(x.t));
      EXPECT_TRUE(x.s_interval.contains(x.s));
      if (i > 0) {
        EXPECT_LE(r.intersections[i - 1].t, x.t);
      }
    }
  }
}

}  // namespace
}  // namespace bezier::core
