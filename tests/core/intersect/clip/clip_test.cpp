// core/intersect/clip/clip.hpp: the local-to-global map rounds outward, and control boxes
// are disjoint only when the boxes widened by the pieces' error bounds are.
#include "core/intersect/clip/clip.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "tests/core/intersect/clip/piece_of.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::piece_of;
using test::Rational;

TEST(Clip, MapToDomainRoundsOutward) {
  test::Mulberry32 rng(8);
  for (int trial = 0; trial < 10000; ++trial) {
    const double a = rng.next(), b = a + (1 - a) * rng.next();
    const double l = rng.next(), h = l + (1 - l) * rng.next();
    const ParamInterval out = map_to_domain({a, b}, {l, h});
    // The exact images a + (b - a) l and a + (b - a) h must be inside.
    const Rational lo = Rational(a) + (Rational(b) - Rational(a)) * Rational(l);
    const Rational hi = Rational(a) + (Rational(b) - Rational(a)) * Rational(h);
    EXPECT_LE(Rational(out.lo), lo);
    EXPECT_GE(Rational(out.hi), hi);
    EXPECT_GE(out.lo, a);
    EXPECT_LE(out.hi, b);
  }
  EXPECT_EQ(map_to_domain({0.25, 0.5}, {0.0, 1.0}), (ParamInterval{0.25, 0.5}));
}

TEST(Clip, BoundingBoxesDisjointOnlyBeyondTheErrorBounds) {
  // f's control box is [0, 1] x [0, 1]; g's starts at x = 1 + 2^-20 (degrees 3 and 2).
  const Piece f = piece_of({0.0, 1.0, 0.25, 0.5}, {0.0, 0.5, 1.0, 0.0}, 0.0);
  for (const double gap : {0x1p-20, -0x1p-20}) {
    const double x0 = 1.0 + gap;
    // The boxes are 2^-20 apart (or overlap by that much): disjoint only when the error
    // bounds, added on the sides that face each other, still leave a gap, whatever the
    // order of the arguments.
    for (const double error : {0.0, 0x1p-22, 0x1p-21, 0x1p-20}) {
      const Piece g = piece_of({x0, x0 + 1.0, x0 + 0.5}, {0.25, 0.75, 0.5}, error);
      const Piece f_with_error = piece_of({0.0, 1.0, 0.25, 0.5}, {0.0, 0.5, 1.0, 0.0}, error);
      EXPECT_EQ(bounding_boxes_disjoint(f, g), gap > 0 && error < gap) << gap << " " << error;
      EXPECT_EQ(bounding_boxes_disjoint(g, f), gap > 0 && error < gap) << gap << " " << error;
      EXPECT_EQ(bounding_boxes_disjoint(f_with_error, g), gap > 0 && 2 * error < gap)
          << gap << " " << error;
    }
  }
  // Boxes apart in y only.
  const Piece above = piece_of({0.0, 1.0}, {2.0, 3.0}, 0.0);
  EXPECT_TRUE(bounding_boxes_disjoint(f, above));
  EXPECT_FALSE(bounding_boxes_disjoint(f, piece_of({0.0, 1.0}, {1.0, 3.0}, 0.0)));
}

}  // namespace
}  // namespace bezier::core
