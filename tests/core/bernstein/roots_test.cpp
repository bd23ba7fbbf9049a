// bernstein_roots and sign_changes (core/bernstein/roots.hpp) against polynomials built
// from known roots: p(t) = k Π (t - r_i), written in Bernstein form by multiplying the
// degree-1 factors [-r, 1 - r] (the product rule of Bernstein coefficients).
#include "core/bernstein/roots.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/numeric/binomial.hpp"
#include "tests/support/exact.hpp"

namespace bezier::core {
namespace {

using test::Rational;

/// Bernstein coefficients of the product of two polynomials in Bernstein form.
std::vector<double> product(const std::vector<double>& a, const std::vector<double>& b) {
  const int m = static_cast<int>(a.size()) - 1, n = static_cast<int>(b.size()) - 1;
  std::vector<double> c(m + n + 1, 0.0);
  for (int i = 0; i <= m; ++i) {
    for (int j = 0; j <= n; ++j) {
      c[i + j] += a[i] * b[j] * binomial(m, i) * binomial(n, j) / binomial(m + n, i + j);
    }
  }
  return c;
}

/// Π (t - r) over `roots`, times `scale`, in Bernstein form.
std::vector<double> from_roots(const std::vector<double>& roots, double scale = 1.0) {
  std::vector<double> p = {scale, scale};
  for (const double r : roots) p = product(p, {-r, 1.0 - r});
  return p;
}

TEST(SignChanges, CountsOnlyClearlyNonzeroCoefficients) {
  const std::vector<double> c = {1.0, -2.0, 3.0, -4.0};
  EXPECT_EQ(sign_changes(c, 0.0).changes, 3);
  EXPECT_FALSE(sign_changes(c, 0.0).any_small);
  EXPECT_FALSE(sign_changes(c, 0.0).all_small);
  // A coefficient within the bound neither counts nor separates: + (small) + has no change.
  const std::vector<double> d = {1.0, -1e-20, 1.0};
  EXPECT_EQ(sign_changes(d, 1e-15).changes, 0);
  EXPECT_TRUE(sign_changes(d, 1e-15).any_small);
  EXPECT_EQ(sign_changes(d, 0.0).changes, 2);
  const std::vector<double> z = {1e-20, -1e-20};
  EXPECT_TRUE(sign_changes(z, 1e-15).all_small);
  EXPECT_TRUE(sign_changes({}, 1.0).all_small);
}

TEST(BernsteinRoots, SimpleRootsOfAProductOfFactors) {
  for (const std::vector<double>& roots : std::vector<std::vector<double>>{
           {0.3}, {0.125, 0.875}, {0.1, 0.35, 0.6, 0.85}, {0.01, 0.02, 0.45, 0.97, 0.99}}) {
    for (const double scale : {1.0, -3.0, 1e-200, 1e200}) {
      const BernsteinRoots r = bernstein_roots(from_roots(roots, scale));
      ASSERT_EQ(r.roots.size(), roots.size()) << roots.size() << " roots, scale " << scale;
      EXPECT_TRUE(r.isolated);
      for (std::size_t i = 0; i < roots.size(); ++i) EXPECT_NEAR(r.roots[i], roots[i], 1e-14);
      EXPECT_TRUE(std::is_sorted(r.roots.begin(), r.roots.end()));
    }
  }
}

TEST(BernsteinRoots, RootsOutsideTheIntervalAreNotReported) {
  const BernsteinRoots r = bernstein_roots(from_roots({-0.5, 0.25, 1.5, 2.0}));
  ASSERT_EQ(r.roots.size(), 1u);
  EXPECT_NEAR(r.roots[0], 0.25, 1e-15);
}

TEST(BernsteinRoots, ExactZerosAtTheEndsAreExact) {
  // t (1 - t) (t - 1/2): coefficients with exact zeros at both ends.
  const BernsteinRoots r = bernstein_roots(from_roots({0.0, 0.5, 1.0}));
  ASSERT_EQ(r.roots.size(), 3u);
  EXPECT_EQ(r.roots.front(), 0.0);
  EXPECT_NEAR(r.roots[1], 0.5, 1e-15);
  EXPECT_EQ(r.roots.back(), 1.0);
}

TEST(BernsteinRoots, NoRootsWhereTheCoefficientsKeepTheirSign) {
  EXPECT_TRUE(bernstein_roots(std::vector<double>{1.0, 2.0, 0.5, 3.0}).roots.empty());
  // (t - 1/2)^2 + 1/100 is positive on [0, 1] although its control polygon dips.
  const std::vector<double> p = product({-0.5, 0.5}, {-0.5, 0.5});
  std::vector<double> q = p;
  for (double& c : q) c += 0.01;  // adding a constant adds it to every coefficient
  EXPECT_TRUE(bernstein_roots(q).roots.empty());
}

TEST(BernsteinRoots, ARootAtASplitPointIsFoundExactly) {
  // t = 1/2 is where [0, 1] is split: p(1/2) is exactly zero there.
  const BernsteinRoots r = bernstein_roots(from_roots({0.5}, 3.0));
  ASSERT_EQ(r.roots.size(), 1u);
  EXPECT_EQ(r.roots[0], 0.5);
}

TEST(BernsteinRoots, ADoubleRootIsFoundWithinTheSquareRootOfTheRounding) {
  // (t - 0.3)^2 (t - 0.8): near 0.3, |p| stays below its rounding bound over a width of
  // about the square root of the rounding, so the root is known only to that width; every
  // root reported there lies within it, and the simple root is found to full precision.
  const BernsteinRoots r = bernstein_roots(from_roots({0.3, 0.3, 0.8}));
  EXPECT_FALSE(r.isolated);
  ASSERT_FALSE(r.roots.empty());
  for (const double t : r.roots) {
    EXPECT_TRUE(std::fabs(t - 0.3) < 1e-7 || std::fabs(t - 0.8) < 1e-14) << t;
  }
  EXPECT_NEAR(r.roots.front(), 0.3, 1e-7);
  EXPECT_NEAR(r.roots.back(), 0.8, 1e-14);
}

TEST(BernsteinRoots, TheZeroPolynomialIsNotIsolated) {
  const BernsteinRoots r = bernstein_roots(std::vector<double>{0.0, 0.0, 0.0});
  EXPECT_FALSE(r.isolated);
  EXPECT_FALSE(r.roots.empty());
  for (const double t : r.roots) {
    EXPECT_GE(t, 0.0);
    EXPECT_LE(t, 1.0);
  }
}

TEST(BernsteinRoots, RootsOfAPolynomialBuiltFromThem) {
  // p(t) = (t - 1/8)(t - 1/2)(t - 3/4)(t - 1), converted to Bernstein form exactly.
  const Rational r[] = {Rational(1, 8), Rational(1, 2), Rational(3, 4), Rational(1)};
  std::vector<Rational> power = {Rational(1)};
  for (const Rational& root : r) {
    std::vector<Rational> next(power.size() + 1, Rational(0));
    for (std::size_t i = 0; i < power.size(); ++i) {
      next[i + 1] += power[i];
      next[i] -= root * power[i];
    }
    power = next;
  }
  const int n = 4;
  std::vector<double> b;
  for (int i = 0; i <= n; ++i) {
    Rational sum(0);
    for (int j = 0; j <= i; ++j) {
      sum += Rational(static_cast<long long>(binomial(i, j))) /
             Rational(static_cast<long long>(binomial(n, j))) * power[static_cast<std::size_t>(j)];
    }
    b.push_back(sum.to_double());
  }
  const BernsteinRoots found = bernstein_roots(b);
  ASSERT_EQ(found.roots.size(), 4u);
  EXPECT_NEAR(found.roots[0], 0.125, 1e-14);
  EXPECT_NEAR(found.roots[1], 0.5, 1e-14);
  EXPECT_NEAR(found.roots[2], 0.75, 1e-14);
  EXPECT_EQ(found.roots[3], 1.0);
  // No roots: a positive polynomial.
  const double positive[] = {1.0, -0.5, 1.0};
  EXPECT_TRUE(bernstein_roots(positive).roots.empty());
}

}  // namespace
}  // namespace bezier::core
