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

TEST(SegmentPiece, EndPiecesAreWhatPortionGivesBitForBit) {
  // Pieces [0, t] and [t, 1], taken as halves of core::subdivide where that is shown to give
  // portion's bits, compared with core::portion over segments with and without zero
  // coordinates (the halving declined where a coordinate is zero).
  test::Mulberry32 rng(910);
  const auto coordinate = [&]() {
    const double u = rng.next();
    if (u < 0.05) return 0.0;
    if (u < 0.1) return -0.0;
    if (u < 0.3) return std::floor(rng.uniform(-4, 4)) / 4;  // cancellations to exact zeros
    return std::ldexp(rng.next() - 0.5, static_cast<int>(rng.next() * 80) - 40);
  };
  int halved_left = 0, halved_right = 0;
  for (int round = 0; round < 4000; ++round) {
    const int degree = 1 + round % 7;
    std::vector<Point2> points;
    for (int i = 0; i <= degree; ++i) points.push_back({coordinate(), coordinate()});
    const Curve c(std::move(points));
    const double t = round % 5 == 0 ? 0.5 : rng.next();
    if (t == 0.0) continue;
    EXPECT_TRUE(same_bits(segment_piece(c, 0.0, t), core::portion(c, 0.0, t))) << "round " << round;
    EXPECT_TRUE(same_bits(segment_piece(c, t, 1.0), core::portion(c, t, 1.0))) << "round " << round;
    Curve left = c, right = c;
    EXPECT_TRUE(same_bits(segment_piece(std::move(left), 0.0, t), core::portion(c, 0.0, t)))
        << "round " << round;
    EXPECT_TRUE(same_bits(segment_piece(std::move(right), t, 1.0), core::portion(c, t, 1.0)))
        << "round " << round;
    const auto [before, after] = segment_pieces_at(c, t);
    EXPECT_TRUE(same_bits(before, core::portion(c, 0.0, t))) << "round " << round;
    EXPECT_TRUE(same_bits(after, core::portion(c, t, 1.0))) << "round " << round;
    if (end_piece_by_halving(c, 0.0, t)) ++halved_left;
    if (end_piece_by_halving(c, t, 1.0)) ++halved_right;
  }
  EXPECT_GT(halved_left, 500);
  EXPECT_GT(halved_right, 500);
}

TEST(SegmentPiece, HalvingIsDeclinedWhereACoordinateIsZero) {
  // A zero in the segment (for [0, t]) or in the piece (for [t, 1]): left to core::portion.
  const Curve with_zero({{-0.0, 1.0}, {2.0, 3.0}, {5.0, -1.0}, {7.0, 2.0}});
  EXPECT_FALSE(end_piece_by_halving(with_zero, 0.0, 0.5));
  EXPECT_TRUE(same_bits(segment_piece(with_zero, 0.0, 0.5), core::portion(with_zero, 0.0, 0.5)));
  // B(1/2) = (1/8)(P0 + 3 P1 + 3 P2 + P3) has x = 0 here: the piece [1/2, 1] starts at x = 0.
  const Curve through_zero({{-4.0, 1.0}, {-4.0, 3.0}, {4.0, -1.0}, {4.0, 2.0}});
  EXPECT_EQ(core::portion(through_zero, 0.5, 1.0)[0].x, 0.0);
  EXPECT_FALSE(end_piece_by_halving(through_zero, 0.5, 1.0));
  EXPECT_TRUE(
      same_bits(segment_piece(through_zero, 0.5, 1.0), core::portion(through_zero, 0.5, 1.0)));
  // Without zeros both ends are halved.
  const Curve plain({{1.0, 1.0}, {2.0, 3.0}, {5.0, -1.0}, {7.0, 2.0}});
  EXPECT_TRUE(end_piece_by_halving(plain, 0.0, 0.25));
  EXPECT_TRUE(end_piece_by_halving(plain, 0.25, 1.0));
  // A middle piece is never halved.
  EXPECT_FALSE(end_piece_by_halving(plain, 0.25, 0.75));
}

TEST(SegmentPiece, AZeroCoordinateKeepsTheSignPortionGivesIt) {
  // -0 in a control point: core::portion may return +0 there; segment_piece returns
  // whatever portion returns.
  const Curve c({{-0.0, 1.0}, {2.0, -0.0}, {3.0, 4.0}});
  EXPECT_TRUE(same_bits(segment_piece(c, 0.0, 1.0), core::portion(c, 0.0, 1.0)));
}

}  // namespace
}  // namespace bezier::region
