// core/intersect/clip/band_solve.hpp: the kept intervals contain every parameter where the
// band can be met, are as tight as the method promises (against roots bracketed and hulls
// computed in exact rationals), and the cubic solver finds the roots of polynomials built
// from them.
#include "core/intersect/clip/band_solve.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "core/bernstein/bernstein1d.hpp"
#include "core/numeric/unit_roundoff.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/exact_hull_clip.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::exact_bernstein_value;
using test::exact_hull_clip;
using test::Rational;

/// The root of the exact p - level in [a, b], where it changes sign, bracketed to 2^-60 by
/// bisection on exact rational values.
std::pair<double, double> exact_root(const std::vector<double>& p, const Rational& level, double a,
                                     double b) {
  const bool rising = exact_bernstein_value(p, Rational(a)) < level;
  for (int i = 0; i < 60; ++i) {
    const double m = a + (b - a) / 2;
    if ((exact_bernstein_value(p, Rational(m)) < level) == rising)
      a = m;
    else
      b = m;
  }
  return {a, b};
}

TEST(BandSolve, KeptIntervalContainsEveryParameterInTheBand) {
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
      if (test::exactly_in_band(p, t, Rational(lo), Rational(hi))) {
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

TEST(BandSolve, KeptIntervalOfAMonotoneCubicIsTight) {
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

TEST(BandSolve, KeptIntervalOfAMonotoneCubicFlatAtOneEndIsTight) {
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

TEST(BandSolve, KeptIntervalOfANonMonotoneCubicIsWithinItsConvexHullClip) {
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

TEST(BandSolve, CubicRootsOfPolynomialsBuiltFromThem) {
  // 32 (t - 1/4)(t - 1/2)(t - 3/4) = 32 t^3 - 48 t^2 + 22 t - 3: three roots in [0, 1].
  // A root is as accurate as p's rounding allows: Horner's bound 6 u Σ |c_i| r^i over the
  // slope |p'(r)| is at most 1e-14 at each of these roots (and the others below).
  constexpr double kWithinRounding = 2e-14;
  const CubicRoots three = real_roots_up_to_cubic(-3.0, 22.0, -48.0, 32.0, 0.0, 1.0);
  ASSERT_EQ(three.count, 3);
  EXPECT_NEAR(three.t[0], 0.25, kWithinRounding);
  EXPECT_NEAR(three.t[1], 0.5, kWithinRounding);
  EXPECT_NEAR(three.t[2], 0.75, kWithinRounding);
  // Only those in [lo, hi].
  const CubicRoots middle = real_roots_up_to_cubic(-3.0, 22.0, -48.0, 32.0, 0.3, 0.7);
  ASSERT_EQ(middle.count, 1);
  EXPECT_NEAR(middle.t[0], 0.5, kWithinRounding);
  // (t - 1/2)(t^2 + 1) = t^3 - t^2 / 2 + t - 1/2: one real root.
  const CubicRoots one = real_roots_up_to_cubic(-0.5, 1.0, -0.5, 1.0, 0.0, 1.0);
  ASSERT_EQ(one.count, 1);
  EXPECT_NEAR(one.t[0], 0.5, kWithinRounding);
  // Lower degrees: (4 t - 1)(t - 3) = 4 t^2 - 13 t + 3 has 1/4 in [0, 1]; 2 t - 1 has 1/2.
  const CubicRoots quadratic = real_roots_up_to_cubic(3.0, -13.0, 4.0, 0.0, 0.0, 1.0);
  ASSERT_EQ(quadratic.count, 1);
  EXPECT_NEAR(quadratic.t[0], 0.25, kWithinRounding);
  const CubicRoots linear = real_roots_up_to_cubic(-1.0, 2.0, 0.0, 0.0, 0.0, 1.0);
  ASSERT_EQ(linear.count, 1);
  EXPECT_EQ(linear.t[0], 0.5);
  // A nonzero constant and the zero polynomial have no isolated roots.
  EXPECT_EQ(real_roots_up_to_cubic(1.0, 0.0, 0.0, 0.0, 0.0, 1.0).count, 0);
  EXPECT_EQ(real_roots_up_to_cubic(0.0, 0.0, 0.0, 0.0, 0.0, 1.0).count, 0);
}

}  // namespace
}  // namespace bezier::core
