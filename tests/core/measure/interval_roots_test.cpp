// core/measure/interval_roots.hpp, its contract: every root of the polynomial in [a, b] (or
// (a, b)) once, ascending, each as accurately as p's rounding determines it; exact zeros at
// the ends and at split points; only rising crossings when asked. The polynomials are built
// from their roots: p(t) = k Π (t - r_i) in Bernstein form, computed in exact rationals and
// rounded once.
#include "core/measure/interval_roots.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/numeric/unit_roundoff.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_bezier.hpp"

namespace bezier::core {
namespace {

using test::Rational;

/// k Π (t - r) over `roots` in Bernstein form: the product of the degree-1 factors
/// [-r, 1 - r] in rationals, each coefficient rounded once.
std::vector<double> from_roots(const std::vector<double>& roots, double k = 1.0) {
  test::BernsteinPoly p = {Rational(k)};
  for (const double r : roots) p = test::exact_bernstein_product(p, {-Rational(r), Rational(1) - Rational(r)});
  std::vector<double> c;
  for (const Rational& v : p) c.push_back(v.to_double());
  return c;
}

/// The roots found, as a vector.
std::vector<double> roots_of(const IntervalRoots& r) {
  return std::vector<double>(r.roots.begin(), r.roots.end());
}

/// How far a computed simple root r_i may be from the true one: the coefficients' rounding
/// (u max|c|, once each) moves the root by at most that over |p'(r_i)|, and the contract
/// puts the computed root within about e / |p'| of the rounded polynomial's, e = 3.02 n u
/// max|c|; twice their sum, plus an ulp of t.
double accuracy(const std::vector<double>& c, const std::vector<double>& roots, std::size_t i, double k) {
  double max_c = 0.0;
  for (const double v : c) max_c = std::max(max_c, std::fabs(v));
  const double n = static_cast<double>(c.size() - 1);
  double slope = std::fabs(k);
  for (std::size_t j = 0; j < roots.size(); ++j) {
    if (j != i) slope *= std::fabs(roots[i] - roots[j]);
  }
  return 2 * (3.02 * n + 1) * kUnitRoundoff * max_c / slope + 2 * kUnitRoundoff;
}

TEST(IntervalRoots, EverySimpleRootOnceAscendingAndAccurate) {
  for (const std::vector<double>& roots : std::vector<std::vector<double>>{
           {0.3}, {0.125, 0.875}, {0.1, 0.35, 0.6, 0.85}, {0.01, 0.02, 0.45, 0.97, 0.99},
           {0.05, 0.15, 0.26, 0.35, 0.45, 0.55, 0.65, 0.74, 0.85, 0.95}}) {
    for (const double k : {1.0, -3.0, 1e-200, 1e200}) {
      SCOPED_TRACE(std::to_string(roots.size()) + " roots, k = " + std::to_string(k));
      const std::vector<double> c = from_roots(roots, k);
      const IntervalRoots r = interval_roots(c, 0.0, 1.0, IntervalEnds::closed);
      ASSERT_EQ(r.roots.size(), roots.size());
      EXPECT_TRUE(r.isolated);
      for (std::size_t i = 0; i < roots.size(); ++i) EXPECT_NEAR(r.roots[i], roots[i], accuracy(c, roots, i, k));
      EXPECT_TRUE(std::is_sorted(r.roots.begin(), r.roots.end()));
    }
  }
}

TEST(IntervalRoots, ASimpleRootOnASplitPointWithinTheLastPiece) {
  // Ten roots put 1/4 and 3/4 (roots here) on split points while their pieces still hold
  // several roots; p rounds to a tiny nonzero value there, and such a root is reported at
  // the middle of its last piece, 2^-41 from its ends: within that and the rounding.
  const std::vector<double> roots = {0.05, 0.15, 0.25, 0.35, 0.45, 0.55, 0.65, 0.75, 0.85, 0.95};
  const std::vector<double> c = from_roots(roots);
  const IntervalRoots r = interval_roots(c, 0.0, 1.0, IntervalEnds::closed);
  ASSERT_EQ(r.roots.size(), roots.size());
  for (std::size_t i = 0; i < roots.size(); ++i) {
    EXPECT_NEAR(r.roots[i], roots[i], 0x1p-41 + accuracy(c, roots, i, 1.0)) << i;
  }
}

TEST(IntervalRoots, OnlyTheRootsInsideTheInterval) {
  // Roots -1/2, 1/4, 0.6, 3/2 and 2: on [0, 1] two; on [0.3, 0.9] one; on [0.7, 1] none.
  const std::vector<double> roots = {-0.5, 0.25, 0.6, 1.5, 2.0};
  const std::vector<double> c = from_roots(roots);
  const IntervalRoots all = interval_roots(c, 0.0, 1.0, IntervalEnds::closed);
  ASSERT_EQ(all.roots.size(), 2u);
  EXPECT_NEAR(all.roots[0], 0.25, accuracy(c, roots, 1, 1.0));
  EXPECT_NEAR(all.roots[1], 0.6, accuracy(c, roots, 2, 1.0));
  const IntervalRoots middle = interval_roots(c, 0.3, 0.9, IntervalEnds::closed);
  ASSERT_EQ(middle.roots.size(), 1u);
  EXPECT_NEAR(middle.roots[0], 0.6, accuracy(c, roots, 2, 1.0));
  EXPECT_TRUE(interval_roots(c, 0.7, 1.0, IntervalEnds::closed).roots.empty());
}

TEST(IntervalRoots, ExactZerosAtTheEndsCountOnlyForClosedEnds) {
  // 3 (t - 1/4)(t - 1/2)(t - 3/4) has the Bernstein coefficients -9/32, 13/32, -13/32, 9/32
  // (exact in doubles), and de Casteljau's steps at 1/4, 1/2 and 3/4 are exact too: p is
  // exactly zero there.
  const std::vector<double> c = {-9.0 / 32, 13.0 / 32, -13.0 / 32, 9.0 / 32};
  ASSERT_EQ(c, from_roots({0.25, 0.5, 0.75}, 3.0));
  const IntervalRoots closed = interval_roots(c, 0.25, 0.75, IntervalEnds::closed);
  EXPECT_EQ(roots_of(closed), (std::vector<double>{0.25, 0.5, 0.75}));
  EXPECT_TRUE(closed.isolated);
  const IntervalRoots open = interval_roots(c, 0.25, 0.75, IntervalEnds::open);
  EXPECT_EQ(roots_of(open), (std::vector<double>{0.5}));
  EXPECT_TRUE(open.isolated);
  // [1/2, 1]: the root at its start, and 3/4.
  EXPECT_EQ(roots_of(interval_roots(c, 0.5, 1.0, IntervalEnds::closed)), (std::vector<double>{0.5, 0.75}));
  EXPECT_EQ(roots_of(interval_roots(c, 0.5, 1.0, IntervalEnds::open)), (std::vector<double>{0.75}));
  // A point interval holds its point when p is zero there.
  EXPECT_EQ(roots_of(interval_roots(c, 0.5, 0.5, IntervalEnds::closed)), (std::vector<double>{0.5}));
  EXPECT_TRUE(interval_roots(c, 0.4, 0.4, IntervalEnds::closed).roots.empty());
}

TEST(IntervalRoots, AnExactZeroAtASplitPointIsOneIsolatedRoot) {
  // Antisymmetric coefficients (c_i = -c_(n-i)) make p(1 - t) = -p(t), and de Casteljau at
  // 1/2 keeps the symmetry exactly (each average of x and -y is minus that of -x and y), so
  // p(1/2) evaluates to exactly zero, at the first split of [0, 1]. 6 (t - 1/3)(t - 1/2)
  // (t - 2/3), its coefficients made exactly antisymmetric, is such a polynomial, with two
  // more roots that are not split points.
  const std::vector<double> roots = {1.0 / 3, 0.5, 2.0 / 3};
  std::vector<double> c = from_roots(roots, 6.0);
  for (std::size_t i = 0; i < c.size() / 2; ++i) c[c.size() - 1 - i] = -c[i];
  const IntervalRoots r = interval_roots(c, 0.0, 1.0, IntervalEnds::closed);
  ASSERT_EQ(r.roots.size(), 3u);
  EXPECT_TRUE(r.isolated);
  EXPECT_EQ(r.roots[1], 0.5);
  EXPECT_NEAR(r.roots[0], 1.0 / 3, accuracy(c, roots, 0, 6.0));
  EXPECT_NEAR(r.roots[2], 2.0 / 3, accuracy(c, roots, 2, 6.0));
}

TEST(IntervalRoots, RisingCrossingsOnly) {
  // (t - 0.2)(t - 0.45)(t - 0.8) rises through 0.2 and 0.8 and falls through 0.45 (none of
  // them a split point, where a root whose p rounds to a tiny value counts either way).
  const std::vector<double> roots = {0.2, 0.45, 0.8};
  const std::vector<double> c = from_roots(roots);
  const IntervalRoots any = interval_roots(c, 0.0, 1.0, IntervalEnds::closed, Crossings::any);
  ASSERT_EQ(any.roots.size(), 3u);
  const IntervalRoots rising = interval_roots(c, 0.0, 1.0, IntervalEnds::closed, Crossings::rising);
  ASSERT_EQ(rising.roots.size(), 2u);
  EXPECT_NEAR(rising.roots[0], 0.2, accuracy(c, roots, 0, 1.0));
  EXPECT_NEAR(rising.roots[1], 0.8, accuracy(c, roots, 2, 1.0));
  // -p rises where p falls.
  std::vector<double> minus = c;
  for (double& v : minus) v = -v;
  const IntervalRoots falling = interval_roots(minus, 0.0, 1.0, IntervalEnds::closed, Crossings::rising);
  ASSERT_EQ(falling.roots.size(), 1u);
  EXPECT_NEAR(falling.roots[0], 0.45, accuracy(c, roots, 1, 1.0));
}

/// A root of p and its multiplicity.
struct Root {
  double at;
  int multiplicity;
};

/// The roots with their multiplicities, one entry per factor (t - r), for from_roots.
std::vector<double> factors(const std::vector<Root>& roots) {
  std::vector<double> out;
  for (const Root& r : roots) out.insert(out.end(), static_cast<std::size_t>(r.multiplicity), r.at);
  return out;
}

/// How far the point reported for root i of multiplicity m may be from it: the contract puts
/// it where the rounded polynomial's computed |p| is within e = 3.02 n u max|c|, so the exact
/// |p| there is within 2e, and the coefficients' rounding (u max|c| at most) adds less than
/// e more: |p(t)| <= 3e. Near the root p(t) = L (t - r_i)^m (1 + O(t - r_i)) with
/// L = k Π_(j != i) (r_i - r_j)^(m_j), so |t - r_i| <= (3e / |L|)^(1/m), doubled for the
/// higher terms, plus an ulp of t.
double cluster_accuracy(const std::vector<double>& c, const std::vector<Root>& roots, std::size_t i, double k) {
  double max_c = 0.0;
  for (const double v : c) max_c = std::max(max_c, std::fabs(v));
  const double e = 3.02 * static_cast<double>(c.size() - 1) * kUnitRoundoff * max_c;
  double leading = std::fabs(k);
  for (std::size_t j = 0; j < roots.size(); ++j) {
    if (j != i) leading *= std::pow(std::fabs(roots[i].at - roots[j].at), roots[j].multiplicity);
  }
  return 2 * std::pow(3 * e / leading, 1.0 / roots[i].multiplicity) + 2 * kUnitRoundoff;
}

TEST(IntervalRoots, EveryMultipleRootOnce) {
  // Double and triple roots on split points (1/2, 1/4, 3/8), off them (0.3, 0.7, 0.55) and
  // near the ends, with simple roots beside them. Each is one flat stretch of p, reported
  // once within its multiplicity's accuracy, whatever the crossings wanted and the ends
  // counted: the roots are inside (0, 1), and a multiple root is a cluster, which `rising`
  // keeps (a piece with one sign change holds at most one root counted with multiplicity).
  const std::vector<std::vector<Root>> cases = {
      {{0.3, 2}, {0.8, 1}},
      {{0.5, 2}},
      {{0.5, 3}},
      {{0.25, 2}, {0.75, 1}},
      {{0.25, 3}, {0.6, 1}},
      {{0.375, 2}, {0.6, 1}, {0.875, 3}},
      {{0.7, 3}, {0.2, 1}},
      {{0.002, 2}, {0.55, 1}, {0.998, 3}},
      {{0.001, 3}, {0.4, 2}, {0.999, 2}},
      {{0.1, 1}, {0.3, 2}, {0.55, 3}, {0.8, 2}, {0.95, 1}},
  };
  for (const std::vector<Root>& roots : cases) {
    for (const double k : {1.0, -3.0}) {
      const std::vector<double> c = from_roots(factors(roots), k);
      for (const Crossings wanted : {Crossings::any, Crossings::rising}) {
        for (const IntervalEnds ends : {IntervalEnds::closed, IntervalEnds::open}) {
          // The roots expected: all, or the multiple ones and the simple ones where p rises
          // (p' = k Π_(j != i) (r_i - r_j)^(m_j) > 0 there).
          std::vector<std::size_t> expected;
          for (std::size_t i = 0; i < roots.size(); ++i) {
            double slope = k;
            for (std::size_t j = 0; j < roots.size(); ++j) {
              if (j != i) slope *= std::pow(roots[i].at - roots[j].at, roots[j].multiplicity);
            }
            if (wanted == Crossings::any || roots[i].multiplicity > 1 || slope > 0) expected.push_back(i);
          }
          std::sort(expected.begin(), expected.end(), [&](std::size_t x, std::size_t y) { return roots[x].at < roots[y].at; });
          SCOPED_TRACE(std::to_string(roots.size()) + " roots from " + std::to_string(roots[0].at) +
                       ", k = " + std::to_string(k) + (wanted == Crossings::any ? ", any" : ", rising") +
                       (ends == IntervalEnds::closed ? ", closed" : ", open"));
          const IntervalRoots r = interval_roots(c, 0.0, 1.0, ends, wanted);
          ASSERT_EQ(r.roots.size(), expected.size());
          EXPECT_FALSE(r.isolated);
          for (std::size_t i = 0; i < expected.size(); ++i) {
            EXPECT_NEAR(r.roots[i], roots[expected[i]].at, cluster_accuracy(c, roots, expected[i], k)) << i;
          }
        }
      }
    }
  }
}

TEST(IntervalRoots, MoreRootsThanTheInlineStore) {
  // More simple roots than SmallArray holds inline: the points found and the roots returned
  // move to the heap, every root still once, ascending and accurate. The roots are
  // Chebyshev's nodes on [0, 1], (1 - cos((2i + 1) pi / 2n)) / 2 as doubles, where p is as
  // large between its roots as anywhere (a multiple of T_n), so that they stay apart
  // against the coefficients' rounding.
  const std::size_t n = SmallArray<double>::kInline + 2;
  std::vector<double> roots;
  for (std::size_t i = 0; i < n; ++i) {
    roots.push_back((1 - std::cos((2 * static_cast<double>(i) + 1) * std::numbers::pi / (2 * static_cast<double>(n)))) / 2);
  }
  const std::vector<double> c = from_roots(roots);
  const IntervalRoots r = interval_roots(c, 0.0, 1.0, IntervalEnds::closed);
  ASSERT_EQ(r.roots.size(), roots.size());
  for (std::size_t i = 0; i < roots.size(); ++i) EXPECT_NEAR(r.roots[i], roots[i], accuracy(c, roots, i, 1.0)) << i;
}

TEST(IntervalRoots, NoRootsWhereThePolynomialKeepsItsSign) {
  // (t - 1/2)^2 + 1/100 > 0 on [0, 1] although its control polygon dips below its minimum.
  std::vector<double> c = from_roots({0.5, 0.5});
  for (double& v : c) v += 0.01;  // a constant adds to every coefficient
  EXPECT_TRUE(interval_roots(c, 0.0, 1.0, IntervalEnds::closed).roots.empty());
  EXPECT_TRUE(interval_roots(std::vector<double>{2.0}, 0.0, 1.0, IntervalEnds::closed).roots.empty());
}

TEST(IntervalRoots, TheZeroPolynomialIsNotIsolated) {
  const IntervalRoots r = interval_roots(std::vector<double>{0.0, 0.0, 0.0}, 0.0, 1.0, IntervalEnds::closed);
  EXPECT_FALSE(r.isolated);
  ASSERT_FALSE(r.roots.empty());
  for (const double t : r.roots) {
    EXPECT_GE(t, 0.0);
    EXPECT_LE(t, 1.0);
  }
}

}  // namespace
}  // namespace bezier::core
