// core/region/segment_piece.hpp: the same control points as core::portion, bit for bit
// (signs of zeros included), for whole segments without zero coordinates (returned as they
// are), for whole segments with zeros and for proper pieces (computed by core::portion), also
// through the overload that takes a segment it may move.
#include "core/region/segment_piece.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

#include "core/curve/polar.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::region {
namespace {

using core::Curve;
using core::Point2;

/// The same doubles bit for bit (so +0 and -0 differ).
bool same_bits(const Curve& p, const Curve& q) {
  if (p.degree() != q.degree()) return false;
  for (int i = 0; i <= p.degree(); ++i) {
    if (std::memcmp(&p[i].x, &q[i].x, sizeof(double)) != 0) return false;
    if (std::memcmp(&p[i].y, &q[i].y, sizeof(double)) != 0) return false;
  }
  return true;
}

TEST(SegmentPiece, TheWholeSegmentIsWhatPortionGivesBitForBit) {
  test::Mulberry32 rng(909);
  // Coordinates of every sign and many magnitudes, some of them zero (either sign).
  const auto coordinate = [&]() {
    const double u = rng.next();
    if (u < 0.05) return 0.0;
    if (u < 0.1) return -0.0;
    const double mantissa = rng.next() - 0.5;
    const int exponent = static_cast<int>(rng.next() * 120) - 60;
    return std::ldexp(mantissa, exponent);
  };
  int whole_without_zero = 0;
  for (int round = 0; round < 4000; ++round) {
    const int degree = 1 + round % 10;
    std::vector<Point2> points;
    for (int i = 0; i <= degree; ++i) points.push_back({coordinate(), coordinate()});
    const Curve c(std::move(points));
    EXPECT_TRUE(same_bits(segment_piece(c, 0.0, 1.0), core::portion(c, 0.0, 1.0))) << "round " << round;
    const double a = rng.next(), b = rng.next();
    EXPECT_TRUE(same_bits(segment_piece(c, a, b), core::portion(c, a, b))) << "round " << round;
    // The overload that may take the segment over gives the same bits.
    Curve whole = c, part = c;
    EXPECT_TRUE(same_bits(segment_piece(std::move(whole), 0.0, 1.0), core::portion(c, 0.0, 1.0)))
        << "round " << round;
    EXPECT_TRUE(same_bits(segment_piece(std::move(part), a, b), core::portion(c, a, b)))
        << "round " << round;
    bool zero = false;
    for (const Point2 p : c.points()) zero = zero || p.x == 0.0 || p.y == 0.0;
    if (!zero) {
      ++whole_without_zero;
      EXPECT_TRUE(same_bits(segment_piece(c, 0.0, 1.0), c)) << "round " << round;
    }
  }
  EXPECT_GT(whole_without_zero, 1000);
}

TEST(SegmentPiece, AZeroCoordinateKeepsTheSignPortionGivesIt) {
  // -0 in a control point: core::portion may return +0 there; segment_piece returns
  // whatever portion returns.
  const Curve c({{-0.0, 1.0}, {2.0, -0.0}, {3.0, 4.0}});
  EXPECT_TRUE(same_bits(segment_piece(c, 0.0, 1.0), core::portion(c, 0.0, 1.0)));
}

}  // namespace
}  // namespace bezier::region
