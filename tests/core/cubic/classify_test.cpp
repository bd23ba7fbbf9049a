#include "core/cubic/classify.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/cubic/canonical_form.hpp"
#include "core/cubic/double_point.hpp"
#include "core/cubic/predicates.hpp"
#include "core/curve/derivative.hpp"
#include "core/curve/evaluate.hpp"
#include "tests/core/cubic/classify_oracle.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using Cubic = std::array<Point2, 4>;

// x -> A x + t with dyadic entries: exact on inputs with few significant bits.
struct Affine {
  double a, b, c, d, e, f;
  [[nodiscard]] Point2 operator()(Point2 p) const {
    return {a * p.x + b * p.y + e, c * p.x + d * p.y + f};
  }
  [[nodiscard]] Cubic operator()(const Cubic& q) const {
    return {(*this)(q[0]), (*this)(q[1]), (*this)(q[2]), (*this)(q[3])};
  }
};

// Identity, a reflection, a shear with translation, a rotation by 90° with scaling, a
// reflection through the diagonal with non-uniform scaling (det < 0), a general map.
const std::vector<Affine> kMaps = {
    {1, 0, 0, 1, 0, 0},         {-1, 0, 0, 1, 0, 0},    {1, 0.5, 0, 1, 3, -2},
    {0, -2, 2, 0, -0.25, 0.75}, {0, 0.125, 4, 0, 5, 5}, {1.5, -0.75, 0.25, 2, -7, 1},
};

Cubic canonical_cubic(Point2 q) {
  return {Point2{0, 0}, Point2{0, 1}, Point2{1, 1}, q};
}
Cubic reversed_cubic(const Cubic& p) {
  return {p[3], p[2], p[1], p[0]};
}

CubicClassification classify_cubic(const Cubic& p) {
  return classify(std::span<const Point2, 4>(p));
}

// Points inside each region of the canonical map, with the region named by the issue's
// edges (checked by hand: cusp edge c(x) = (3 + 2x − x²)/4).
struct RegionCase {
  Point2 q;
  CubicType type;
};
const std::vector<RegionCase> kInteriorPoints = {
    {{0, 2}, CubicType::single_inflection},             // y > 1
    {{5, 5}, CubicType::single_inflection},             // y > 1, far right
    {{-1, 0.5}, CubicType::double_inflection},          // c(−1) = 0 < y < 1, x <= 1
    {{0.75, 0.9921875}, CubicType::double_inflection},  // c(0.75) = 0.984375
    {{2, 0.875}, CubicType::arch},                      // above c(2) = 0.75, but x > 1
    {{4, -1}, CubicType::arch},                         // above c(4) = −1.25, x > 1
    {{0.5, -1}, CubicType::arch},                       // below the loop-at-end edge
    {{-4, -10}, CubicType::arch},                       // below the loop-at-start edge (−28/3)
    {{-1, -0.5}, CubicType::loop},                      // c(−1) = 0 > y > −4/3
    {{0.5, 0.921875}, CubicType::loop},  // between 0.8956 (t = 1 edge) and c = 0.9375
    {{-0.25, 0.5}, CubicType::loop},
};

TEST(Classify, InteriorPointOfEveryRegionUnderAffineMaps) {
  for (const RegionCase& rc : kInteriorPoints) {
    EXPECT_EQ(canonical_region(rc.q), rc.type) << rc.q.x << ", " << rc.q.y;
    for (const Affine& m : kMaps) {
      const Cubic p = m(canonical_cubic(rc.q));
      EXPECT_EQ(classify_cubic(p).type, rc.type) << rc.q.x << ", " << rc.q.y;
      EXPECT_EQ(test::exact_type(p), rc.type);
    }
  }
}

TEST(Classify, CanonicalPointOfAnAffineImageIsExact) {
  // With dyadic points and maps every cross product is exact, so (u × w) / (u × v) is the
  // correctly rounded canonical coordinate: exactly q.
  for (const RegionCase& rc : kInteriorPoints) {
    for (const Affine& m : kMaps) {
      const auto q = canonical_point(std::span<const Point2, 4>(m(canonical_cubic(rc.q))));
      ASSERT_TRUE(q.has_value());
      EXPECT_EQ(*q, rc.q);
    }
  }
}

TEST(Classify, HorizontalFirstLegHasACanonicalPoint) {
  // P1.y = P0.y: the primer's closed formula divides by zero here; the 2×2 system does not.
  const Cubic p = {Point2{0, 0}, Point2{1, 0}, Point2{1, 1}, Point2{0, 1}};
  const auto c = classify_cubic(p);
  ASSERT_TRUE(c.canonical_point.has_value());
  // u = (1,0), v = (1,1), w = (0,1): x = (u × w)/(u × v) = 1, y = ((P1 − P2) × w)/(u × v) = 0.
  EXPECT_EQ(*c.canonical_point, (Point2{1, 0}));
  EXPECT_EQ(c.type, CubicType::arch);
  EXPECT_EQ(c.type, test::exact_type(p));
}

TEST(Classify, ParametersMatchClosedForms) {
  // Canonical cubic: I(t) ∝ −1 + (3 − x) t + (x + y − 3) t².
  {  // (−1, 0.5): I = −1 + 4t − 3.5t², roots (4 ± √2)/7.
    const auto c = classify_cubic(canonical_cubic({-1, 0.5}));
    ASSERT_EQ(c.inflections.count, 2);
    EXPECT_NEAR(c.inflections.t[0], (4 - std::sqrt(2.0)) / 7, 1e-15);
    EXPECT_NEAR(c.inflections.t[1], (4 + std::sqrt(2.0)) / 7, 1e-15);
  }
  {  // (0, 2): I = −1 + 3t − t², roots (3 ± √5)/2; only the smaller is in [0,1].
    const auto c = classify_cubic(canonical_cubic({0, 2}));
    ASSERT_EQ(c.inflections.count, 1);
    EXPECT_NEAR(c.inflections.t[0], (3 - std::sqrt(5.0)) / 2, 1e-15);
  }
  {  // Cusp edge at x = −1: B'(t) = 0 at t = 2/(3 − x) = 1/2.
    const auto c = classify_cubic(canonical_cubic({-1, 0}));
    EXPECT_EQ(c.type, CubicType::cusp);
    ASSERT_TRUE(c.cusp.has_value());
    EXPECT_NEAR(*c.cusp, 0.5, 1e-15);
    EXPECT_TRUE(c.inflections.values().empty());
  }
  {  // Loop at start, x = −3: t1 = 0, t2 = 3/(3 − x) = 1/2, the point is P0.
    const auto c = classify_cubic(canonical_cubic({-3, -6}));
    EXPECT_EQ(c.type, CubicType::loop_at_start);
    ASSERT_TRUE(c.self_intersection.has_value());
    EXPECT_EQ(c.self_intersection->t1, 0.0);
    EXPECT_NEAR(c.self_intersection->t2, 0.5, 1e-15);
    EXPECT_EQ(c.self_intersection->point, (Point2{0, 0}));
  }
  {  // (−1, −0.5): σ = (3 − x)/(3 − x − y) = 8/9, s² + st + t² = 3/(3 − x − y) = 2/3,
     // st = σ² − 2/3 = 10/81: t = (8 ± √(64 − 40))/18 = (4 ± √6)/9.
    const auto c = classify_cubic(canonical_cubic({-1, -0.5}));
    ASSERT_TRUE(c.self_intersection.has_value());
    EXPECT_NEAR(c.self_intersection->t1, (4 - std::sqrt(6.0)) / 9, 1e-15);
    EXPECT_NEAR(c.self_intersection->t2, (4 + std::sqrt(6.0)) / 9, 1e-15);
  }
}

TEST(Classify, DegenerateInputs) {
  {  // All points equal.
    const auto c = classify_cubic({Point2{2, -1}, Point2{2, -1}, Point2{2, -1}, Point2{2, -1}});
    EXPECT_EQ(c.type, CubicType::point);
    EXPECT_EQ(c.loop_blinn, LoopBlinnClass::point);
    EXPECT_FALSE(c.canonical_point.has_value());
  }
  for (const Cubic& p :
       {Cubic{Point2{0, 0}, Point2{1, 1}, Point2{2, 2}, Point2{3, 3}},
        Cubic{Point2{0, 0}, Point2{2, 2}, Point2{-1, -1}, Point2{1, 1}},  // folds back
        Cubic{Point2{5, 0}, Point2{5, 3}, Point2{5, 3}, Point2{5, -7}},   // vertical
        Cubic{Point2{1, 2}, Point2{1, 2}, Point2{1, 2}, Point2{4, 8}}}) {
    const auto c = classify_cubic(p);
    EXPECT_EQ(c.type, CubicType::line);
    EXPECT_EQ(c.loop_blinn, LoopBlinnClass::line);
    EXPECT_FALSE(c.canonical_point.has_value());
    EXPECT_FALSE(c.self_intersection.has_value());
    EXPECT_TRUE(c.inflections.values().empty());
  }
  {  // Degree elevation of the parabola (0,0), (3,6), (6,0): P3 − 3P2 + 3P1 − P0 = 0.
    const Cubic p = {Point2{0, 0}, Point2{2, 4}, Point2{4, 4}, Point2{6, 0}};
    for (const Affine& m : kMaps) {
      const auto c = classify_cubic(m(p));
      EXPECT_EQ(c.type, CubicType::quadratic);
      EXPECT_EQ(c.loop_blinn, LoopBlinnClass::quadratic);
      ASSERT_TRUE(c.canonical_point.has_value());
      EXPECT_EQ(*c.canonical_point, (Point2{3, 0}));
      EXPECT_EQ(canonical_region(*c.canonical_point), CubicType::quadratic);
    }
  }
  {  // P0 = P1: B'(0) = 0, a cusp at t = 0 on the closed interval.
    const auto c = classify_cubic({Point2{0, 0}, Point2{0, 0}, Point2{1, 1}, Point2{2, 0}});
    EXPECT_EQ(c.type, CubicType::cusp);
    ASSERT_TRUE(c.cusp.has_value());
    EXPECT_EQ(*c.cusp, 0.0);
    EXPECT_FALSE(std::signbit(*c.cusp));
    EXPECT_FALSE(c.canonical_point.has_value());  // P0, P1, P2 collinear
    EXPECT_EQ(c.loop_blinn, LoopBlinnClass::cusp);
  }
  {  // P2 = P3: a cusp at t = 1.
    const auto c = classify_cubic({Point2{0, 0}, Point2{1, 3}, Point2{2, 0}, Point2{2, 0}});
    EXPECT_EQ(c.type, CubicType::cusp);
    ASSERT_TRUE(c.cusp.has_value());
    EXPECT_EQ(*c.cusp, 1.0);
    ASSERT_TRUE(c.canonical_point.has_value());
    EXPECT_EQ(*c.canonical_point, (Point2{1, 1}));
  }
  {  // P1 = P2: B'' parallel to B' at both ends, inflections exactly at 0 and 1.
    const Cubic p = {Point2{0, 0}, Point2{1, 1}, Point2{1, 1}, Point2{3, 0}};
    const auto c = classify_cubic(p);
    EXPECT_EQ(c.type, CubicType::double_inflection);
    EXPECT_EQ(c.type, test::exact_type(p));
    ASSERT_EQ(c.inflections.count, 2);
    EXPECT_EQ(c.inflections.t[0], 0.0);
    EXPECT_EQ(c.inflections.t[1], 1.0);
    EXPECT_FALSE(c.canonical_point.has_value());
  }
  {  // P0, P1, P2 collinear and distinct: B(t) = (3t, t³), y = x³/27. No canonical map, but a
     // single inflection at t = 0 (the curve's flat point), and the unbounded class is
     // Loop–Blinn's cusp at infinity. The reversed curve has a canonical point.
    const Cubic p = {Point2{0, 0}, Point2{1, 0}, Point2{2, 0}, Point2{3, 1}};
    const auto c = classify_cubic(p);
    EXPECT_FALSE(c.canonical_point.has_value());
    EXPECT_EQ(c.type, CubicType::single_inflection);
    ASSERT_EQ(c.inflections.count, 1);
    EXPECT_EQ(c.inflections.t[0], 0.0);
    EXPECT_EQ(c.loop_blinn, LoopBlinnClass::cusp);
    const auto r = classify_cubic(reversed_cubic(p));
    ASSERT_TRUE(r.canonical_point.has_value());
    EXPECT_EQ(canonical_region(*r.canonical_point), CubicType::single_inflection);
    ASSERT_EQ(r.inflections.count, 1);
    EXPECT_EQ(r.inflections.t[0], 1.0);
  }
  {  // Closed: P0 = P3, a teardrop. Its double point is the trivial pair (0, 1).
    const Cubic p = {Point2{0, 0}, Point2{4, 4}, Point2{-4, 4}, Point2{0, 0}};
    const auto c = classify_cubic(p);
    EXPECT_EQ(c.type, CubicType::loop_at_start);
    ASSERT_TRUE(c.self_intersection.has_value());
    EXPECT_EQ(c.self_intersection->t1, 0.0);
    EXPECT_EQ(c.self_intersection->t2, 1.0);
    EXPECT_EQ(c.self_intersection->point, (Point2{0, 0}));
    EXPECT_EQ(classify_cubic(reversed_cubic(p)).type, CubicType::loop_at_start);
  }
}

TEST(Classify, LoopBlinnClassOfTheUnboundedCurve) {
  // Serpentine: two real inflections (here one of them outside [0,1]).
  EXPECT_EQ(classify_cubic(canonical_cubic({0, 2})).loop_blinn, LoopBlinnClass::serpentine);
  // Loop, also when the loop is outside [0,1] (type arch).
  const auto outside = classify_cubic(canonical_cubic({-4, -10}));
  EXPECT_EQ(outside.type, CubicType::arch);
  EXPECT_EQ(outside.loop_blinn, LoopBlinnClass::loop);
  // A cusp, also beyond t = 1 (the cusp edge for x > 1: type arch).
  EXPECT_EQ(classify_cubic(canonical_cubic({-1, 0})).loop_blinn, LoopBlinnClass::cusp);
  const auto far_cusp = classify_cubic(canonical_cubic({2, 0.75}));
  EXPECT_EQ(far_cusp.type, CubicType::arch);
  EXPECT_EQ(far_cusp.loop_blinn, LoopBlinnClass::cusp);
  // Cusp at infinity: x + y = 3 makes d3 = 0 (one finite inflection).
  const auto at_infinity = classify_cubic(canonical_cubic({-1, 4}));
  EXPECT_EQ(at_infinity.loop_blinn, LoopBlinnClass::cusp);
  EXPECT_EQ(at_infinity.type, CubicType::single_inflection);
}

Cubic random_cubic(test::Mulberry32& rng, double lo, double hi) {
  Cubic p;
  for (Point2& q : p) q = {rng.uniform(lo, hi), rng.uniform(lo, hi)};
  return p;
}

TEST(Classify, AgreesWithTheExactOracleOnRandomCubics) {
  // Full 53-bit random coordinates: the exact canonical point (rationals) and Pomax's
  // edges decide the type independently of core's predicates.
  for (const std::uint32_t seed : {1u, 2u}) {
    test::Mulberry32 rng(seed);
    for (int i = 0; i < 2500; ++i) {
      const Cubic p = random_cubic(rng, -1.0, 1.0);
      const auto c = classify_cubic(p);
      ASSERT_EQ(c.type, test::exact_type(p)) << "seed " << seed << " cubic " << i;
      // The returned (rounded) canonical point lies in the same region: none of these
      // random cubics is within rounding of an edge.
      if (c.canonical_point) {
        ASSERT_EQ(canonical_region(*c.canonical_point), c.type)
            << "seed " << seed << " cubic " << i;
      }
      EXPECT_TRUE(c.exact);
      // The fast path and the exact path decide the same signs.
      const auto fast = cubic_predicates(std::span<const Point2, 4>(p));
      const auto slow = cubic_predicates_exact(std::span<const Point2, 4>(p));
      ASSERT_EQ(fast.sign.disc, slow.sign.disc);
      ASSERT_EQ(fast.sign.l0, slow.sign.l0);
      ASSERT_EQ(fast.sign.l1, slow.sign.l1);
      ASSERT_EQ(fast.sign.i1, slow.sign.i1);
      ASSERT_EQ(fast.sign.d2_plus_2d3, slow.sign.d2_plus_2d3);
    }
  }
}

TEST(Classify, AgreesWithCanonicalRegionOnGridPoints) {
  // Canonical points on a dyadic grid, mapped back by dyadic maps: the cubic's type, the
  // region of its canonical point, and the exact oracle must all agree. Grid steps 1/8 in
  // x and 1/256 in y put many points exactly on the cusp edge (3 + 2x − x²)/4.
  test::Mulberry32 rng(7);
  int on_cusp_edge = 0;
  for (int i = 0; i < 4000; ++i) {
    const double x = std::floor(rng.uniform(-48, 48)) / 8;
    const double y = std::floor(rng.uniform(-4096, 1024)) / 256;
    const Point2 q{x, y};
    const CubicType region = canonical_region(q);
    ASSERT_EQ(region, test::exact_region(x, y)) << x << ", " << y;
    const Affine& m = kMaps[static_cast<std::size_t>(i) % kMaps.size()];
    const Cubic p = m(canonical_cubic(q));
    ASSERT_EQ(classify_cubic(p).type, region) << x << ", " << y;
    if (y == (3 + 2 * x - x * x) / 4) ++on_cusp_edge;
  }
  EXPECT_GT(on_cusp_edge, 0);
}

TEST(Classify, DirectMathOnRandomCubics) {
  // The parameters satisfy their defining equations: B' × B'' = 0 at inflections,
  // B(t1) = B(t2) at the double point; and the inflection count matches the sign changes
  // of B' × B'' on a fine grid when no root is within the grid's resolution of another
  // or of an end.
  test::Mulberry32 rng(3);
  int loops = 0, inflections = 0;
  for (int i = 0; i < 3000; ++i) {
    const Cubic p = random_cubic(rng, -1.0, 1.0);
    const Curve curve(std::vector<Point2>(p.begin(), p.end()));
    const auto c = classify(curve);
    // B' and B'' straight from the Bernstein form of the hodographs.
    const auto kappa = [&](double t) {
      const double s = 1 - t;
      const Point2 d1 =
          3 * (s * s * (p[1] - p[0]) + 2 * s * t * (p[2] - p[1]) + t * t * (p[3] - p[2]));
      const Point2 d2 = 6 * (s * (p[2] - 2 * p[1] + p[0]) + t * (p[3] - 2 * p[2] + p[1]));
      return cross(d1, d2);
    };
    for (const double t : c.inflections.values()) {
      const auto d = derivatives_at(curve, t, 2);
      EXPECT_LE(std::fabs(cross(d[0], d[1])), 1e-10 * length(d[0]) * length(d[1]) + 1e-12);
      ++inflections;
    }
    if (c.self_intersection) {
      ++loops;
      const double t1 = c.self_intersection->t1, t2 = c.self_intersection->t2;
      EXPECT_LT(t1, t2);
      EXPECT_LE(length(evaluate(curve, t1) - evaluate(curve, t2)), 1e-9);
      EXPECT_LE(length(evaluate(curve, t1) - c.self_intersection->point), 1e-9);
    }
    constexpr int kSteps = 2048;
    int changes = 0;
    bool ambiguous = false;
    double previous = kappa(0.0);
    for (int k = 1; k <= kSteps; ++k) {
      const double value = kappa(static_cast<double>(k) / kSteps);
      if ((value < 0) != (previous < 0)) ++changes;
      previous = value;
    }
    for (const double t : c.inflections.values()) ambiguous |= t < 1e-3 || t > 1 - 1e-3;
    if (c.inflections.count == 2) ambiguous |= c.inflections.t[1] - c.inflections.t[0] < 1e-3;
    if (!ambiguous && c.type != CubicType::cusp) {
      EXPECT_EQ(changes, c.inflections.count) << i;
    }
  }
  EXPECT_GT(loops, 50);
  EXPECT_GT(inflections, 500);
}

TEST(Classify, ReversalMirrorsTypeAndParameters) {
  test::Mulberry32 rng(4);
  for (int i = 0; i < 2000; ++i) {
    const Cubic p = random_cubic(rng, -3.0, 3.0);
    const auto c = classify_cubic(p);
    const auto r = classify_cubic(reversed_cubic(p));
    ASSERT_EQ(r.type, test::mirrored(c.type));
    ASSERT_EQ(r.inflections.count, c.inflections.count);
    for (int k = 0; k < c.inflections.count; ++k) {
      EXPECT_NEAR(r.inflections.t[static_cast<std::size_t>(c.inflections.count - 1 - k)],
                  1 - c.inflections.t[static_cast<std::size_t>(k)], 1e-12);
    }
    ASSERT_EQ(r.self_intersection.has_value(), c.self_intersection.has_value());
    if (c.self_intersection) {
      EXPECT_NEAR(r.self_intersection->t1, 1 - c.self_intersection->t2, 1e-12);
      EXPECT_NEAR(r.self_intersection->t2, 1 - c.self_intersection->t1, 1e-12);
    }
  }
}

TEST(Classify, InvariantUnderExactAffineMapsAndScaling) {
  // Coordinates on a 2^-20 grid keep every dyadic map exact: the images classify the same.
  test::Mulberry32 rng(5);
  for (int i = 0; i < 1500; ++i) {
    Cubic p = random_cubic(rng, -2.0, 2.0);
    for (Point2& q : p)
      q = {std::ldexp(std::round(std::ldexp(q.x, 20)), -20),
           std::ldexp(std::round(std::ldexp(q.y, 20)), -20)};
    const auto c = classify_cubic(p);
    for (const Affine& m : kMaps) {
      const auto mc = classify_cubic(m(p));
      ASSERT_EQ(mc.type, c.type) << i;
      ASSERT_EQ(mc.inflections.count, c.inflections.count);
      for (int k = 0; k < c.inflections.count; ++k) {
        EXPECT_NEAR(mc.inflections.t[static_cast<std::size_t>(k)],
                    c.inflections.t[static_cast<std::size_t>(k)], 1e-12);
      }
    }
    // Powers of two far beyond the filter's range (the exact path then decides) and
    // ordinary decimal scales from 1e-8 to 1e8 (rounded: the oracle decides).
    for (const int e : {-600, -300, -60, 60, 300, 600}) {
      Cubic s = p;
      for (Point2& q : s) q = {std::ldexp(q.x, e), std::ldexp(q.y, e)};
      ASSERT_EQ(classify_cubic(s).type, c.type) << i << " scaled by 2^" << e;
    }
    for (const double f : {1e-8, 1e8}) {
      Cubic s = p;
      for (Point2& q : s) q = f * q;
      ASSERT_EQ(classify_cubic(s).type, test::exact_type(s)) << i << " scaled by " << f;
    }
  }
}

// Coordinates at the ends of the double range: the type is the exact oracle's, the double
// point finite and ordered.
// a loop whose double point sits within two ulps of t = 1
// on a cubic with coordinates 2^250 apart. The exact signs say 0 < t1 < t2 < 1; t1 rounds to
// 1, and clamping t2 below 1 alone would reverse the pair (t1 = 1 > t2). The type is the
// exact rational oracle's; the pair must keep its order and stay strictly inside (0, 1).
TEST(ClassifyExtremes, LoopNextToAnEndKeepsItsParametersOrdered) {
  const std::array<Point2, 4> p{
      Point2{-0x1.f2fc8ffffff65p+260, -0x1.62fc8fffffff1p+261}, Point2{0x1.62fc8fffffff1p+261, 0.0},
      Point2{-0x1.1548p+11, -0x1.1548p+10}, Point2{0x1.1548p+10, -0x1.1548p+10}};
  const CubicClassification c = classify(p);
  ASSERT_TRUE(c.exact);
  EXPECT_EQ(c.type, bezier::test::exact_type(p));
  ASSERT_EQ(c.type, CubicType::loop);
  ASSERT_TRUE(c.self_intersection.has_value());
  const CubicDoublePoint& d = *c.self_intersection;
  EXPECT_TRUE(d.on_segment);
  EXPECT_LT(0.0, d.t1);
  EXPECT_LT(d.t1, d.t2);
  EXPECT_LT(d.t2, 1.0);
}

// Finite coordinates more than the largest
// double apart. The differences P_i - P_0 overflow to infinity and the filter's finiteness
// assertion, written on their sum (inf - inf = NaN), aborted; release builds took the exact
// path, which rescales. The type must be the exact oracle's (the assertion itself is checked
// by the fuzz build only: this build has none).
TEST(ClassifyExtremes, CoordinatesFartherApartThanTheLargestDoubleAreClassified) {
  const std::array<std::array<Point2, 4>, 4> cubics{{
      {Point2{1.5e308, -1.5e308}, Point2{-1.5e308, 1.5e308}, Point2{-1e308, -1e308},
       Point2{1e308, 1e308}},  // differences -inf and +inf: their sum is NaN
      {Point2{-1.5e308, 0.0}, Point2{1.5e308, 1e300}, Point2{0.0, 1e308}, Point2{1e300, -1e308}},
      {Point2{-1.7e308, -1.7e308}, Point2{1.7e308, 1.7e308}, Point2{1.7e308, -1.7e308},
       Point2{-1.7e308, 1.7e308}},
      {Point2{1e308, 0.0}, Point2{-1e308, 1e308}, Point2{-1e308, -1e308}, Point2{1e308, 1e299}},
  }};
  for (const auto& p : cubics) {
    const CubicClassification c = classify(p);
    EXPECT_TRUE(c.exact);
    EXPECT_EQ(c.type, bezier::test::exact_type(p));
  }
}

// A loop on a cubic with coordinates near the largest double.
// The double point is the mean of B(t1) and B(t2); half their sum would overflow to
// -inf. Both points lie in the control points' convex hull, so their mean does:
// it must be finite and inside the control points' bounding box.
TEST(ClassifyExtremes, DoublePointNearTheLargestDoubleIsFinite) {
  const std::array<Point2, 4> p{Point2{0.0, -0x1.7000001f00108p+1023},
                                Point2{-0x1.7000001f0efefp+1023, 0x1.7000001f0efefp+1023},
                                Point2{-0x1.7000001f0efefp+1023, -0x1.fffffffcp-50},
                                Point2{0.0, 0.0}};
  const CubicClassification c = classify(p);
  ASSERT_TRUE(c.self_intersection.has_value());
  const Point2 d = c.self_intersection->point;
  double x_lo = p[0].x, x_hi = p[0].x, y_lo = p[0].y, y_hi = p[0].y;
  for (const Point2& q : p) {
    x_lo = std::min(x_lo, q.x);
    x_hi = std::max(x_hi, q.x);
    y_lo = std::min(y_lo, q.y);
    y_hi = std::max(y_hi, q.y);
  }
  EXPECT_TRUE(std::isfinite(d.x) && std::isfinite(d.y));
  EXPECT_TRUE(x_lo <= d.x && d.x <= x_hi && y_lo <= d.y && d.y <= y_hi);
}

}  // namespace
}  // namespace bezier::core
