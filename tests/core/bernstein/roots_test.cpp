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
  EXPECT_TRUE(r.isolated);
}

TEST(BernsteinRoots, AnExactZeroAtASplitPointIsOneIsolatedRoot) {
  // Antisymmetric coefficients (c_i = -c_(n-i)) make p(1 - t) = -p(t), and de Casteljau at
  // 1/2 keeps the symmetry exactly (each average of x and -y is minus that of -x and y), so
  // p(1/2) evaluates to exactly zero. With roots near 1/3 and 2/3 too, [0, 1] has three sign
  // changes and is split at 1/2: the zero there is a root, reported once and exactly, and the
  // halves leave it out of their counts, so every root is isolated.
  std::vector<double> c = from_roots({1.0 / 3, 0.5, 2.0 / 3}, 6.0);
  for (std::size_t i = 0; i < c.size() / 2; ++i) c[c.size() - 1 - i] = -c[i];
  const BernsteinRoots r = bernstein_roots(c);
  ASSERT_EQ(r.roots.size(), 3u);
  EXPECT_TRUE(r.isolated);
  EXPECT_EQ(r.roots[1], 0.5);
  EXPECT_NEAR(r.roots[0], 1.0 / 3, 1e-14);
  EXPECT_NEAR(r.roots[2], 2.0 / 3, 1e-14);
}

/// The rounding bound of bernstein_roots for c: 3.02 n u max|c_i|.
double rounding_bound(const std::vector<double>& c) {
  double max_c = 0.0;
  for (const double v : c) max_c = std::max(max_c, std::fabs(v));
  return 3.02 * static_cast<double>(c.size() - 1) * 0x1p-53 * max_c;
}

TEST(BernsteinRoots, ADoubleRootIsReportedOnceWithinTheSquareRootOfTheRounding) {
  // (t - 0.3)^2 (t - 0.8): near 0.3, |p| stays below its rounding bound e over a stretch of
  // about sqrt(e / |p''|) each side (|p''(0.3)| = 2 |0.3 - 0.8| = 1), so the root is known
  // only to that width: one root there, within it, and isolated = false; the simple root
  // to full precision.
  const std::vector<double> c = from_roots({0.3, 0.3, 0.8});
  const BernsteinRoots r = bernstein_roots(c);
  EXPECT_FALSE(r.isolated);
  ASSERT_EQ(r.roots.size(), 2u);
  EXPECT_NEAR(r.roots[0], 0.3, 4 * std::sqrt(rounding_bound(c) / 1.0));
  EXPECT_NEAR(r.roots[1], 0.8, 1e-14);
}

TEST(BernsteinRoots, DoubleAndTripleRootsAnywhereAreReportedOnce) {
  // (t - r)^m (t - s) with s 0.4 away, for r across (0, 1): two roots, the multiple one
  // within a few times (m! e / |p^(m)(r)|)^(1/m) = (e / |r - s|)^(1/m) of r, where |p| stays
  // within the rounding bound e.
  for (int i = 1; i < 100; ++i) {
    for (const int m : {2, 3}) {
      const double r = i / 100.0 + 1e-4 / 3;
      const double s = r < 0.5 ? r + 0.4 : r - 0.4;
      std::vector<double> roots(static_cast<std::size_t>(m), r);
      roots.push_back(s);
      const std::vector<double> c = from_roots(roots);
      const BernsteinRoots found = bernstein_roots(c);
      ASSERT_EQ(found.roots.size(), 2u) << "r = " << r << ", multiplicity " << m;
      EXPECT_FALSE(found.isolated);
      const double multiple = r < s ? found.roots[0] : found.roots[1];
      const double simple = r < s ? found.roots[1] : found.roots[0];
      EXPECT_NEAR(multiple, r, 4 * std::pow(rounding_bound(c) / 0.4, 1.0 / m)) << "multiplicity " << m;
      EXPECT_NEAR(simple, s, 1e-14);
    }
  }
}

TEST(BernsteinRoots, AMultipleRootThatIsAnExactZeroIsReportedExactly) {
  // (t - 1/2)^3 = ((t - (1 - t)) / 2)^3 = (-1/8, 1/8, -1/8, 1/8) in Bernstein form (here
  // times 8): zero exactly at 1/2, and flat around it. One root, exactly 1/2, and not
  // isolated (a triple root).
  const BernsteinRoots triple = bernstein_roots(std::vector<double>{-1.0, 1.0, -1.0, 1.0});
  EXPECT_EQ(triple.roots, (std::vector<double>{0.5}));
  EXPECT_FALSE(triple.isolated);
  // (t - 0.3)(1 - t)^2: the double root at 1 is an exact zero (the last coefficient is 0).
  const std::vector<double> c = from_roots({0.3, 1.0, 1.0});
  ASSERT_EQ(c.back(), 0.0);
  const BernsteinRoots end = bernstein_roots(c);
  ASSERT_EQ(end.roots.size(), 2u);
  EXPECT_NEAR(end.roots[0], 0.3, 1e-14);
  EXPECT_EQ(end.roots[1], 1.0);
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
