// core/intersect/clip/fat_line.hpp: the fat line holds the exact piece, the distance
// coefficients are within their error of the exact control points' distances, and a piece
// that is a point takes its line's direction from the other piece. Exact checks in
// rationals.
#include "core/intersect/clip/fat_line.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/intersect/working_curve.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::Rational;

/// N · (p - O) exactly.
Rational exact_distance(const FatLine& line, const test::RPoint2& p) {
  return Rational(line.normal.x) * (p.x - Rational(line.origin.x)) +
         Rational(line.normal.y) * (p.y - Rational(line.origin.y));
}

/// The exact control points of the working curve w, shifted by -shift.
std::vector<test::RPoint2> exact_working_points(const WorkingCurve& w, Point2 shift) {
  std::vector<test::RPoint2> pts;
  for (std::size_t i = 0; i < w.x.size(); ++i) {
    pts.push_back({Rational(w.x[i]) + Rational(w.x_lo[i]) - Rational(shift.x),
                   Rational(w.y[i]) + Rational(w.y_lo[i]) - Rational(shift.y)});
  }
  return pts;
}

TEST(FatLine, HoldsTheExactPiece) {
  test::Mulberry32 rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE("seed 5 trial " + std::to_string(trial));
    const int n = 1 + trial % 5;
    const Curve c = test::random_curve<Point2>(rng, n, -1, 1);
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
      const Rational d = exact_distance(line, test::exact_evaluate(exact_working_points(w, shift), t));
      EXPECT_LE(Rational(line.d_min), d);
      EXPECT_LE(d, Rational(line.d_max));
    }
  }
}

TEST(FatLine, DistanceCoefficientsAreWithinTheirErrorOfTheExactPiece) {
  // The control points of f on [a, b] are its blossom at (a^(n-i), b^i): their exact
  // distances from the line are the exact distance function's Bernstein coefficients.
  test::Mulberry32 rng(12);
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE("seed 12 trial " + std::to_string(trial));
    const int n = 1 + trial % 6;
    const Curve f = test::random_curve<Point2>(rng, n, -1, 1);
    const Curve g = test::random_curve<Point2>(rng, 3, -1, 1);
    const WorkingFrame frame = working_frame(f, g);
    const WorkingCurve wf = to_working(f, frame), wg = to_working(g, frame);
    const double a = rng.next() * 0.5, b = a + rng.next() * 0.5;
    const Piece piece = fast_piece(wf, a, b);
    const FatLine line = fat_line(fast_piece(wg, 0.0, 1.0), piece);
    const DistanceCoefficients d = distance_coefficients(line, piece);
    ASSERT_EQ(d.a.size(), static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) {
      std::vector<Rational> us(static_cast<std::size_t>(n - i), Rational(a));
      us.insert(us.end(), static_cast<std::size_t>(i), Rational(b));
      const test::RPoint2 control = test::exact_polar(exact_working_points(wf, {0, 0}), us).front();
      const Rational error = abs(exact_distance(line, control) - Rational(d.a[static_cast<std::size_t>(i)]));
      EXPECT_LE(error, Rational(d.error)) << "i = " << i;
    }
  }
}

TEST(FatLine, APointTakesItsDirectionFromTheOtherPiece) {
  // g is one point; the other piece's chord is c = (3, 4). For a line across the other
  // piece the normal runs along c (N · c = ±|c|^2, with |N| = |c|); for a line along it the
  // normal is perpendicular to c (N · c = 0).
  Piece point;
  point.x = Coeffs(std::vector<double>{0.5, 0.5, 0.5});
  point.y = Coeffs(std::vector<double>{0.25, 0.25, 0.25});
  point.error = 0x1p-50;
  Piece other;
  other.x = Coeffs(std::vector<double>{0.0, 1.0, 3.0});
  other.y = Coeffs(std::vector<double>{0.0, -1.0, 4.0});
  EXPECT_TRUE(is_point_like(point));
  EXPECT_FALSE(is_point_like(other));
  const FatLine across = fat_line(point, other, PointLineDirection::across_other);
  const FatLine along = fat_line(point, other, PointLineDirection::along_other);
  const double across_dot = across.normal.x * 3 + across.normal.y * 4;
  const double along_dot = along.normal.x * 3 + along.normal.y * 4;
  EXPECT_EQ(std::abs(across_dot), 25.0);
  EXPECT_EQ(along_dot, 0.0);
  // The band holds the point itself, and is no wider than its error margins.
  for (const FatLine& line : {across, along}) {
    EXPECT_LE(line.d_min, 0.0);
    EXPECT_GE(line.d_max, 0.0);
    EXPECT_LE(line.d_max - line.d_min, 2 * line.margin);
  }
}

TEST(FatLine, IsPointLikeWithinFourTimesTheErrorBound) {
  Piece p;
  p.x = Coeffs(std::vector<double>{1.0, 1.0 + 0x1p-40});
  p.y = Coeffs(std::vector<double>{2.0, 2.0});
  p.error = 0x1p-42;  // 4 error = 2^-40: the spread is exactly at the limit
  EXPECT_TRUE(is_point_like(p));
  p.error = 0x1p-43;
  EXPECT_FALSE(is_point_like(p));
}

}  // namespace
}  // namespace bezier::core
