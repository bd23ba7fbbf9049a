// core/intersect/clip/implicit_cubic_clip.hpp: the clip against a cubic's own implicit
// equation never removes a parameter where the pieces meet, and parts cubics that run a
// tiny distance apart along their whole length, which a fat parabola cannot.
#include "core/intersect/clip/implicit_cubic_clip.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "core/intersect/intersect.hpp"
#include "core/intersect/working_curve.hpp"
#include "tests/core/intersect/clip/piece_of.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::piece_of;
using test::Rational;

/// The cubic quarter of the circle of radius r about (cx, 0) from angle 0 to 90 degrees
/// (the usual handle length 0.5522847498 r).
Curve quarter(double cx, double r) {
  const double k = 0.5522847498307936 * r;
  return Curve({{cx + r, 0.0}, {cx + r, k}, {cx + k, r}, {cx, r}});
}

TEST(ImplicitCubicClip, KeepsEveryParameterOfAPieceOfTheCubicItself) {
  // x is a piece of `other` (so every x(t) is on it, up to the pieces' rounding, which
  // their error bounds cover): nothing may be clipped.
  test::Mulberry32 rng(21);
  for (int trial = 0; trial < 300; ++trial) {
    const Curve g = test::random_curve<Point2>(rng, 3, -1, 1);
    const WorkingFrame frame = working_frame(g, g);
    const WorkingCurve wg = to_working(g, frame);
    const Piece other = fast_piece(wg, 0.0, 1.0);
    double a = rng.next(), b = rng.next();
    if (a > b) std::swap(a, b);
    const Piece x = fast_piece(wg, a, b);
    const Clip c = implicit_cubic_clip(x, other);
    ASSERT_TRUE(c.kept.has_value()) << trial;
    EXPECT_EQ(c.kept->lo, 0.0) << trial;
    EXPECT_EQ(c.kept->hi, 1.0) << trial;
  }
}

TEST(ImplicitCubicClip, KeepsTheExactCrossingOfALine) {
  // other: (t, t^3), control points (0, 0), (1/3, 0), (2/3, 0), (1, 1) (the thirds rounded,
  // within the piece's error). x: the line y = 1/8 from x = 0 to 1, which meets it at
  // x = 1/2, its own t = 1/2; and y = 27/64, meeting at x = 3/4.
  const Piece other = piece_of({0.0, 1.0 / 3, 2.0 / 3, 1.0}, {0.0, 0.0, 0.0, 1.0}, 0x1p-53);
  for (const auto& [level, crossing] : {std::pair{0.125, Rational(1, 2)}, std::pair{27.0 / 64, Rational(3, 4)}}) {
    const Piece x = piece_of({0.0, 1.0}, {level, level}, 0.0);
    const Clip c = implicit_cubic_clip(x, other);
    ASSERT_TRUE(c.kept.has_value()) << level;
    EXPECT_LE(Rational(c.kept->lo), crossing) << level;
    EXPECT_GE(Rational(c.kept->hi), crossing) << level;
  }
}

TEST(ImplicitCubicClip, PartsConcentricQuartersATinyDistanceApart) {
  // Two concentric circles of radii 1 and 1 + d do not meet; their cubic quarters (the
  // second the first scaled by 1 + d, rounded within the piece's error) stay about d apart
  // along their whole length. The clip must see that at once, for d down to 2^-36.
  for (const int e : {20, 28, 36}) {
    const double d = std::ldexp(1.0, -e);
    const Curve inner = quarter(0.0, 1.0);
    const Piece other = piece_of({inner[0].x, inner[1].x, inner[2].x, inner[3].x},
                                 {inner[0].y, inner[1].y, inner[2].y, inner[3].y}, 0.0);
    std::vector<double> xs, ys;
    for (const Point2 p : inner.points()) {
      xs.push_back(p.x * (1 + d));
      ys.push_back(p.y * (1 + d));
    }
    const Piece x = piece_of(xs, ys, 0x1p-52);
    EXPECT_FALSE(implicit_cubic_clip(x, other).kept.has_value()) << e;
    EXPECT_FALSE(implicit_cubic_clip(other, x).kept.has_value()) << e;
  }
}

TEST(ImplicitCubicClip, AQuarterAndItsCopyMovedATinyDistanceAreSeparatedWithinAFewMillionUnits) {
  // The quarter C and C + (d, 0): a common point needs C(t) - C(s) = (d, 0), so equal y, and
  // y rises along the quarter (its control ordinates 0, k, r, r), so t = s and the
  // difference is 0, not d. They do not meet; the search must say so (no intersection, no
  // overlap) within a work cap of 3e6 units (a fat parabola alone parts them only in boxes
  // about d^(1/3) wide, thousands of them), for gaps of 1e-10 and 1e-11 on a radius of 5.
  IntersectOptions options;
  options.max_work = 3'000'000;
  for (const double d : {1e-10, 1e-11}) {
    const IntersectionResult r = intersect(quarter(0.0, 5.0), quarter(d, 5.0), options);
    EXPECT_EQ(r.status, IntersectStatus::ok) << d;
    EXPECT_TRUE(r.intersections.empty()) << d;
    EXPECT_TRUE(r.overlaps.empty()) << d;
  }
}

TEST(ImplicitCubicClip, ACopyScaledAboutTheCommonStartIsSolvedWithinAFewMillionUnits) {
  // S(t) = (9t + 3t^2 - 2t^3, 15t - 45t^2 + 30t^3) (control points (0,0), (3,5), (7,-5),
  // (10,0)) and (1 + e) S, e = 2^-30 (exact). They meet at the common start, touching, and
  // near where S's tangent passes through the origin, cross(S, S') = 0, which is t = 3/4
  // exactly (both factors of cross / t equal -18.984375 there); the crossing moves by O(e).
  // Near the common start the gap vanishes and no implicit band parts the pieces: the
  // cubic clip must not spend the budget retrying there.
  const Curve s({{0, 0}, {3, 5}, {7, -5}, {10, 0}});
  const double e = 0x1p-30;
  const Curve scaled({{0, 0}, {3 * (1 + e), 5 * (1 + e)}, {7 * (1 + e), -5 * (1 + e)}, {10 * (1 + e), 0}});
  IntersectOptions options;
  options.max_work = 4'000'000;
  const IntersectionResult r = intersect(s, scaled, options);
  ASSERT_EQ(r.status, IntersectStatus::ok);
  ASSERT_EQ(r.intersections.size(), 2u);
  EXPECT_EQ(r.intersections[0].t, 0.0);
  EXPECT_EQ(r.intersections[0].s, 0.0);
  EXPECT_NEAR(r.intersections[1].t, 0.75, 1e-6);
  EXPECT_NEAR(r.intersections[1].s, 0.75, 1e-6);
}

TEST(ImplicitCubicClip, TheCrossingOfTwoCirclesANearDistanceApartIsFound) {
  // The circles of radius 5 about (0, 0) and (1e-10, 0) cross on the line x = 5e-11, in the
  // first's quarter from 0 to 90 degrees and the second's from 90 to 180 degrees (the first
  // quarter mirrored in the y-axis, reversed, and moved by 1e-10). The reflection in
  // x = 5e-11 maps each of the two onto the other with the parameter reversed, so they meet
  // once, with t + s = 1 and x = 5e-11, to the tolerance.
  const Curve q = quarter(0.0, 5.0);
  const double d = 1e-10;
  const Curve second({{d - q[3].x, q[3].y}, {d - q[2].x, q[2].y}, {d - q[1].x, q[1].y}, {d - q[0].x, q[0].y}});
  const IntersectionResult r = intersect(q, second);
  ASSERT_EQ(r.status, IntersectStatus::ok);
  ASSERT_EQ(r.intersections.size(), 1u);
  const Intersection& i = r.intersections[0];
  EXPECT_NEAR(i.t + i.s, 1.0, 1e-9);
  EXPECT_NEAR(i.point.x, 5e-11, 1e-11);
  EXPECT_NEAR(i.point.y, 5.0, 1e-9);
}

}  // namespace
}  // namespace bezier::core
