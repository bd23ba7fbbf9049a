// The building blocks of the clipping methods, each checked for what makes the search
// sound: the fat line holds the exact piece, the fat curve's delta bounds the distance
// function, the kept intervals contain every parameter where the band can be met, and the
// local-to-global map rounds outward. Exact checks in rationals at many sample points.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/bernstein/roots.hpp"
#include "core/numeric/binomial.hpp"
#include "core/intersect/clip/band_solve.hpp"
#include "core/bernstein/bernstein1d.hpp"
#include "core/intersect/clip/clip.hpp"
#include "core/intersect/clip/fat_curve.hpp"
#include "core/intersect/clip/fat_line.hpp"
#include "core/intersect/clip/implicit_clip.hpp"
#include "core/intersect/working_curve.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/mulberry32.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {
namespace {

using test::Rational;

Curve random_curve(test::Mulberry32& rng, int degree) {
  std::vector<Point2> pts(static_cast<std::size_t>(degree) + 1);
  for (Point2& p : pts) p = {rng.uniform(-1, 1), rng.uniform(-1, 1)};
  return Curve(std::move(pts));
}

/// N · (p - O) exactly.
Rational exact_distance(const FatLine& line, const test::RPoint2& p) {
  return Rational(line.normal.x) * (p.x - Rational(line.origin.x)) +
         Rational(line.normal.y) * (p.y - Rational(line.origin.y));
}

/// Bernstein polynomial value in rationals.
Rational exact_value(const std::vector<double>& c, const Rational& t) {
  std::vector<Rational> row;
  for (const double v : c) row.push_back(Rational(v));
  const Rational one_minus = Rational(1) - t;
  for (std::size_t level = row.size() - 1; level > 0; --level) {
    for (std::size_t i = 0; i < level; ++i) row[i] = one_minus * row[i] + t * row[i + 1];
  }
  return row[0];
}

TEST(ClipComponents, FatLineHoldsTheExactPiece) {
  test::Mulberry32 rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE("seed 5 trial " + std::to_string(trial));
    const int n = 1 + trial % 5;
    const Curve c = random_curve(rng, n);
    const WorkingFrame frame = working_frame(c, c);
    const WorkingCurve w = to_working(c, frame);
    const double a = rng.next() * 0.5, b = a + rng.next() * 0.5;
    const Piece g = trial % 2 ? fast_piece(w, a, b) : compensated_piece(w, a, b, {w.x[0], w.y[0]});
    const Piece other = fast_piece(w, 0.0, 1.0);
    const FatLine line = fat_line(g, other);
    const Point2 shift = trial % 2 ? Point2{0, 0} : Point2{w.x[0], w.y[0]};
    for (int k = 0; k <= 16; ++k) {
      // The exact working curve at a + (b - a) k/16 (a rational parameter), in g's frame.
      const Rational t = Rational(a) + (Rational(b) - Rational(a)) * Rational(k) / Rational(16);
      std::vector<test::RPoint2> pts;
      for (std::size_t i = 0; i < w.x.size(); ++i) {
        pts.push_back({Rational(w.x[i]) + Rational(w.x_lo[i]) - Rational(shift.x),
                       Rational(w.y[i]) + Rational(w.y_lo[i]) - Rational(shift.y)});
      }
      const Rational d = exact_distance(line, test::exact_evaluate(pts, t));
      EXPECT_LE(Rational(line.d_min), d);
      EXPECT_LE(d, Rational(line.d_max));
    }
  }
}

TEST(ClipComponents, FatCurveDeltaBoundsTheDistanceFunction) {
  test::Mulberry32 rng(6);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 3 + trial % 6, k = 2 + trial % 2;
    SCOPED_TRACE("n = " + std::to_string(n) + ", k = " + std::to_string(k));
    std::vector<double> a(static_cast<std::size_t>(n) + 1);
    for (double& v : a) v = rng.uniform(-1, 1);
    const FatCurveOperator op = fat_curve_operator(n, k);
    const FatCurve fc = fat_curve(op, a);
    const std::vector<double> p(fc.p.begin(), fc.p.end());
    for (int j = 0; j <= 32; ++j) {
      const Rational t(Rational(j) / Rational(32));
      EXPECT_LE(abs(exact_value(a, t) - exact_value(p, t)), Rational(fc.delta));
    }
  }
}

/// The root of the exact p - level in [a, b], where it changes sign, bracketed to 2^-60 by
/// bisection on exact rational values.
std::pair<double, double> exact_root(const std::vector<double>& p, const Rational& level, double a,
                                     double b) {
  const bool rising = exact_value(p, Rational(a)) < level;
  for (int i = 0; i < 60; ++i) {
    const double m = a + (b - a) / 2;
    if ((exact_value(p, Rational(m)) < level) == rising)
      a = m;
    else
      b = m;
  }
  return {a, b};
}

/// Sederberg and Nishita's clip in exact rationals: the least and the largest abscissa where
/// the convex hull of the points (i / k, p_i) meets the band lo <= y <= hi (its extreme points
/// there lie on segments between two control points, or are control points in the band).
std::pair<Rational, Rational> exact_hull_clip(const std::vector<double>& p, const Rational& lo,
                                              const Rational& hi) {
  const Rational k(static_cast<int>(p.size()) - 1);
  std::vector<Rational> xs;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Rational xi = Rational(static_cast<int>(i)) / k, ci(p[i]);
    if (lo <= ci && ci <= hi) xs.push_back(xi);
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const Rational xj = Rational(static_cast<int>(j)) / k, cj(p[j]);
      for (const Rational& level : {lo, hi}) {
        if ((ci < level && level < cj) || (cj < level && level < ci))
          xs.push_back(xi + (xj - xi) * (level - ci) / (cj - ci));
      }
    }
  }
  Rational least = xs.at(0), largest = xs.at(0);
  for (const Rational& x : xs) {
    if (x < least) least = x;
    if (largest < x) largest = x;
  }
  return {least, largest};
}

TEST(ClipComponents, KeptIntervalContainsEveryParameterInTheBand) {
  // Random polynomials of degree 1-3 and bands, including bands that only graze an
  // extremum (the closed form's weak spot): every sample t with lo <= p(t) <= hi (exactly)
  // must be inside the kept interval, and an empty answer means no sample is in the band.
  // Whatever the path (monotone roots, closed form, hull iteration), the kept interval is
  // never looser than Sederberg and Nishita's clip, up to the pads (2^-32 around a computed
  // root; 16 u around a hull clip).
  test::Mulberry32 rng(7);
  int grazing = 0;
  for (int trial = 0; trial < 1200; ++trial) {
    const int k = 1 + trial % 3;
    std::vector<double> p(static_cast<std::size_t>(k) + 1);
    for (double& v : p) v = rng.uniform(-1, 1);
    double lo = rng.uniform(-1, 1), hi = lo + rng.next() * 0.5;
    if (trial % 4 == 0 && k >= 2) {
      // A band ending at the value of p at an interior extremum, up to a few ulps.
      const double t0 = rng.next();
      const double v = bernstein::evaluate(p, t0);
      lo = v - 0x1p-50 * rng.next();
      hi = v;
      ++grazing;
    }
    const auto kept = kept_interval(p, lo, hi);
    const auto hulls = kept_interval_by_hulls(p, lo, hi);
    if (kept) {
      // Not empty: some coefficient is in the band, or some below and some above it.
      const auto [hull_lo, hull_hi] = exact_hull_clip(p, Rational(lo), Rational(hi));
      const Rational pad(0x1p-32 + 16 * kUnitRoundoff);
      EXPECT_GE(Rational(kept->lo), hull_lo - pad) << "trial " << trial;
      EXPECT_LE(Rational(kept->hi), hull_hi + pad) << "trial " << trial;
    }
    for (int j = 0; j <= 128; ++j) {
      const double t = j / 128.0;
      const Rational v = exact_value(p, Rational(t));
      if (Rational(lo) <= v && v <= Rational(hi)) {
        ASSERT_TRUE(kept.has_value()) << "trial " << trial << " t " << t;
        EXPECT_TRUE(kept->contains(t))
            << "trial " << trial << " t " << t << " kept " << kept->lo << " " << kept->hi;
        ASSERT_TRUE(hulls.has_value());
        EXPECT_TRUE(hulls->contains(t));
      }
    }
  }
  EXPECT_GT(grazing, 50);
}

TEST(ClipComponents, KeptIntervalOfAMonotoneCubicIsTight) {
  // p with Bernstein coefficients 0, 0.9, 2.1, 3 rises monotonically from 0 to 3, bending
  // slightly, as the distance function of a small piece does. {1 <= p <= 2} is [r1, r2]
  // with r1, r2 the roots of p = 1 and p = 2, bracketed in exact rationals; the kept
  // interval must hold it and be within 1e-8 of it (the clip's pad is 2^-32): near a root
  // the distance function is monotone, and this tightness is what gives the fat curve its
  // order of convergence.
  const std::vector<double> p = {0.0, 0.9, 2.1, 3.0};
  const auto [r1_lo, r1_hi] = exact_root(p, Rational(1), 0.0, 1.0);
  const auto [r2_lo, r2_hi] = exact_root(p, Rational(2), 0.0, 1.0);
  const auto kept = kept_interval(p, 1.0, 2.0);
  ASSERT_TRUE(kept.has_value());
  EXPECT_LE(kept->lo, r1_lo);
  EXPECT_GE(kept->hi, r2_hi);
  EXPECT_GT(kept->lo, r1_hi - 1e-8);
  EXPECT_LT(kept->hi, r2_lo + 1e-8);
}

TEST(ClipComponents, KeptIntervalOfAMonotoneCubicFlatAtOneEndIsTight) {
  // p(t) = 3 t^3 (Bernstein 0, 0, 0, 3) is monotone but flat at 0: its control polygon
  // crosses the level 1 at t = 7/9 and the level 2 at 8/9, while the roots are (1/3)^(1/3)
  // = 0.693 and (2/3)^(1/3) = 0.874 (bracketed here in rationals), 0.085 and 0.015 away.
  // The root finder must still reach the 2^-32 pad from there and certify it, or the
  // answer falls back to the looser hull iteration: within 1e-8 of [r1, r2] either way.
  const std::vector<double> p = {0.0, 0.0, 0.0, 3.0};
  const auto [r1_lo, r1_hi] = exact_root(p, Rational(1), 0.0, 1.0);
  const auto [r2_lo, r2_hi] = exact_root(p, Rational(2), 0.0, 1.0);
  for (const double sign : {1.0, -1.0}) {
    // The mirror image -p with the band [-2, -1]: the decreasing case, the same interval.
    const std::vector<double> q = {0.0, 0.0, 0.0, 3.0 * sign};
    const auto kept = sign > 0 ? kept_interval(q, 1.0, 2.0) : kept_interval(q, -2.0, -1.0);
    ASSERT_TRUE(kept.has_value());
    EXPECT_LE(kept->lo, r1_lo);
    EXPECT_GE(kept->hi, r2_hi);
    EXPECT_GT(kept->lo, r1_hi - 1e-8) << "sign " << sign;
    EXPECT_LT(kept->hi, r2_lo + 1e-8) << "sign " << sign;
  }
}

TEST(ClipComponents, KeptIntervalOfANonMonotoneCubicIsWithinItsConvexHullClip) {
  // p(t) = 6t(1 - t)(1 - 2t) (Bernstein 0, 2, -2, 0) rises to a maximum near t = 0.21 and
  // falls to a minimum near 0.79. {p >= 1/5} is [r1, r2] with r1, r2 the roots of p = 1/5
  // left of t = 1/2. A non-monotone cubic is clipped by repeated convex hulls: the kept
  // interval must hold [r1, r2] and lie within the first hull clip, [1/30, 14/15] (computed
  // here in rationals), up to the 8 u pad of the clip, the 4 u of its map to [0, 1] and the
  // rounding of the crossing itself.
  const std::vector<double> p = {0.0, 2.0, -2.0, 0.0};
  const Rational level(Rational(1) / Rational(5));
  const auto [r1_lo, r1_hi] = exact_root(p, level, 0.0, 0.21);
  const auto [r2_lo, r2_hi] = exact_root(p, level, 0.22, 0.5);
  const auto [hull_lo, hull_hi] = exact_hull_clip(p, level, Rational(5));
  EXPECT_EQ(hull_lo, Rational(1) / Rational(30));
  EXPECT_EQ(hull_hi, Rational(14) / Rational(15));
  const auto kept = kept_interval(p, 0.2, 5.0);
  ASSERT_TRUE(kept.has_value());
  EXPECT_LE(kept->lo, r1_lo);
  EXPECT_GE(kept->hi, r2_hi);
  const Rational pad(16 * kUnitRoundoff);
  EXPECT_GE(Rational(kept->lo), hull_lo - pad);
  EXPECT_LE(Rational(kept->hi), hull_hi + pad);
  // A band holding every value of p: the whole domain.
  EXPECT_EQ(*kept_interval(p, -5.0, 5.0), (ParamInterval{0.0, 1.0}));
}

TEST(ClipComponents, HullClipIsTheConvexHullOnTheBand) {
  // Points (0, -1), (1/2, 1), (1, -1): the hull meets y in [0, 0] for x in [1/4, 3/4].
  const double c[] = {-1.0, 1.0, -1.0};
  const auto r = bernstein::hull_clip(c, 0.0, 0.0);
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR(r->lo, 0.25, 1e-15);
  EXPECT_NEAR(r->hi, 0.75, 1e-15);
  EXPECT_LE(r->lo, 0.25);
  EXPECT_GE(r->hi, 0.75);
  EXPECT_FALSE(bernstein::hull_clip(c, 1.5, 2.0).has_value());
  const double all_in[] = {0.1, 0.2};
  EXPECT_EQ(*bernstein::hull_clip(all_in, 0.0, 1.0), (ParamInterval{0.0, 1.0}));
}

TEST(ClipComponents, HullClipMatchesTheHullComputedInRationals) {
  // hull_clip tests only the segments and the level each end of the polygon needs; the
  // reference here takes every control point in the band and every segment's crossing of
  // both levels, in exact rationals. Degrees 1-7; some coefficients put exactly on a level,
  // and bands inside, below, above and across the coefficients. The clip must contain the
  // exact hull and exceed it by at most its pad (8 u) plus the rounding of a crossing.
  test::Mulberry32 rng(11);
  const Rational slack(16 * kUnitRoundoff);
  int empty = 0, clipped = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int k = 1 + trial % 7;
    std::vector<double> p(static_cast<std::size_t>(k) + 1);
    for (double& v : p) v = rng.uniform(-1, 1);
    double lo = rng.uniform(-1.2, 1.2), hi = lo + rng.next() * 0.6;
    if (trial % 5 == 0) p[rng.next() < 0.5 ? 0 : static_cast<std::size_t>(k)] = lo;
    if (trial % 7 == 0) p[static_cast<std::size_t>(k) / 2] = hi;
    const auto clip = bernstein::hull_clip(p, lo, hi);
    const bool all_below = std::all_of(p.begin(), p.end(), [&](double v) { return v < lo; });
    const bool all_above = std::all_of(p.begin(), p.end(), [&](double v) { return v > hi; });
    ASSERT_EQ(clip.has_value(), !(all_below || all_above)) << "trial " << trial;
    if (!clip) {
      ++empty;
      continue;
    }
    const auto [exact_lo, exact_hi] = exact_hull_clip(p, Rational(lo), Rational(hi));
    EXPECT_LE(Rational(clip->lo), exact_lo) << "trial " << trial;
    EXPECT_GE(Rational(clip->hi), exact_hi) << "trial " << trial;
    EXPECT_GE(Rational(clip->lo), exact_lo - slack) << "trial " << trial;
    EXPECT_LE(Rational(clip->hi), exact_hi + slack) << "trial " << trial;
    clipped += clip->lo > 0.0 || clip->hi < 1.0;
  }
  EXPECT_GT(empty, 100);
  EXPECT_GT(clipped, 1000);
}

TEST(ClipComponents, MapToDomainRoundsOutward) {
  test::Mulberry32 rng(8);
  for (int trial = 0; trial < 10000; ++trial) {
    const double a = rng.next(), b = a + (1 - a) * rng.next();
    const double l = rng.next(), h = l + (1 - l) * rng.next();
    const ParamInterval out = map_to_domain({a, b}, {l, h});
    // The exact images a + (b - a) l and a + (b - a) h must be inside.
    const Rational lo = Rational(a) + (Rational(b) - Rational(a)) * Rational(l);
    const Rational hi = Rational(a) + (Rational(b) - Rational(a)) * Rational(h);
    EXPECT_LE(Rational(out.lo), lo);
    EXPECT_GE(Rational(out.hi), hi);
    EXPECT_GE(out.lo, a);
    EXPECT_LE(out.hi, b);
  }
  EXPECT_EQ(map_to_domain({0.25, 0.5}, {0.0, 1.0}), (ParamInterval{0.25, 0.5}));
}

TEST(ClipComponents, ImplicitClipKeepsEveryPointNearTheOtherCurve) {
  // x's parameters where x(t) is (exactly) on `other` must be kept: take x through points
  // of `other` and check the clip keeps those parameters.
  test::Mulberry32 rng(9);
  for (int trial = 0; trial < 300; ++trial) {
    const int m = 2 + trial % 3;
    const Curve g = random_curve(rng, m);
    const WorkingFrame frame = working_frame(g, g);
    const WorkingCurve wg = to_working(g, frame);
    const Piece other = fast_piece(wg, 0.0, 1.0);
    // x: the segment between two points of `other` (so x(0) and x(1) are on it, up to the
    // rounding of the evaluation, which fast_piece's error covers).
    const double s0 = rng.next(), s1 = rng.next();
    const PointAndTangent p0 = evaluate_with_tangent(wg, s0), p1 = evaluate_with_tangent(wg, s1);
    Piece x;
    x.x = Coeffs(std::vector<double>{p0.point.x, p1.point.x});
    x.y = Coeffs(std::vector<double>{p0.point.y, p1.point.y});
    x.error = 16 * 0x1p-53 * m;  // de Casteljau rounding of the two points
    const Clip c = implicit_clip(x, other, fat_curve_operator(m, 2));
    ASSERT_TRUE(c.kept.has_value()) << trial;
    EXPECT_EQ(c.kept->lo, 0.0) << trial;
    EXPECT_EQ(c.kept->hi, 1.0) << trial;
  }
}

TEST(BernsteinRoots, RootsOfAPolynomialBuiltFromThem) {
  // p(t) = (t - 1/8)(t - 1/2)(t - 3/4)(t - 1), converted to Bernstein form exactly.
  const Rational r[] = {Rational(1, 8), Rational(1, 2), Rational(3, 4), Rational(1)};
  std::vector<Rational> power = {Rational(1)};
  for (const Rational& root : r) {
    std::vector<Rational> next(power.size() + 1, Rational(0));
    for (std::size_t i = 0; i < power.size(); ++i) {
      next[i + 1] += power[i];
      next[i] -= root * power[i];
    }
    power = next;
  }
  const int n = 4;
  std::vector<double> b;
  for (int i = 0; i <= n; ++i) {
    Rational sum(0);
    for (int j = 0; j <= i; ++j) {
      sum += Rational(static_cast<long long>(binomial(i, j))) /
             Rational(static_cast<long long>(binomial(n, j))) * power[static_cast<std::size_t>(j)];
    }
    b.push_back(sum.to_double());
  }
  const BernsteinRoots found = bernstein_roots(b);
  ASSERT_EQ(found.roots.size(), 4u);
  EXPECT_NEAR(found.roots[0], 0.125, 1e-14);
  EXPECT_NEAR(found.roots[1], 0.5, 1e-14);
  EXPECT_NEAR(found.roots[2], 0.75, 1e-14);
  EXPECT_EQ(found.roots[3], 1.0);
  // No roots: a positive polynomial.
  const double positive[] = {1.0, -0.5, 1.0};
  EXPECT_TRUE(bernstein_roots(positive).roots.empty());
}

}  // namespace
}  // namespace bezier::core
