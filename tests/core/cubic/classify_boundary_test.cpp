// Cubics exactly on the edges of the Stone–DeRose map: every edge and corner, mapped back
// into general position by affine maps with dyadic entries (reflections included, so the
// images are exact), and cubics built in general position from a chosen cusp, double
// point or inflection parameter. The type must be the edge's, and one ulp off the edge it
// must be the neighbouring region's as the exact oracle says: boundaries are decided
// exactly, not with an epsilon.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "core/cubic/canonical_form.hpp"
#include "core/cubic/classify.hpp"
#include "core/cubic/predicates.hpp"
#include "tests/core/cubic/classify_oracle.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

using Cubic = std::array<Point2, 4>;

struct Affine {
  double a, b, c, d, e, f;
  [[nodiscard]] Point2 operator()(Point2 p) const {
    return {a * p.x + b * p.y + e, c * p.x + d * p.y + f};
  }
  [[nodiscard]] Cubic operator()(const Cubic& q) const {
    return {(*this)(q[0]), (*this)(q[1]), (*this)(q[2]), (*this)(q[3])};
  }
};

// Fixed maps (identity, reflections in both axes and the diagonal, shears, scalings by
// 2^±k) and random ones with entries in {k/8}; all have det != 0.
std::vector<Affine> dyadic_maps() {
  std::vector<Affine> maps = {
      {1, 0, 0, 1, 0, 0},
      {-1, 0, 0, 1, 0, 0},
      {1, 0, 0, -1, 0.5, 0},
      {0, 1, 1, 0, -3, 2},
      {1, 0.5, 0, 1, 3, -2},
      {0, -2, 2, 0, -0.25, 0.75},
      {1.5, -0.75, 0.25, 2, -7, 1},
      {0x1p-30, 0, 0, 0x1p-30, 0, 0},
      {0x1p40, 0, 0, -0x1p40, 0x1p41, 0},
  };
  test::Mulberry32 rng(11);
  while (maps.size() < 24) {
    const auto entry = [&rng] { return std::floor(rng.uniform(-16, 17)) / 8; };
    const Affine m{entry(), entry(), entry(), entry(), entry() * 4, entry() * 4};
    if (m.a * m.d - m.b * m.c != 0) maps.push_back(m);
  }
  return maps;
}

Cubic canonical_cubic(Point2 q) {
  return {Point2{0, 0}, Point2{0, 1}, Point2{1, 1}, q};
}
Cubic reversed_cubic(const Cubic& p) {
  return {p[3], p[2], p[1], p[0]};
}
CubicClassification classify_cubic(const Cubic& p) {
  return classify(std::span<const Point2, 4>(p));
}

// The fast (filtered) path and the exact path decide every sign alike.
void expect_paths_agree(const Cubic& p) {
  const CubicSigns a = cubic_predicates(std::span<const Point2, 4>(p)).sign;
  const CubicSigns b = cubic_predicates_exact(std::span<const Point2, 4>(p)).sign;
  EXPECT_EQ(a.d1, b.d1);
  EXPECT_EQ(a.d2, b.d2);
  EXPECT_EQ(a.d3, b.d3);
  EXPECT_EQ(a.d2_plus_2d3, b.d2_plus_2d3);
  EXPECT_EQ(a.i1, b.i1);
  EXPECT_EQ(a.disc, b.disc);
  EXPECT_EQ(a.l0, b.l0);
  EXPECT_EQ(a.l1, b.l1);
}

// Classifies q's canonical cubic under every map; one ulp moves of the image's P3 must
// follow the exact oracle. Returns how many of those moves left the edge's type.
int check_edge_point(Point2 q, CubicType expected) {
  EXPECT_EQ(canonical_region(q), expected) << q.x << ", " << q.y;
  EXPECT_EQ(test::exact_region(q.x, q.y), expected) << q.x << ", " << q.y;
  int left_the_edge = 0;
  for (const Affine& m : dyadic_maps()) {
    const Cubic p = m(canonical_cubic(q));
    const CubicClassification c = classify_cubic(p);
    EXPECT_EQ(c.type, expected) << "q = (" << q.x << ", " << q.y << ")";
    EXPECT_TRUE(c.exact);
    expect_paths_agree(p);
    // One ulp of the cubic's scale (a zero coordinate moved by one ulp of itself would be a
    // subnormal, far outside the exactness window; see ReportsWhenTheInputSpansTooManyBinades).
    double scale = 0;
    for (const Point2& pt : p) scale = std::fmax(scale, max_abs_coordinate(pt));
    const double ulp = std::nextafter(scale, INFINITY) - scale;
    for (const double step : {-ulp, ulp}) {
      for (const int axis : {0, 1}) {
        Cubic moved = p;
        (axis == 0 ? moved[3].x : moved[3].y) += step;
        const CubicClassification mc = classify_cubic(moved);
        EXPECT_TRUE(mc.exact);
        EXPECT_EQ(mc.type, test::exact_type(moved)) << "q = (" << q.x << ", " << q.y << ") moved";
        if (mc.type != expected) ++left_the_edge;
      }
    }
  }
  return left_the_edge;
}

TEST(ClassifyBoundary, CuspEdgeUpToXEqualsOne) {
  // y = (3 + 2x − x²)/4, exact for x on a 1/16 grid; B'(t) = 0 at t = 2/(3 − x).
  std::vector<double> xs = {-8, -3, -1.5, -1, -0.5, -0.25, 0, 0.125, 0.5, 0.75, 0.9375, 1};
  test::Mulberry32 rng(21);
  for (int i = 0; i < 40; ++i) xs.push_back(std::floor(rng.uniform(-160, 17)) / 16);
  int left = 0;
  for (const double x : xs) {
    const Point2 q{x, (3 + 2 * x - x * x) / 4};
    left += check_edge_point(q, CubicType::cusp);
    for (const Affine& m : dyadic_maps()) {
      const auto c = classify_cubic(m(canonical_cubic(q)));
      ASSERT_TRUE(c.cusp.has_value());
      EXPECT_NEAR(*c.cusp, 2 / (3 - x), 4e-16);
      EXPECT_EQ(c.loop_blinn, LoopBlinnClass::cusp);
      EXPECT_TRUE(c.inflections.values().empty());
      EXPECT_FALSE(c.self_intersection.has_value());
    }
  }
  EXPECT_GT(left, 0);
}

TEST(ClassifyBoundary, CuspEdgeBeyondXEqualsOneIsAnArch) {
  // The cusp is at t = 2/(3 − x) > 1 (or < 0 beyond x = 3): not on the segment.
  // Only the unbounded curve's class changes across it (loop below, serpentine above).
  int changed_class = 0;
  for (const double x : {1.125, 1.5, 2.0, 2.5, 3.5, 4.0, 8.0}) {
    const Point2 q{x, (3 + 2 * x - x * x) / 4};
    EXPECT_EQ(check_edge_point(q, CubicType::arch), 0);
    const auto c = classify_cubic(canonical_cubic(q));
    EXPECT_EQ(c.loop_blinn, LoopBlinnClass::cusp);
    EXPECT_FALSE(c.cusp.has_value());
    for (const double dy : {-0x1p-40, 0x1p-40}) {
      const auto moved = classify_cubic(canonical_cubic({x, q.y + dy}));
      EXPECT_EQ(moved.loop_blinn, dy < 0 ? LoopBlinnClass::loop : LoopBlinnClass::serpentine);
      changed_class += moved.loop_blinn != LoopBlinnClass::cusp;
    }
  }
  EXPECT_EQ(changed_class, 14);
}

TEST(ClassifyBoundary, LoopClosingAtStart) {
  // y = (3x − x²)/3 for x = 3m <= 0: y = 3m(1 − m); t1 = 0, t2 = 3/(3 − x) = 1/(1 − m).
  int left = 0;
  for (const double m : {-4.0, -2.0, -1.0, -0.5, -0.25, -0.125, -1.0 / 64}) {
    const Point2 q{3 * m, 3 * m * (1 - m)};
    left += check_edge_point(q, CubicType::loop_at_start);
    for (const Affine& map : dyadic_maps()) {
      const Cubic p = map(canonical_cubic(q));
      const auto c = classify_cubic(p);
      ASSERT_TRUE(c.self_intersection.has_value());
      EXPECT_EQ(c.self_intersection->t1, 0.0);
      EXPECT_NEAR(c.self_intersection->t2, 1 / (1 - m), 4e-16);
      EXPECT_EQ(c.self_intersection->point, p[0]);
      // Reversed, the same loop closes at the end: t2 = 1 exactly, the point is the last.
      const auto r = classify_cubic(reversed_cubic(p));
      EXPECT_EQ(r.type, CubicType::loop_at_end);
      ASSERT_TRUE(r.self_intersection.has_value());
      EXPECT_EQ(r.self_intersection->t2, 1.0);
      EXPECT_NEAR(r.self_intersection->t1, 1 - 1 / (1 - m), 4e-16);
      EXPECT_EQ(r.self_intersection->point, p[0]);
      expect_paths_agree(reversed_cubic(p));
    }
  }
  EXPECT_GT(left, 0);
  // The same curve for 0 < x <= 3 is no edge: the loop's other end 3/(3 − x) is past 1.
  for (const double m : {0.125, 0.25, 0.5, 0.75}) {
    const Point2 q{3 * m, 3 * m * (1 - m)};
    EXPECT_EQ(classify_cubic(canonical_cubic(q)).type, CubicType::arch);
    EXPECT_EQ(canonical_region(q), CubicType::arch);
  }
}

TEST(ClassifyBoundary, InflectionExactlyAtTheEnd) {
  // y = 1: I(t) ∝ −1 + (3 − x) t + (x − 2) t² = −(t − 1)((x − 2) t + 1): roots 1 and 1/(2 − x).
  int left = 0;
  for (const double x : {-4.0, -1.0, 0.0, 0.5, 0.875}) {
    left += check_edge_point({x, 1}, CubicType::double_inflection);
    for (const Affine& m : dyadic_maps()) {
      const auto c = classify_cubic(m(canonical_cubic({x, 1})));
      ASSERT_EQ(c.inflections.count, 2);
      EXPECT_NEAR(c.inflections.t[0], 1 / (2 - x), 4e-16);
      EXPECT_EQ(c.inflections.t[1], 1.0);
      ASSERT_TRUE(c.canonical_point.has_value());
      EXPECT_EQ(c.canonical_point->y, 1.0);
    }
  }
  for (const double x : {1.125, 1.5, 2.0, 3.0, 6.0}) {
    left += check_edge_point({x, 1}, CubicType::single_inflection);
    for (const Affine& m : dyadic_maps()) {
      const auto c = classify_cubic(m(canonical_cubic({x, 1})));
      ASSERT_EQ(c.inflections.count, 1);
      EXPECT_EQ(c.inflections.t[0], 1.0);
    }
  }
  EXPECT_GT(left, 0);
}

TEST(ClassifyBoundary, Corners) {
  // (1, 1): P3 = P2, where the cusp edge, y = 1 and the loop-at-end edge meet: a cusp at
  // t = 1 takes precedence over the inflection and the loop.
  check_edge_point({1, 1}, CubicType::cusp);
  for (const Affine& m : dyadic_maps()) {
    const auto c = classify_cubic(m(canonical_cubic({1, 1})));
    ASSERT_TRUE(c.cusp.has_value());
    EXPECT_EQ(*c.cusp, 1.0);
  }
  // (0, 0): P3 = P0, where both loop edges meet: a closed curve, t = (0, 1).
  check_edge_point({0, 0}, CubicType::loop_at_start);
  for (const Affine& m : dyadic_maps()) {
    const Cubic p = m(canonical_cubic({0, 0}));
    const auto c = classify_cubic(p);
    ASSERT_TRUE(c.self_intersection.has_value());
    EXPECT_EQ(c.self_intersection->t1, 0.0);
    EXPECT_EQ(c.self_intersection->t2, 1.0);
    EXPECT_EQ(c.self_intersection->point, p[0]);
  }
  // (3, 0): P3 − 3 P2 + 3 P1 − P0 = 0, the quadratic.
  check_edge_point({3, 0}, CubicType::quadratic);
}

TEST(ClassifyBoundary, CuspAtInfinityLine) {
  // x + y = 3 makes d3 = 0: I is linear, Loop–Blinn's discriminant vanishes (cusp at t = ∞).
  for (const Point2 q : {Point2{-1, 4}, Point2{0, 3}, Point2{4, -1}, Point2{5, -2}, Point2{2, 1}}) {
    for (const Affine& m : dyadic_maps()) {
      const Cubic p = m(canonical_cubic(q));
      const auto c = classify_cubic(p);
      EXPECT_EQ(c.loop_blinn, LoopBlinnClass::cusp);
      EXPECT_EQ(c.type, test::exact_type(p));
      expect_paths_agree(p);
    }
  }
}

// Control points P0 + (0, a, 2a + b, 3a + 3b + c): B(t) = P0 + 3at + 3bt² + ct³.
Cubic from_power_form(Point2 p0, Point2 a, Point2 b, Point2 c) {
  return {p0, p0 + a, p0 + 2 * a + b, p0 + 3 * a + 3 * b + c};
}

Point2 random_lattice_point(test::Mulberry32& rng, double range) {
  return {std::floor(rng.uniform(-range, range + 1)), std::floor(rng.uniform(-range, range + 1))};
}

TEST(ClassifyBoundary, LoopBuiltFromItsParameters) {
  // B(s) = B(t) with s != t iff 3a + 3b(s + t) + c(s² + st + t²) = 0. For s = i/8, t = j/8,
  // a = N a0, b = N b0 with N = i² + ij + j², c = −(192 a0 + 24 (i + j) b0) is integral.
  test::Mulberry32 rng(31);
  const std::vector<Affine> maps = dyadic_maps();
  int built = 0;
  for (int i = -3; i <= 8; ++i) {
    for (int j = i + 1; j <= 11; ++j) {
      const double n = i * i + i * j + j * j;
      Point2 a0 = random_lattice_point(rng, 6), b0 = random_lattice_point(rng, 6);
      if (cross(a0, b0) == 0) continue;
      const Point2 c = -(192 * a0 + 24.0 * (i + j) * b0);
      const Cubic base = from_power_form(random_lattice_point(rng, 50), n * a0, n * b0, c);
      const double s = i / 8.0, t = j / 8.0;
      const bool on_segment = i >= 0 && j <= 8;
      const CubicType expected = !on_segment ? CubicType::arch
                                 : i == 0    ? CubicType::loop_at_start
                                 : j == 8    ? CubicType::loop_at_end
                                             : CubicType::loop;
      for (const Affine& m : maps) {
        const Cubic p = m(base);
        const auto c_p = classify_cubic(p);
        ASSERT_EQ(c_p.type, expected) << "s = " << s << ", t = " << t;
        ASSERT_EQ(c_p.type, test::exact_type(p));
        EXPECT_EQ(c_p.loop_blinn, LoopBlinnClass::loop);
        const auto dp = cubic_double_point(std::span<const Point2, 4>(p));
        ASSERT_TRUE(dp.has_value());
        EXPECT_EQ(dp->on_segment, on_segment);
        EXPECT_NEAR(dp->t1, s, 1e-14);
        EXPECT_NEAR(dp->t2, t, 1e-14);
        if (i == 0) {
          EXPECT_EQ(dp->t1, 0.0);
        }
        if (j == 8) {
          EXPECT_EQ(dp->t2, 1.0);
        }
        expect_paths_agree(p);
      }
      ++built;
    }
  }
  EXPECT_GT(built, 60);
}

TEST(ClassifyBoundary, CuspBuiltFromItsParameter) {
  // B'(τ) = 0 iff a + 2bτ + cτ² = 0. For τ = k/8, a = k² a0, b = k² b0:
  // c = −(64 a0 + 16 k b0) is integral. k = 0 is P0 = P1 (a = 0, any c).
  test::Mulberry32 rng(41);
  const std::vector<Affine> maps = dyadic_maps();
  for (int k = -4; k <= 12; ++k) {
    for (int trial = 0; trial < 4; ++trial) {
      const Point2 a0 = random_lattice_point(rng, 5), b0 = random_lattice_point(rng, 5);
      if (cross(a0, b0) == 0) continue;
      const double kk = k * k;
      const Point2 c = k == 0 ? random_lattice_point(rng, 20) : -(64 * a0 + 16.0 * k * b0);
      const Cubic base = from_power_form(random_lattice_point(rng, 50), kk * a0, kk * b0, c);
      if (test::exact_type(base) == CubicType::line) continue;  // k = 0 with c ∥ b
      const double tau = k / 8.0;
      const bool inside = k >= 0 && k <= 8;
      for (const Affine& m : maps) {
        const Cubic p = m(base);
        const auto cl = classify_cubic(p);
        ASSERT_EQ(cl.type, inside ? CubicType::cusp : CubicType::arch) << "tau = " << tau;
        ASSERT_EQ(cl.type, test::exact_type(p));
        EXPECT_EQ(cl.loop_blinn, LoopBlinnClass::cusp);
        if (inside) {
          ASSERT_TRUE(cl.cusp.has_value());
          EXPECT_NEAR(*cl.cusp, tau, 1e-15);
          if (k == 0 || k == 8) {
            EXPECT_EQ(*cl.cusp, tau);
          }
        }
        expect_paths_agree(p);
      }
    }
  }
}

TEST(ClassifyBoundary, InflectionAtAnEndBuiltInGeneralPosition) {
  // I(1) = a × b + (a + b) × c = 0 for c = α a + (α − 1) b; with a = 4 a0, b = 4 b0 and
  // α = k/4, c = k a0 + (k − 4) b0. Reversed, the inflection is at t = 0.
  test::Mulberry32 rng(51);
  const std::vector<Affine> maps = dyadic_maps();
  int with_inflection = 0;
  for (int k = -12; k <= 12; ++k) {
    const Point2 a0 = random_lattice_point(rng, 5), b0 = random_lattice_point(rng, 5);
    if (cross(a0, b0) == 0) continue;
    const Cubic base =
        from_power_form(random_lattice_point(rng, 50), 4 * a0, 4 * b0, k * a0 + (k - 4.0) * b0);
    for (const Affine& m : maps) {
      const Cubic p = m(base);
      const auto c = classify_cubic(p);
      ASSERT_EQ(c.type, test::exact_type(p)) << k;
      const auto r = classify_cubic(reversed_cubic(p));
      ASSERT_EQ(r.type, test::mirrored(c.type));
      if (c.type == CubicType::cusp) continue;  // k = 4 puts P2 = P3: the cusp wins
      ASSERT_GE(c.inflections.count, 1) << k;
      EXPECT_EQ(c.inflections.t[static_cast<std::size_t>(c.inflections.count - 1)], 1.0);
      EXPECT_EQ(r.inflections.t[0], 0.0);
      expect_paths_agree(p);
      ++with_inflection;
    }
  }
  EXPECT_GT(with_inflection, 100);
}

TEST(ClassifyBoundary, ExtremeScalesStayExact) {
  // Far outside the floating-point filter's range (largest coordinate difference 2^±200)
  // the exact path decides, after an exact power-of-two rescaling.
  const std::vector<std::pair<Point2, CubicType>> cases = {{{-1, 0}, CubicType::cusp},
                                                           {{-3, -6}, CubicType::loop_at_start},
                                                           {{0, 1}, CubicType::double_inflection},
                                                           {{1.5, 1}, CubicType::single_inflection},
                                                           {{2, 0.75}, CubicType::arch},
                                                           {{1, 1}, CubicType::cusp}};
  for (const auto& [q, type] : cases) {
    for (const int e : {-1000, -700, -400, -250, 250, 400, 700, 900}) {
      Cubic p = canonical_cubic(q);
      for (Point2& pt : p) pt = {std::ldexp(pt.x + 3, e), std::ldexp(pt.y - 5, e)};
      const auto c = classify_cubic(p);
      EXPECT_EQ(c.type, type) << q.x << ", " << q.y << " at 2^" << e;
      EXPECT_TRUE(c.exact);
    }
  }
}

TEST(ClassifyBoundary, ReportsWhenTheInputSpansTooManyBinades) {
  // A coordinate 2^-500 next to coordinates of size 1 underflows in the exact path's
  // products: the signs are then not certified, and the result says so. P0 = P1 still
  // makes it a cusp at t = 0.
  const Cubic p = {Point2{0, 0}, Point2{0, 0}, Point2{1, 1}, Point2{2, 0x1p-500}};
  const auto c = classify_cubic(p);
  EXPECT_EQ(c.type, CubicType::cusp);
  EXPECT_FALSE(c.exact);
  // A closed curve opened by the smallest subnormal: l1 = d3² (1 − s)(1 − t) is far below
  // 2^-1074 in the exact path's units; the answer is flagged.
  const Cubic opened = {Point2{0, 0}, Point2{0, 1}, Point2{1, 1}, Point2{0, 0x1p-1074}};
  EXPECT_FALSE(classify_cubic(opened).exact);
  // Within 2^400 the exact path is exact.
  const Cubic q = {Point2{0, 0}, Point2{0, 0}, Point2{1, 1}, Point2{2, 0x1p-380}};
  EXPECT_TRUE(classify_cubic(q).exact);
}

}  // namespace
}  // namespace bezier::core
