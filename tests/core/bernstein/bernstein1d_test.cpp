// bernstein::hull_clip (core/bernstein/bernstein1d.hpp): Sederberg and Nishita's convex-hull
// clip of a Bernstein polynomial against a band, against the hull computed in exact rationals;
// bernstein::portion_into and portion_into_fixed (the piece of a polynomial on [a, b]) against
// the blossom values in exact rationals.
#include "core/bernstein/bernstein1d.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "core/numeric/unit_roundoff.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_hull_clip.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using test::exact_hull_clip;
using test::Rational;

TEST(HullClip, IsTheConvexHullOnTheBand) {
  // Points (0, -1), (1/2, 1), (1, -1): the hull meets y in [0, 0] for x in [1/4, 3/4].
  const double c[] = {-1.0, 1.0, -1.0};
  const auto r = bernstein::hull_clip(c, 0.0, 0.0);
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR(r->lo, 0.25, 1e-15);
  EXPECT_NEAR(r->hi, 0.75, 1e-15);
  EXPECT_LE(r->lo, 0.25);
  EXPECT_GE(r->hi, 0.75);
  EXPECT_FALSE(bernstein::hull_clip(c, 1.5, 2.0).has_value());
  const double all_in[] = {0.1, 0.2};
  EXPECT_EQ(*bernstein::hull_clip(all_in, 0.0, 1.0), (ParamInterval{0.0, 1.0}));
}

TEST(HullClip, MatchesTheHullComputedInRationals) {
  // hull_clip tests only the segments and the level each end of the polygon needs; the
  // reference here takes every control point in the band and every segment's crossing of
  // both levels, in exact rationals. Degrees 1-7; some coefficients put exactly on a level,
  // and bands inside, below, above and across the coefficients. The clip must contain the
  // exact hull and exceed it by at most its pad (8 u) plus the rounding of a crossing.
  test::Mulberry32 rng(11);
  const Rational slack(16 * kUnitRoundoff);
  int empty = 0, clipped = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int k = 1 + trial % 7;
    std::vector<double> p(static_cast<std::size_t>(k) + 1);
    for (double& v : p) v = rng.uniform(-1, 1);
    double lo = rng.uniform(-1.2, 1.2), hi = lo + rng.next() * 0.6;
    if (trial % 5 == 0) p[rng.next() < 0.5 ? 0 : static_cast<std::size_t>(k)] = lo;
    if (trial % 7 == 0) p[static_cast<std::size_t>(k) / 2] = hi;
    const auto clip = bernstein::hull_clip(p, lo, hi);
    const bool all_below = std::all_of(p.begin(), p.end(), [&](double v) { return v < lo; });
    const bool all_above = std::all_of(p.begin(), p.end(), [&](double v) { return v > hi; });
    ASSERT_EQ(clip.has_value(), !(all_below || all_above)) << "trial " << trial;
    if (!clip) {
      ++empty;
      continue;
    }
    const auto [exact_lo, exact_hi] = exact_hull_clip(p, Rational(lo), Rational(hi));
    EXPECT_LE(Rational(clip->lo), exact_lo) << "trial " << trial;
    EXPECT_GE(Rational(clip->hi), exact_hi) << "trial " << trial;
    EXPECT_GE(Rational(clip->lo), exact_lo - slack) << "trial " << trial;
    EXPECT_LE(Rational(clip->hi), exact_hi + slack) << "trial " << trial;
    clipped += clip->lo > 0.0 || clip->hi < 1.0;
  }
  EXPECT_GT(empty, 100);
  EXPECT_GT(clipped, 1000);
}

/// The blossom value b(a^(n-i), b^i) of c in exact rationals: n - i de Casteljau rounds
/// with a, then i with b (a blossom is symmetric, so the order does not matter).
Rational exact_blossom(const std::vector<double>& c, std::size_t i, double a, double b) {
  std::vector<Rational> row(c.begin(), c.end());
  const std::size_t n = c.size() - 1;
  for (std::size_t round = 0; round < n; ++round) {
    const Rational t(round < n - i ? a : b);
    for (std::size_t k = 0; k + round < n; ++k) row[k] = (Rational(1) - t) * row[k] + t * row[k + 1];
  }
  return row[0];
}

template <std::size_t E>
void expect_fixed_portion_is_portion(const std::vector<double>& c, double a, double b) {
  std::array<double, E> fixed;
  std::vector<double> any(E);
  bernstein::portion_into_fixed<E>(c.data(), a, b, fixed.data());
  bernstein::portion_into(std::span<const double>(c), a, b, any.data());
  for (std::size_t i = 0; i < E; ++i) EXPECT_EQ(fixed[i], any[i]) << "size " << E << ", i " << i;
}

/// The check above for the size of c, among 1..sizeof...(I) coefficients.
template <std::size_t... I>
void expect_fixed_portions_are_portions(const std::vector<double>& c, double a, double b,
                                        std::index_sequence<I...>) {
  ((c.size() == I + 1 ? expect_fixed_portion_is_portion<I + 1>(c, a, b) : void()), ...);
}

TEST(Portion, IsTheExactPieceWithinItsBound) {
  // Degrees 0-9 on random intervals: every coefficient within 3.01 n u max|c| of the exact
  // blossom value, and the size fixed at compile time gives the same values bit for bit.
  test::Mulberry32 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = static_cast<std::size_t>(trial % 10);
    std::vector<double> c(n + 1);
    for (double& v : c) v = rng.uniform(-1, 1);
    double a = rng.next(), b = rng.next();
    if (a > b) std::swap(a, b);
    std::vector<double> piece(n + 1);
    bernstein::portion_into(std::span<const double>(c), a, b, piece.data());
    const double bound = 3.01 * static_cast<double>(n) * kUnitRoundoff * bernstein::max_abs(c);
    for (std::size_t i = 0; i <= n; ++i) {
      EXPECT_LE(abs(Rational(piece[i]) - exact_blossom(c, i, a, b)), Rational(bound))
          << "degree " << n << ", i " << i;
    }
    expect_fixed_portions_are_portions(c, a, b, std::make_index_sequence<10>{});
  }
}

}  // namespace
}  // namespace bezier::core
