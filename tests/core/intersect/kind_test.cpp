// The classification of an intersection by its derivatives (kind.hpp). Expected values from
// closed forms: the sine of the angle between two vectors, and the thresholds' definitions
// (a derivative is zero below zero_derivative times its scale, the curves touch below
// tangent_sine).

#include "core/intersect/kind.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bezier::core {
namespace {

TEST(SineBetween, ClosedForms) {
  EXPECT_EQ(sine_between({1.0, 0.0}, {0.0, 1.0}), 1.0);     // perpendicular
  EXPECT_EQ(sine_between({2.0, 0.0}, {-5.0, 0.0}), 0.0);    // opposite directions
  EXPECT_EQ(sine_between({0.0, 0.0}, {1.0, 1.0}), 0.0);     // a zero vector
  // (3, 4) and (4, 3): |a x b| = |9 - 16| = 7, |a| |b| = 25.
  // A handful of roundings, each at most u = 2^-53 relative.
  EXPECT_NEAR(sine_between({3.0, 4.0}, {4.0, 3.0}), 7.0 / 25.0, 8 * 0x1p-53);
  // The sine is the same whatever the vectors' lengths (powers of two scale exactly).
  EXPECT_EQ(sine_between({3.0, 4.0}, {4.0, 3.0}), sine_between({0x3p-40, 0x4p-40}, {0x4p30, 0x3p30}));
}

TEST(ClassifyIntersection, CrossingAtAnAngleIsTransversal) {
  EXPECT_EQ(classify_intersection({1.0, 0.0}, {1.0, 1.0}, 1.0, 1.0),
            IntersectionKind::transversal);
}

TEST(ClassifyIntersection, ParallelNonzeroDerivativesAreATangency) {
  EXPECT_EQ(classify_intersection({2.0, 1.0}, {-4.0, -2.0}, 4.0, 4.0), IntersectionKind::tangent);
}

TEST(ClassifyIntersection, AZeroDerivativeIsDegenerate) {
  EXPECT_EQ(classify_intersection({0.0, 0.0}, {1.0, 0.0}, 1.0, 1.0), IntersectionKind::degenerate);
  EXPECT_EQ(classify_intersection({1.0, 0.0}, {0.0, 0.0}, 1.0, 1.0), IntersectionKind::degenerate);
}

TEST(ClassifyIntersection, ThresholdsAreRelativeToTheScales) {
  const KindTolerances tol;
  // A derivative at a quarter of the zero threshold of its scale is zero; at four times the
  // threshold it is not.
  const double scale = 0x1p20;
  EXPECT_EQ(classify_intersection({0.25 * tol.zero_derivative * scale, 0.0}, {0.0, 1.0}, scale,
                                  1.0, tol),
            IntersectionKind::degenerate);
  EXPECT_EQ(classify_intersection({4.0 * tol.zero_derivative * scale, 0.0}, {0.0, 1.0}, scale,
                                  1.0, tol),
            IntersectionKind::transversal);
  // Directions whose angle has sine tan(a) ~ a: a quarter of tangent_sine touches, four
  // times it crosses (the vectors (1, a) and (1, 0), sine a / sqrt(1 + a^2)).
  const double below = 0.25 * tol.tangent_sine, above = 4.0 * tol.tangent_sine;
  EXPECT_EQ(classify_intersection({1.0, below}, {1.0, 0.0}, 1.0, 1.0, tol),
            IntersectionKind::tangent);
  EXPECT_EQ(classify_intersection({1.0, above}, {1.0, 0.0}, 1.0, 1.0, tol),
            IntersectionKind::transversal);
}

}  // namespace
}  // namespace bezier::core
