#include "core/path/path_area.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "tests/support/exact.hpp"
#include "tests/support/exact_polynomial.hpp"
#include "tests/support/mulberry32.hpp"
#include "tests/support/parsed_path.hpp"

namespace bezier::path {
namespace {

using test::parsed_path;
using test::Rational;

constexpr double kEps = std::numeric_limits<double>::epsilon();

/// Σ over the closed subpaths of 1/2 ∫ (x y' - x' y) dt of every segment, in rationals
/// through the power form (Green's theorem over a closed chain needs no chords).
Rational exact_closed_area(const Path& path) {
  Rational sum(0);
  for (const Subpath& sub : path.subpaths) {
    if (!sub.closed) continue;
    for (std::size_t k = 0; k < sub.segment_count; ++k) {
      sum = sum + test::exact_green_integral(test::power_form(path.segments[sub.first_segment + k]),
                                             Rational(0), Rational(1));
    }
  }
  return sum;
}

TEST(PathArea, UnitSquareCounterClockwiseIsOne) {
  EXPECT_EQ(closed_area(parsed_path("M0 0 H1 V1 H0 Z")), 1.0);
  EXPECT_EQ(closed_area(parsed_path("M0 0 V1 H1 V0 Z")), -1.0);
}

TEST(PathArea, AChainOfCurvesGivesItsSubpathsAreaBitForBit) {
  // A unit square with a parabolic bulge: 1 + 2/3 * 1 * 0.25 (the parabolic segment over the
  // chord x = 1, its apex at half the control point's distance 0.5); the
  // chain of the same curves, given by address, is the same sum in the same order.
  const Path path = parsed_path("M0 0 H1 Q1.5 0.5 1 1 H0 Z");
  std::vector<const core::Curve*> chain;
  for (const core::Curve& c : path.segments) chain.push_back(&c);
  EXPECT_EQ(closed_chain_area(chain), closed_subpath_area(path, path.subpaths.front()));
  EXPECT_NEAR(closed_chain_area(chain), 1.0 + 1.0 / 6.0, 4 * kEps);
}

TEST(PathArea, HoleOfOppositeOrientationIsSubtracted) {
  // 4x4 square counter-clockwise, 2x2 hole clockwise: 16 - 4.
  EXPECT_EQ(closed_area(parsed_path("M0 0 H4 V4 H0 Z M1 1 V3 H3 V1 Z")), 12.0);
}

TEST(PathArea, OpenSubpathsEncloseNothing) {
  EXPECT_FALSE(closed_area(parsed_path("M0 0 L1 0 L1 1")).has_value());
  EXPECT_EQ(closed_area(parsed_path("M0 0 L1 0 L1 1 M5 5 h2 v2 h-2 z")), 4.0);
}

TEST(PathArea, ParabolicSegmentIsTwoThirdsOfItsBoundingRectangle) {
  // Archimedes: the parabola from (0,0) through its apex (1,1) to (2,0) (control point (1,2))
  // and its chord bound 2/3 of base x height = 4/3; drawn clockwise (up, then back along
  // the x axis), so -4/3.
  const std::optional<double> a = closed_area(parsed_path("M0 0 Q1 2 2 0 Z"));
  ASSERT_TRUE(a);
  EXPECT_NEAR(*a, -4.0 / 3.0, 4 * kEps);
}

TEST(PathArea, RandomPolygonsMatchTheExactShoelace) {
  test::Mulberry32 rng(7);
  for (int round = 0; round < 200; ++round) {
    std::string data = "M";
    const int corners = 3 + static_cast<int>(rng.next() * 12);
    std::vector<test::RPoint2> v;
    for (int k = 0; k < corners; ++k) {
      const double x = std::floor(rng.uniform(-1000, 1000)) / 16;
      const double y = std::floor(rng.uniform(-1000, 1000)) / 16;
      v.push_back({Rational(x), Rational(y)});
      data += k == 0 ? "" : " L";
      data += std::to_string(x);
      data += ' ';
      data += std::to_string(y);
    }
    data += " Z";
    Rational twice(0);
    for (int k = 0; k < corners; ++k) {
      const auto& p = v[static_cast<std::size_t>(k)];
      const auto& q = v[static_cast<std::size_t>((k + 1) % corners)];
      twice = twice + (p.x * q.y - p.y * q.x);
    }
    const Rational exact = twice / Rational(2);
    const std::optional<double> a = closed_area(parsed_path(data));
    ASSERT_TRUE(a);
    // Every corner is a multiple of 1/16 below 64 in magnitude, so every difference, cross
    // product and partial sum of the shoelace formula is a multiple of 2^-8 far below 2^45:
    // all exact in doubles.
    EXPECT_EQ(*a, exact.to_double()) << data;
  }
}

TEST(PathArea, RandomClosedCurvePathsMatchTheExactGreenIntegral) {
  test::Mulberry32 rng(11);
  // A point: two multiples of 1/32 in [-8, 8), then a space.
  const auto point = [&](std::string& out) {
    for (int i = 0; i < 2; ++i) {
      out += std::to_string(std::floor(rng.uniform(-256, 256)) / 32);
      out += ' ';
    }
  };
  for (int round = 0; round < 200; ++round) {
    std::string data = "M";
    point(data);
    const int segments = 1 + static_cast<int>(rng.next() * 8);
    for (int k = 0; k < segments; ++k) {
      const int degree = 1 + static_cast<int>(rng.next() * 3);
      data += degree == 1 ? " L" : degree == 2 ? " Q" : " C";
      for (int i = 0; i < degree; ++i) point(data);
    }
    data += round % 3 == 0 ? " Z M1 1 l2 0 q1 1 -1 2 z" : " Z";
    const Path path = parsed_path(data);
    const double exact = exact_closed_area(path).to_double();
    const std::optional<double> a = closed_area(path);
    ASSERT_TRUE(a);
    // Each term is at most a few times 8^2 and carries a few roundings.
    EXPECT_NEAR(*a, exact, 64 * 8 * 8 * kEps * segments) << data;
  }
}

}  // namespace
}  // namespace bezier::path
