// core/intersect/clip/implicit_clip.hpp: the clip against the other piece's fat parabola
// never removes a parameter where the pieces meet; a straight other piece gives no
// information.
#include "core/intersect/clip/implicit_clip.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "core/intersect/working_curve.hpp"
#include "tests/core/intersect/clip/piece_of.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::piece_of;
using test::Rational;

TEST(ImplicitClip, KeepsEveryPointNearTheOtherCurve) {
  // x's parameters where x(t) is (exactly) on `other` must be kept: take x through points
  // of `other` and check the clip keeps those parameters.
  test::Mulberry32 rng(9);
  for (int trial = 0; trial < 300; ++trial) {
    const int m = 2 + trial % 3;
    const Curve g = test::random_curve<Point2>(rng, m, -1, 1);
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

TEST(ImplicitClip, KeepsTheExactCrossingsWithAParabola) {
  // other: the parabola y = x^2 on [-1, 1], control points (-1, 1), (0, -1), (1, 1), and
  // the same curve elevated to degree 3, (-1, 1), (-1/3, -1/3), (1/3, -1/3), (1, 1) (the
  // thirds rounded, within the piece's error). x: the line y = 1/4 from x = -2 to 4, as a
  // cubic with control points at x = -2, 0, 2, 4: it meets the parabola at x = -1/2 and
  // 1/2, t = 1/4 and 5/12. Both must be kept.
  const Piece x = piece_of({-2.0, 0.0, 2.0, 4.0}, {0.25, 0.25, 0.25, 0.25}, 0.0);
  const Piece quadratic = piece_of({-1.0, 0.0, 1.0}, {1.0, -1.0, 1.0}, 0.0);
  const Piece cubic = piece_of({-1.0, -1.0 / 3, 1.0 / 3, 1.0}, {1.0, -1.0 / 3, -1.0 / 3, 1.0}, 0x1p-52);
  for (const Piece* other : {&quadratic, &cubic}) {
    const Clip c = implicit_clip(x, *other, fat_curve_operator(other->degree(), 2));
    ASSERT_TRUE(c.kept.has_value());
    EXPECT_LE(Rational(c.kept->lo), Rational(1, 4)) << other->degree();
    EXPECT_GE(Rational(c.kept->hi), Rational(5, 12)) << other->degree();
  }
}

TEST(ImplicitClip, AStraightOtherPieceGivesNoInformation) {
  const Piece x = piece_of({-2.0, 0.0, 2.0}, {0.25, 0.5, 0.25}, 0.0);
  // A line, and a quadratic whose control points lie on one line.
  for (const Piece& other : {piece_of({-1.0, 1.0}, {0.0, 1.0}, 0.0),
                             piece_of({-1.0, 0.0, 1.0}, {0.0, 0.5, 1.0}, 0.0)}) {
    const Clip c = implicit_clip(x, other, fat_curve_operator(other.degree(), 2));
    EXPECT_FALSE(c.informative) << other.degree();
    ASSERT_TRUE(c.kept.has_value());
    EXPECT_EQ(*c.kept, (ParamInterval{0.0, 1.0}));
  }
}

}  // namespace
}  // namespace bezier::core
