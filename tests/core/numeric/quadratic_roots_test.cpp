#include "core/numeric/quadratic_roots.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bezier::core {
namespace {

// c2 (z − r1)(z − r2): c1 = −c2 (r1 + r2), c0 = c2 r1 r2, disc = c2² (r1 − r2)².
RootPair roots_of(double c2, double r1, double r2) {
  return quadratic_roots(c2, -c2 * (r1 + r2), c2 * r1 * r2, c2 * c2 * (r1 - r2) * (r1 - r2));
}

TEST(QuadraticRoots, BuiltFromDyadicRoots) {
  for (const double c2 : {1.0, -2.0, 0.25}) {
    const RootPair r = roots_of(c2, 0.75, -1.5);
    EXPECT_EQ(r.lo, -1.5);
    EXPECT_EQ(r.hi, 0.75);
  }
  const RootPair same = roots_of(4.0, 0.375, 0.375);  // double root, disc = 0
  EXPECT_EQ(same.lo, 0.375);
  EXPECT_EQ(same.hi, 0.375);
}

TEST(QuadraticRoots, SmallRootKeepsFullPrecision) {
  // z² − (1e10 + 1e-10) z + 1 has roots 1e-10 and 1e10; (−c1 − √disc)/2 would lose the
  // small one to cancellation, the stable form takes it as c0 / q.
  const double big = 1e10, small = 1e-10;
  const double c1 = -(big + small);
  const RootPair r = quadratic_roots(1.0, c1, 1.0, c1 * c1 - 4.0);
  EXPECT_NEAR(r.lo, small, 1e-25);
  EXPECT_NEAR(r.hi, big, 1e-5);
}

TEST(QuadraticRoots, SymmetricAndDegenerateCases) {
  const RootPair sym = quadratic_roots(1.0, 0.0, -4.0, 16.0);  // z² − 4
  EXPECT_EQ(sym.lo, -2.0);
  EXPECT_EQ(sym.hi, 2.0);
  const RootPair zero = quadratic_roots(3.0, 0.0, 0.0, 0.0);  // 3 z²: q = 0
  EXPECT_EQ(zero.lo, 0.0);
  EXPECT_EQ(zero.hi, 0.0);
  // A slightly negative discriminant (rounding) is a double root.
  const RootPair clamped = quadratic_roots(1.0, -2.0, 1.0, -1e-30);
  EXPECT_EQ(clamped.lo, 1.0);
  EXPECT_EQ(clamped.hi, 1.0);
}

}  // namespace
}  // namespace bezier::core
