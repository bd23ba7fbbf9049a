// core/intersect/clip/subdivision.hpp: the subdivision method's exclusion test never
// separates pieces that hold a crossing built into the curves, and separates pieces that
// certainly do not meet, by their boxes or by a fat line.
#include "core/intersect/clip/subdivision.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/intersect/working_curve.hpp"
#include "tests/core/intersect/clip/piece_of.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::piece_of;

TEST(Subdivision, PiecesHoldingACrossingAreNeverSeparated) {
  // Cubics with control points on the grid of 1/8, so f(1/2) is exact in doubles, and g a
  // cubic through it at s = 1/2 (control points chosen so that g(1/2) = f(1/2) exactly:
  // G3 = 8 f(1/2) - G0 - 3 G1 - 3 G2). Pieces of both around the parameter 1/2, of every
  // width, must stay: their exact curves meet.
  test::Mulberry32 rng(22);
  const auto grid = [&] { return std::floor(rng.uniform(-32, 32)) / 8; };
  for (int trial = 0; trial < 500; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    std::vector<Point2> fp(4), gp(4);
    for (Point2& q : fp) q = {grid(), grid()};
    for (int i = 0; i < 3; ++i) gp[static_cast<std::size_t>(i)] = {grid(), grid()};
    const double mx = fp[0].x + 3 * fp[1].x + 3 * fp[2].x + fp[3].x;
    const double my = fp[0].y + 3 * fp[1].y + 3 * fp[2].y + fp[3].y;
    gp[3] = {mx - gp[0].x - 3 * gp[1].x - 3 * gp[2].x, my - gp[0].y - 3 * gp[1].y - 3 * gp[2].y};
    const Curve f(fp), g(gp);
    const WorkingFrame frame = working_frame(f, g);
    const WorkingCurve wf = to_working(f, frame), wg = to_working(g, frame);
    for (int level = 1; level <= 40; level += 3) {
      const double w = std::ldexp(1.0, -level);
      const double fa = 0.5 - w * rng.next(), fb = 0.5 + w * rng.next();
      const double ga = 0.5 - w * rng.next(), gb = 0.5 + w * rng.next();
      const Separation sep = separation(fast_piece(wf, fa, fb), fast_piece(wg, ga, gb));
      EXPECT_FALSE(sep.separated) << "width 2^-" << level;
    }
  }
}

TEST(Subdivision, DisjointBoxesSeparate) {
  const Separation sep = separation(piece_of({0.0, 1.0, 2.0}, {0.0, 1.0, 0.0}), piece_of({3.0, 4.0}, {0.0, 1.0}));
  EXPECT_TRUE(sep.separated);
  EXPECT_FALSE(sep.noisy);
}

TEST(Subdivision, APieceOutsideTheOtherPiecesFatLineSeparates) {
  // The segment y = x on [0, 2] and the segment y = x + 3/2 from (0, 3/2) to (1/2, 2): their
  // boxes overlap, but the second lies on one side of the first's line, which is its own
  // fat line. Parallel lines: they never meet.
  const Piece diagonal = piece_of({0.0, 2.0}, {0.0, 2.0});
  const Piece above = piece_of({0.0, 0.5}, {1.5, 2.0});
  EXPECT_TRUE(separation(diagonal, above).separated);
  EXPECT_TRUE(separation(above, diagonal).separated);
  // Moved onto the line, the same segment touches it: not separated.
  EXPECT_FALSE(separation(diagonal, piece_of({0.0, 0.5}, {0.0, 0.5})).separated);
}

TEST(Subdivision, CurvesThatCrossStayTogetherAcrossTheirFatLines) {
  // An arch over the x axis from (0, 0) through (1, 1) (control point (1, 2)) to (2, 0) and
  // the line y = 1/2 from (-1, 1/2) to (3, 1/2) cross twice, at x = 1 ± sqrt(1/2).
  EXPECT_FALSE(separation(piece_of({0.0, 1.0, 2.0}, {0.0, 2.0, 0.0}), piece_of({-1.0, 3.0}, {0.5, 0.5})).separated);
  // The line y = 3/2 passes above the arch (its top is y = 1) but inside its control box:
  // the arch's fat line, 0 <= y <= 1 (half the middle control point's height), keeps it out.
  EXPECT_TRUE(separation(piece_of({0.0, 1.0, 2.0}, {0.0, 2.0, 0.0}), piece_of({-1.0, 3.0}, {1.5, 1.5})).separated);
}

}  // namespace
}  // namespace bezier::core
