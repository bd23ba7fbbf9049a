// Tests of core/self_intersect/refine.hpp on curves whose double points are known in
// closed form:
//   the loop cubic 12 ((2t-1)^2 - 1/4, (2t-1)^3 - (2t-1)/4), control points
//   (9,-9) (-7,13) (-7,-13) (9,9): x(s) = s^2 - 1/4 and y(s) = s x(s) (s = 2t - 1) agree at
//   s = ±1/2, a transversal double point at (t, s) = (1/4, 3/4), B = (0, 0), with
//   B'(1/4) = (-24, 12) and B'(3/4) = (24, 12);
//   the quintic 80 (s^2 - 1/4, s (s^2 - 1/4)^2): both coordinates agree at s = ±1/2 and
//   y' = 0 there, so the branches touch tangentially at (1/4, 3/4), B = (0, 0), with
//   curvatures of opposite sides (y ~ ±x^2 / 4 near the point, scale 80).

#include "core/self_intersect/refine.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace bezier::core {
namespace {

const std::vector<Point2> kLoopCubic{{9, -9}, {-7, 13}, {-7, -13}, {9, 9}};
const std::vector<Point2> kTouchingQuintic{{60, -45}, {-4, 69},  {-36, -89},
                                           {-36, 89}, {-4, -69}, {60, 45}};

// The rounding level self_intersections() uses: 4 (n + 1) u times the largest coordinate.
double rounding_of(const std::vector<Point2>& pts) {
  double s = 0;
  for (const Point2& p : pts) s = std::fmax(s, std::fmax(std::fabs(p.x), std::fabs(p.y)));
  return 4.0 * static_cast<double>(pts.size()) * 0x1p-53 * s;
}

TEST(CurveJet, ExactAtADyadicParameter) {
  // t = 1/4 and 1 - t = 3/4 are exact and every de Casteljau product of these small
  // integers is exact: the jet is the exact one, x = 12 (4t^2 - 4t + 3/4),
  // y = 12 (8t^3 - 12t^2 + 11t/2 - 3/4).
  const CurveJet j = curve_jet(kLoopCubic, 0.25);
  EXPECT_EQ(j.point, (Point2{0, 0}));
  EXPECT_EQ(j.d1, (Point2{-24, 12}));
  EXPECT_EQ(j.d2, (Point2{96, -144}));
  const CurveJet end = curve_jet(kLoopCubic, 1.0);
  EXPECT_EQ(end.point, (Point2{9, 9}));
  EXPECT_EQ(end.d1, (Point2{48, 66}));   // 3 (P3 - P2)
  EXPECT_EQ(end.d2, (Point2{96, 288}));  // 6 (P3 - 2 P2 + P1)
  // A line: the second derivative is zero.
  const std::vector<Point2> line{{1, 2}, {5, -2}};
  const CurveJet l = curve_jet(line, 0.5);
  EXPECT_EQ(l.point, (Point2{3, 0}));
  EXPECT_EQ(l.d1, (Point2{4, -4}));
  EXPECT_EQ(l.d2, (Point2{0, 0}));
}

TEST(RefineDoublePoint, ConvergesToTheClosedFormDoublePoint) {
  const ParameterBox box{{0.0, 0.5}, {0.5, 1.0}};
  const double rounding = rounding_of(kLoopCubic);
  for (const auto& [u0, v0] : {std::pair{0.2, 0.8}, std::pair{0.3, 0.7}, std::pair{0.26, 0.9}}) {
    const PairRefinement r = refine_double_point(kLoopCubic, u0, v0, box, rounding);
    EXPECT_TRUE(r.converged) << u0 << " " << v0;
    EXPECT_NEAR(r.u, 0.25, 0x1p-48);
    EXPECT_NEAR(r.v, 0.75, 0x1p-48);
    EXPECT_LE(r.residual, 1e-9);
    EXPECT_GE(r.iterations, 1);
  }
}

TEST(RefineDoublePoint, StopsWhenTheIterateLeavesTheBox) {
  // The only double point is (1/4, 3/4), outside this box.
  const ParameterBox box{{0.5, 0.6}, {0.9, 1.0}};
  const PairRefinement r =
      refine_double_point(kLoopCubic, 0.55, 0.95, box, rounding_of(kLoopCubic));
  EXPECT_FALSE(r.converged);
}

TEST(DoublePointUncertainty, IsTheStatedFormula) {
  const double rounding = rounding_of(kLoopCubic);
  // B'(1/4) = (-24, 12), B'(3/4) = (24, 12): cross = -576, max length sqrt(720).
  const double expected = rounding * std::sqrt(2.0) * std::sqrt(720.0) / 576.0;
  EXPECT_NEAR(double_point_uncertainty(kLoopCubic, 0.25, 0.75, rounding), expected,
              1e-14 * expected);
  // On the diagonal the tangents are equal: J is singular.
  EXPECT_EQ(double_point_uncertainty(kLoopCubic, 0.4, 0.4, rounding),
            std::numeric_limits<double>::infinity());
}

TEST(IsResolvedDoublePoint, TheLoopIsResolvedTheDiagonalIsNot) {
  const double rounding = rounding_of(kLoopCubic);
  EXPECT_TRUE(is_resolved_double_point(kLoopCubic, 0.25, 0.75, rounding, false));
  EXPECT_FALSE(is_resolved_double_point(kLoopCubic, 0.4, 0.4, rounding, false));
  // A pair far closer together than its uncertainty allows is not resolved.
  EXPECT_FALSE(is_resolved_double_point(kLoopCubic, 0.4, 0.4 + 1e-14, rounding, false));
}

TEST(ParameterSeparation, OpenAndClosed) {
  EXPECT_EQ(parameter_separation(0.25, 0.75, false), 0.5);
  EXPECT_EQ(parameter_separation(0.125, 0.875, false), 0.75);
  EXPECT_EQ(parameter_separation(0.125, 0.875, true), 0.25);
  EXPECT_EQ(parameter_separation(0.25, 0.5, true), 0.25);
}

TEST(RefineSelfContact, FindsTheTangentialContact) {
  const ParameterBox box{{0.0, 0.5}, {0.5, 1.0}};
  for (const auto& [u0, v0] :
       {std::pair{0.24, 0.76}, std::pair{0.26, 0.74}, std::pair{0.2, 0.79}}) {
    const PairRefinement r = refine_self_contact(kTouchingQuintic, u0, v0, box);
    EXPECT_NEAR(r.u, 0.25, 1e-12) << u0 << " " << v0;
    EXPECT_NEAR(r.v, 0.75, 1e-12) << u0 << " " << v0;
    EXPECT_LE(r.residual, 1e-10);
  }
}

TEST(RefineSelfContact, ANearMissEndsAtTheClosestApproachWithItsDistance) {
  // Raising P5 by e adds e t^5 to y: the branch through t = 3/4 (curving up, y ~ x^2/4)
  // rises by e (3/4)^5, the one through t = 1/4 (curving down) by e (1/4)^5, so they no
  // longer touch and their closest approach is the gap e (243 - 1) / 1024 near x = 0.
  std::vector<Point2> pts = kTouchingQuintic;
  const double e = 0x1p-10;
  pts[5].y += e;
  const ParameterBox box{{0.0, 0.5}, {0.5, 1.0}};
  const PairRefinement r = refine_self_contact(pts, 0.25, 0.75, box);
  EXPECT_NEAR(r.residual, e * 242.0 / 1024.0, 0.05 * e * 242.0 / 1024.0);
  EXPECT_NEAR(r.u, 0.25, 1e-3);
  EXPECT_NEAR(r.v, 0.75, 1e-3);
}

}  // namespace
}  // namespace bezier::core
