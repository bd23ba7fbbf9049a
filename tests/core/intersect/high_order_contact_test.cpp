// High-order contacts (high_order_contact.hpp): the issue-29 pair and a family whose contact
// order is known in closed form, B(t) = A(t) + (t - p)^k v, built in exact rationals, through
// the certificate and through intersect() by every method; near misses are not tangencies.

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "core/base/curve.hpp"
#include "core/intersect/high_order_contact.hpp"
#include "core/intersect/intersect.hpp"
#include "core/numeric/binomial.hpp"
#include "tests/support/exact.hpp"

namespace bezier::core {
namespace {

using test::Rational;

const IntersectMethod kMethods[] = {IntersectMethod::hybrid, IntersectMethod::bezier_clipping,
                                    IntersectMethod::subdivision};

/// The API's default work cap (api/limits.hpp): "well within" is a tenth of it.
constexpr std::int64_t kDefaultCap = 22000000;

IntersectionResult run(const Curve& f, const Curve& g, IntersectMethod method,
                       int fat_curve_degree = 3) {
  IntersectOptions options;
  options.method = method;
  options.fat_curve_degree = fat_curve_degree;
  options.max_work = kDefaultCap;
  return intersect(f, g, options);
}

// The pair of issue 29: A(t) - B(t) = (2t - 1)^3 (1, -1), and (1, -1) is A's tangent
// direction at 1/2, so the contact is of order 5: the resultant Res_s(A(t) - B(s)) is
// -4 (2t - 1)^5 (64 t^4 - 128 t^3 + 168 t^2 - 104 t + 49), whose quartic has no real root.
Curve issue_a() { return Curve({{1, 4}, {4, 5}, {3, 2}, {6, 3}}); }
Curve issue_b() { return Curve({{2, 3}, {3, 6}, {4, 1}, {5, 4}}); }

TEST(HighOrderContact, IssuePairIsCertifiedOfOrderFive) {
  std::int64_t products = 0;
  const auto c =
      certify_high_order_contact(issue_a(), issue_b(), {1, 2}, {1, 2}, 1000000, products);
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->order, 5);
  EXPECT_EQ(c->t, (ParamInterval{0.5, 0.5}));
  EXPECT_EQ(c->s, (ParamInterval{0.5, 0.5}));
  EXPECT_LT(c->t_isolated.lo, 0.5);
  EXPECT_GT(c->t_isolated.hi, 0.5);
  EXPECT_LT(c->s_isolated.lo, 0.5);
  EXPECT_GT(c->s_isolated.hi, 0.5);
  EXPECT_GT(products, 0);
}

TEST(HighOrderContact, IssuePairAnswersOneExactTangencyByEveryMethod) {
  for (const IntersectMethod method : kMethods) {
    for (const int k : {2, 3}) {
      if (method != IntersectMethod::hybrid && k == 2) continue;
      SCOPED_TRACE(std::string(to_string(method)) + " fat curve degree " + std::to_string(k));
      for (const bool swapped : {false, true}) {
        const IntersectionResult r = swapped ? run(issue_b(), issue_a(), method, k)
                                             : run(issue_a(), issue_b(), method, k);
        EXPECT_EQ(r.status, IntersectStatus::ok);
        EXPECT_LT(r.stats.work, kDefaultCap / 10);
        ASSERT_EQ(r.intersections.size(), 1u);
        const Intersection& x = r.intersections[0];
        EXPECT_EQ(x.t, 0.5);
        EXPECT_EQ(x.s, 0.5);
        EXPECT_EQ(x.t_interval, (ParamInterval{0.5, 0.5}));
        EXPECT_EQ(x.s_interval, (ParamInterval{0.5, 0.5}));
        EXPECT_EQ(x.point, (Point2{3.5, 3.5}));
        EXPECT_EQ(x.kind, IntersectionKind::tangent);
        EXPECT_TRUE(x.resolved);
      }
    }
  }
}

// A curve that stops where it touches another: g(s) = (4 s^2, -2 s^2) (control points (0, 0),
// (0, 0), (4, -2)) runs along the line x + 2y = 0 with g'(0) = 0, and f(t) = (4t - 4t^2,
// -2t + 6t^2) leaves (0, 0) along that line: x + 2y = 8 t^2 on f, so f meets the line only at
// t = 0, and the one intersection is f(0) = g(0). There f's distance from the line grows like
// t^2 while g reaches f's neighbourhood only at s ~ sqrt(t): in g's parameter the contact is
// of order 4. The certificate needs the moving curve's derivative, so it is taken with the
// curves' roles exchanged whichever comes first.
Curve moving() { return Curve({{0, 0}, {2, -1}, {0, 4}}); }
Curve stopping() { return Curve({{0, 0}, {0, 0}, {4, -2}}); }

TEST(HighOrderContact, CurveStoppingAtTheContactIsCertifiedInEitherOrder) {
  for (const bool swapped : {false, true}) {
    std::int64_t products = 0;
    const auto c = swapped ? certify_high_order_contact(stopping(), moving(), {0, 1}, {0, 1}, 1000000, products)
                           : certify_high_order_contact(moving(), stopping(), {0, 1}, {0, 1}, 1000000, products);
    ASSERT_TRUE(c.has_value()) << swapped;
    EXPECT_EQ(c->order, 4);
    EXPECT_EQ(c->t, (ParamInterval{0.0, 0.0}));
    EXPECT_EQ(c->s, (ParamInterval{0.0, 0.0}));
    EXPECT_EQ(c->t_isolated.lo, 0.0);
    EXPECT_GT(c->t_isolated.hi, 0.0);
    EXPECT_EQ(c->s_isolated.lo, 0.0);
    EXPECT_GT(c->s_isolated.hi, 0.0);
  }
  // Both curves stopping there: no certificate (neither map has a derivative to follow).
  std::int64_t products = 0;
  EXPECT_FALSE(certify_high_order_contact(stopping(), stopping(), {0, 1}, {0, 1}, 1000000, products));
}

TEST(HighOrderContact, CurveStoppingAtTheContactAnswersOneExactRootByEveryMethod) {
  for (const IntersectMethod method : kMethods) {
    SCOPED_TRACE(std::string(to_string(method)));
    for (const bool swapped : {false, true}) {
      const IntersectionResult r =
          swapped ? run(stopping(), moving(), method) : run(moving(), stopping(), method);
      EXPECT_EQ(r.status, IntersectStatus::ok) << swapped;
      EXPECT_LT(r.stats.work, kDefaultCap / 10);
      ASSERT_EQ(r.intersections.size(), 1u);
      const Intersection& x = r.intersections[0];
      EXPECT_EQ(x.t_interval, (ParamInterval{0.0, 0.0}));
      EXPECT_EQ(x.s_interval, (ParamInterval{0.0, 0.0}));
      EXPECT_EQ(x.point, (Point2{0.0, 0.0}));
      EXPECT_TRUE(x.resolved);
    }
  }
}

TEST(HighOrderContact, SimplestRationalHasTheLeastDenominator) {
  EXPECT_EQ(simplest_rational({0.3, 0.35}, 256), (RationalParameter{1, 3}));
  EXPECT_EQ(simplest_rational({0.5, 0.5}, 256), (RationalParameter{1, 2}));
  EXPECT_EQ(simplest_rational({0.0, 0.1}, 256), (RationalParameter{0, 1}));
  // 1/4 and 3/11 lie just outside; no denominator below 15 has a fraction inside.
  EXPECT_EQ(simplest_rational({0.26, 0.27}, 256), (RationalParameter{4, 15}));
  EXPECT_EQ(simplest_rational({0.26, 0.27}, 14), std::nullopt);
  EXPECT_EQ(simplest_rational({1.0 / 3 + 1e-12, 1.0 / 3 + 2e-12}, 256), std::nullopt);
}

// The family. A is a degree-5 arc with x' > 0 throughout; B = A + (t - p)^k v with
// v = (0, 1) across the tangent, so f(t) = g(t) meets with a contact of order exactly k at
// t = s = p. (t - p)^k in the Bernstein basis of degree 5 has coefficients
// b_i = sum_{j <= i} C(i, j) / C(5, j) [t^j](t - p)^k, whose denominators divide
// 10 den(p)^k; both curves are multiplied by that, so every coordinate is an integer.

struct Family {
  Curve f, g;
  Rational p;
};

const int kArc[6][2] = {{0, 0}, {2, 3}, {5, 5}, {9, 6}, {13, 5}, {16, 3}};

/// (t - p)^k in the Bernstein basis of degree 5, exactly.
std::vector<Rational> bernstein_of_power(const Rational& p, int k) {
  std::vector<Rational> power(6, Rational(0));  // [t^j](t - p)^k
  Rational minus_p_power(1);
  for (int j = k; j >= 0; --j) {
    power[static_cast<std::size_t>(j)] = Rational(static_cast<long long>(binomial(k, j))) * minus_p_power;
    minus_p_power = minus_p_power * (Rational(0) - p);
  }
  std::vector<Rational> b;
  for (int i = 0; i <= 5; ++i) {
    Rational sum(0);
    for (int j = 0; j <= i; ++j)
      sum += Rational(static_cast<long long>(binomial(i, j))) /
             Rational(static_cast<long long>(binomial(5, j))) * power[static_cast<std::size_t>(j)];
    b.push_back(sum);
  }
  return b;
}

double exact_double(const Rational& r) {
  const double d = r.to_double();
  EXPECT_EQ(Rational(d), r) << "not exact: " << r;
  return d;
}

/// The pair for p = num/den and order k, with g shifted by `shift` (times the common scale)
/// along y, the normal direction (x' > 0).
Family family(long long num, long long den, int k, const Rational& shift = Rational(0)) {
  const Rational p = Rational(num) / Rational(den);
  Rational scale(10);
  for (int i = 0; i < k; ++i) scale *= Rational(den);
  const std::vector<Rational> b = bernstein_of_power(p, k);
  std::vector<Point2> fp, gp;
  for (int i = 0; i < 6; ++i) {
    const Rational x = scale * Rational(kArc[i][0]), y = scale * Rational(kArc[i][1]);
    fp.push_back({exact_double(x), exact_double(y)});
    gp.push_back({exact_double(x),
                  exact_double(y + scale * (b[static_cast<std::size_t>(i)] + shift))});
  }
  return {Curve(fp), Curve(gp), p};
}

/// The same transformation of both curves: x -> a x + dx, y -> a y + dy (exact here).
Curve moved(const Curve& c, double a, double dx, double dy) {
  std::vector<Point2> q;
  for (const Point2 p : c.points()) q.push_back({a * p.x + dx, a * p.y + dy});
  return Curve(q);
}

bool contains(ParamInterval iv, const Rational& x) {
  return Rational(iv.lo) <= x && x <= Rational(iv.hi);
}

/// The reported intersections whose intervals contain (t, s).
std::vector<Intersection> at(const IntersectionResult& r, const Rational& t, const Rational& s) {
  std::vector<Intersection> out;
  for (const Intersection& x : r.intersections)
    if (contains(x.t_interval, t) && contains(x.s_interval, s)) out.push_back(x);
  return out;
}

const long long kContactAt[][2] = {{1, 2}, {1, 4}, {3, 8}, {1, 3}, {2, 5}};

TEST(HighOrderContact, FamilyIsCertifiedWithItsOrder) {
  for (const auto& [num, den] : kContactAt) {
    for (int k = 3; k <= 5; ++k) {
      SCOPED_TRACE("p = " + std::to_string(num) + "/" + std::to_string(den) +
                   ", k = " + std::to_string(k));
      const Family fam = family(num, den, k);
      const RationalParameter p{static_cast<double>(num), static_cast<double>(den)};
      std::int64_t products = 0;
      const auto c = certify_high_order_contact(fam.f, fam.g, p, p, 1000000, products);
      ASSERT_TRUE(c.has_value());
      EXPECT_EQ(c->order, k);
      EXPECT_TRUE(contains(c->t, fam.p));
      EXPECT_TRUE(contains(c->s, fam.p));
      // Not a contact one parameter step away.
      const RationalParameter next{static_cast<double>(num + 1), static_cast<double>(den)};
      EXPECT_FALSE(certify_high_order_contact(fam.f, fam.g, next, p, 1000000, products));
    }
  }
}

TEST(HighOrderContact, FamilyAnswersOneTangencyAtTheContactByEveryMethod) {
  for (const auto& [num, den] : kContactAt) {
    for (int k = 2; k <= 5; ++k) {
      const Family fam = family(num, den, k);
      const Rational one(1);
      // As built; moved (scaled by 3 and by 2^-20, translated); g reversed; f and g swapped.
      struct Variant {
        const char* name;
        Curve f, g;
        Rational t, s;
      };
      const std::vector<Variant> variants = {
          {"as built", fam.f, fam.g, fam.p, fam.p},
          {"scaled by 3, translated", moved(fam.f, 3, 1024, -512), moved(fam.g, 3, 1024, -512),
           fam.p, fam.p},
          {"scaled by 2^-20, translated", moved(fam.f, 0x1p-20, 0.5, 7), moved(fam.g, 0x1p-20, 0.5, 7),
           fam.p, fam.p},
          {"g reversed", fam.f, reversed(fam.g), fam.p, one - fam.p},
          {"swapped, f reversed", reversed(fam.g), fam.f, one - fam.p, fam.p},
      };
      for (const Variant& v : variants) {
        for (const IntersectMethod method : kMethods) {
          SCOPED_TRACE("p = " + std::to_string(num) + "/" + std::to_string(den) + ", k = " +
                       std::to_string(k) + ", " + v.name + ", " + std::string(to_string(method)));
          const IntersectionResult r = run(v.f, v.g, method);
          EXPECT_EQ(r.status, IntersectStatus::ok);
          EXPECT_LT(r.stats.work, kDefaultCap / 10);
          const std::vector<Intersection> found = at(r, v.t, v.s);
          ASSERT_EQ(found.size(), 1u);
          EXPECT_EQ(found[0].kind, IntersectionKind::tangent);
          // A dyadic contact of order >= 3 is certified exactly: the estimate is the contact.
          if (k >= 3 && (den & (den - 1)) == 0) {
            EXPECT_EQ(Rational(found[0].t), v.t);
            EXPECT_EQ(Rational(found[0].s), v.s);
            EXPECT_TRUE(found[0].resolved);
          }
        }
      }
    }
  }
}

TEST(HighOrderContact, NearMissesAreNotTangencies) {
  // k = 4, g shifted by delta along the normal: up (v's side) the curves no longer meet near
  // p; down they cross twice, at (t - p)^4 = delta, i.e. t = p +- delta^(1/4).
  for (const auto& [num, den] : kContactAt) {
    for (const int e : {20, 32}) {
      const Rational delta = Rational(1) / Rational(1LL << e);
      const Rational quarter_root = Rational(1) / Rational(1LL << (e / 4));
      for (const int side : {1, -1}) {
        const Family fam = family(num, den, 4, side > 0 ? delta : Rational(0) - delta);
        const RationalParameter p{static_cast<double>(num), static_cast<double>(den)};
        std::int64_t products = 0;
        EXPECT_FALSE(certify_high_order_contact(fam.f, fam.g, p, p, 1000000, products));
        for (const IntersectMethod method : kMethods) {
          SCOPED_TRACE("p = " + std::to_string(num) + "/" + std::to_string(den) +
                       ", delta = 2^-" + std::to_string(e) + (side > 0 ? " up" : " down") +
                       ", " + std::string(to_string(method)));
          const IntersectionResult r = run(fam.f, fam.g, method);
          EXPECT_EQ(r.status, IntersectStatus::ok);
          std::vector<Intersection> near;
          for (const Intersection& x : r.intersections)
            if ((Rational(x.t) - fam.p).abs() < quarter_root * Rational(2))
              near.push_back(x);
          if (side > 0) {
            EXPECT_TRUE(near.empty());
          } else {
            ASSERT_EQ(near.size(), 2u);
            for (int i = 0; i < 2; ++i) {
              const Rational root = fam.p + (i == 0 ? Rational(0) - quarter_root : quarter_root);
              EXPECT_TRUE(contains(near[static_cast<std::size_t>(i)].t_interval, root));
              EXPECT_TRUE(contains(near[static_cast<std::size_t>(i)].s_interval, root));
              EXPECT_EQ(near[static_cast<std::size_t>(i)].kind, IntersectionKind::transversal);
            }
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace bezier::core
