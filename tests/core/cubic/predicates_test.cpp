#include "core/cubic/predicates.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "tests/support/exact.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using Cubic = std::array<Point2, 4>;
using test::Rational;

CubicPredicates predicates(const Cubic& p) {
  return cubic_predicates(std::span<const Point2, 4>(p));
}
CubicPredicates exact_predicates(const Cubic& p) {
  return cubic_predicates_exact(std::span<const Point2, 4>(p));
}

// The predicates straight from their definitions in the power form, in rationals:
// a = P1 − P0, b = P2 − 2P1 + P0, c = P3 − 3P2 + 3P1 − P0, d1 = a × b, d2 = a × c, d3 = b × c.
struct ExactValues {
  Rational d1, d2, d3, vertex, i1, disc, l0, l1;
};
ExactValues exact_values(const Cubic& p) {
  const test::RPoint2 p0 = test::exact(p[0]), p1 = test::exact(p[1]), p2 = test::exact(p[2]),
                      p3 = test::exact(p[3]);
  const auto cr = [](const test::RPoint2& u, const test::RPoint2& v) {
    return u.x * v.y - u.y * v.x;
  };
  const test::RPoint2 a = p1 - p0;
  const test::RPoint2 b = (p2 - p1) - (p1 - p0);
  const test::RPoint2 c = (p3 - p0) + Rational(3) * (p1 - p2);
  ExactValues v{cr(a, b), cr(a, c), cr(b, c), {}, {}, {}, {}, {}};
  v.vertex = v.d2 + Rational(2) * v.d3;
  v.i1 = v.d1 + v.d2 + v.d3;
  v.disc = v.d2 * v.d2 - Rational(4) * v.d1 * v.d3;
  v.l0 = v.d2 * v.d2 - Rational(3) * v.d1 * v.d3;
  v.l1 = v.d2 * v.d2 + v.d2 * v.d3 + v.d3 * v.d3 - Rational(3) * v.d1 * v.d3;
  return v;
}

void expect_signs_exact(const Cubic& p, const CubicSigns& s) {
  const ExactValues v = exact_values(p);
  EXPECT_EQ(s.d1, v.d1.sign());
  EXPECT_EQ(s.d2, v.d2.sign());
  EXPECT_EQ(s.d3, v.d3.sign());
  EXPECT_EQ(s.d2_plus_2d3, v.vertex.sign());
  EXPECT_EQ(s.i1, v.i1.sign());
  EXPECT_EQ(s.disc, v.disc.sign());
  EXPECT_EQ(s.l0, v.l0.sign());
  EXPECT_EQ(s.l1, v.l1.sign());
}

TEST(CubicPredicates, CanonicalCubicValues) {
  // P0, P1, P2 = (0,0), (0,1), (1,1), P3 = (x, y): d1 = −1, d2 = 3 − x, d3 = x + y − 3 and
  // the edges: disc = x² − 2x + 4y − 3, l0 = x² − 3x + 3y, l1 = x² + xy + y² − 3x.
  const double x = -1.5, y = 0.25;
  const CubicPredicates p = predicates({Point2{0, 0}, Point2{0, 1}, Point2{1, 1}, Point2{x, y}});
  EXPECT_EQ(p.d1, -1);
  EXPECT_EQ(p.d2, 3 - x);
  EXPECT_EQ(p.d3, x + y - 3);
  EXPECT_EQ(p.disc, x * x - 2 * x + 4 * y - 3);
  EXPECT_EQ(p.l0, x * x - 3 * x + 3 * y);
  EXPECT_EQ(p.l1, x * x + x * y + y * y - 3 * x);
  // Canonical numerators: x = x_num / d1, y = y_num / d1.
  EXPECT_EQ(p.x_num / p.d1, x);
  EXPECT_EQ(p.y_num / p.d1, y);
}

TEST(CubicPredicates, SignsAreExactOnRandomAndNearDegenerateInput) {
  test::Mulberry32 rng(61);
  for (int i = 0; i < 3000; ++i) {
    Cubic p;
    for (Point2& q : p) q = {rng.uniform(-1, 1), rng.uniform(-1, 1)};
    switch (i % 5) {
      case 1:  // P1 a few ulps from P0
        p[1] = {std::nextafter(p[0].x, 2.0), std::nextafter(std::nextafter(p[0].y, -2.0), -2.0)};
        break;
      case 2:  // P2 a few ulps from the line P0 P1 (through its midpoint)
        p[2] = {std::nextafter(0.5 * (p[0].x + p[1].x), 2.0), 0.5 * (p[0].y + p[1].y)};
        break;
      case 3:  // P3 a few ulps from P0: nearly closed
        p[3] = {std::nextafter(p[0].x, 2.0), p[0].y};
        break;
      case 4:  // nearly a degree-elevated quadratic: P3 ≈ P0 + 3 (P2 − P1)
        p[3] = p[0] + 3 * (p[2] - p[1]);
        break;
      default:
        break;
    }
    const CubicPredicates fast = predicates(p);
    expect_signs_exact(p, fast.sign);
    expect_signs_exact(p, exact_predicates(p).sign);
    ASSERT_FALSE(testing::Test::HasFailure()) << "cubic " << i;
  }
}

TEST(CubicPredicates, ApproximationsAgreeWithTheirSigns) {
  test::Mulberry32 rng(62);
  for (int i = 0; i < 2000; ++i) {
    Cubic p;
    for (Point2& q : p) q = {rng.uniform(-1, 1), rng.uniform(-1, 1)};
    if (i % 2 == 1) p[2] = 0.5 * (p[1] + p[3]);  // often exactly on an edge, exact path
    for (const CubicPredicates& c : {predicates(p), exact_predicates(p)}) {
      const auto sgn = [](double v) { return (v > 0) - (v < 0); };
      EXPECT_EQ(sgn(c.d1), c.sign.d1);
      EXPECT_EQ(sgn(c.d2), c.sign.d2);
      EXPECT_EQ(sgn(c.d3), c.sign.d3);
      EXPECT_EQ(sgn(c.disc), c.sign.disc);
      EXPECT_EQ(sgn(c.l0), c.sign.l0);
      EXPECT_EQ(sgn(c.l1), c.sign.l1);
    }
  }
}

TEST(CubicPredicates, TranslationAndLinearMapsActByTheDeterminant) {
  // Exact images (coordinates on a 2^-16 grid, dyadic maps): translation changes no sign
  // and no ratio, a linear map multiplies d1, d2, d3 by det and the degree-4 values by det².
  // (The approximations share one power-of-two scale, chosen per input: compare ratios.)
  test::Mulberry32 rng(63);
  const auto same_signs = [](const CubicSigns& a, const CubicSigns& b, int det_sign) {
    EXPECT_EQ(a.d1, det_sign * b.d1);
    EXPECT_EQ(a.d2, det_sign * b.d2);
    EXPECT_EQ(a.d3, det_sign * b.d3);
    EXPECT_EQ(a.d2_plus_2d3, det_sign * b.d2_plus_2d3);
    EXPECT_EQ(a.i1, det_sign * b.i1);
    EXPECT_EQ(a.disc, b.disc);
    EXPECT_EQ(a.l0, b.l0);
    EXPECT_EQ(a.l1, b.l1);
  };
  for (int i = 0; i < 500; ++i) {
    Cubic p;
    for (Point2& q : p)
      q = {std::round(rng.uniform(-4, 4) * 65536) / 65536,
           std::round(rng.uniform(-4, 4) * 65536) / 65536};
    const CubicPredicates base = predicates(p);
    Cubic moved = p;
    for (Point2& q : moved) q = q + Point2{1024.5, -3.25};
    const CubicPredicates t = predicates(moved);
    same_signs(t.sign, base.sign, 1);
    EXPECT_NEAR(t.d2 / t.d1, base.d2 / base.d1, 1e-12 * std::fabs(base.d2 / base.d1));
    EXPECT_NEAR(t.disc / (t.d1 * t.d1), base.disc / (base.d1 * base.d1),
                1e-12 * std::fabs(base.disc / (base.d1 * base.d1)));
    // Reflection x -> −x with y -> 2y: det = −2.
    Cubic mapped = p;
    for (Point2& q : mapped) q = {-q.x, 2 * q.y};
    same_signs(predicates(mapped).sign, base.sign, -1);
    const ExactValues v = exact_values(p), w = exact_values(mapped);
    EXPECT_EQ(w.d1, Rational(-2) * v.d1);
    EXPECT_EQ(w.l1, Rational(4) * v.l1);
  }
}

TEST(CubicPredicates, AllPointsAtTheOriginGiveZero) {
  const CubicPredicates p = predicates({Point2{}, Point2{}, Point2{}, Point2{}});
  EXPECT_EQ(p.sign.d1, 0);
  EXPECT_EQ(p.sign.disc, 0);
  EXPECT_EQ(p.sign.l1, 0);
  EXPECT_TRUE(p.exact);
}

TEST(CubicPredicates, HugeAndTinyCoordinates) {
  // Coordinates near the top of the double range: differences would overflow unscaled.
  const Cubic big = {Point2{-0x1p1023, 0}, Point2{0x1p1023, 0x1p1022}, Point2{0, 0x1p1023},
                     Point2{0x1p1022, -0x1p1023}};
  expect_signs_exact(big, predicates(big).sign);
  // Subnormal-free tiny coordinates.
  Cubic tiny = big;
  for (Point2& q : tiny) q = {std::ldexp(q.x, -2000), std::ldexp(q.y, -2000)};
  expect_signs_exact(tiny, predicates(tiny).sign);
  EXPECT_TRUE(predicates(tiny).exact);
}

}  // namespace
}  // namespace bezier::core
