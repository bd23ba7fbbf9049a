// core/intersect/clip/fat_curve.hpp: the fat curve's delta bounds the distance function's
// distance from its reduction, and the hybrid clip keeps every parameter where the distance
// function meets the band. Exact checks in rationals at many sample points.
#include "core/intersect/clip/fat_curve.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::exact_bernstein_value;
using test::Rational;

TEST(FatCurve, DeltaBoundsTheDistanceFunction) {
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
      EXPECT_LE(abs(exact_bernstein_value(a, t) - exact_bernstein_value(p, t)), Rational(fc.delta));
    }
  }
}

TEST(FatCurve, ADegreeAtMostKIsItsOwnFatCurve) {
  const std::vector<double> a = {0.5, -1.0, 2.0};
  const FatCurveOperator op = fat_curve_operator(2, 3);
  EXPECT_EQ(op.k, 2);
  const FatCurve fc = fat_curve(op, a);
  EXPECT_EQ(std::vector<double>(fc.p.begin(), fc.p.end()), a);
  EXPECT_EQ(fc.delta, 0.0);
}

TEST(FatCurve, ClipKeepsEveryParameterWhereTheDistanceIsInTheBand) {
  // Random distance functions of degree 3-8 with an error bound, bands across their range:
  // every sample t where the exact distance function is within the band (widened by the
  // coefficients' error, which the clip must allow for) is kept, and nullopt means no
  // sample is there.
  test::Mulberry32 rng(13);
  int kept_part = 0, inside_samples = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int n = 3 + trial % 6, k = 2 + trial % 2;
    SCOPED_TRACE("trial " + std::to_string(trial));
    DistanceCoefficients d;
    std::vector<double> a(static_cast<std::size_t>(n) + 1);
    for (double& v : a) v = rng.uniform(-1, 1);
    d.a = Coeffs(a);
    d.error = trial % 3 == 0 ? 0.0 : 1e-3 * rng.next();
    const double lo = rng.uniform(-1, 1), hi = lo + 0.2 * rng.next();
    const FatCurveOperator op = fat_curve_operator(n, k);
    const auto kept = fat_curve_clip(op, d, lo, hi);
    if (kept && (kept->lo > 0.0 || kept->hi < 1.0)) ++kept_part;
    const Rational band_lo = Rational(lo) - Rational(d.error), band_hi = Rational(hi) + Rational(d.error);
    for (int j = 0; j <= 128; ++j) {
      const double t = j / 128.0;
      const bool inside = test::exactly_in_band(a, t, band_lo, band_hi);
      if (inside) {
        ++inside_samples;
        ASSERT_TRUE(kept.has_value()) << "t " << t;
        EXPECT_TRUE(kept->contains(t)) << "t " << t << " kept " << kept->lo << " " << kept->hi;
      }
    }
  }
  EXPECT_GT(kept_part, 50);
  EXPECT_GT(inside_samples, 1000);
}

}  // namespace
}  // namespace bezier::core
