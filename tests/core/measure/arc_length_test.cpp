// Tests of core/measure/arc_length.hpp: the length of a curve piece and its inverse.
//
// Independent truths: closed forms (lines, the parabolas y = x^2 and y = 64 x^2, the cusp
// cubic (0,0),(1,1),(0,1),(1,0) whose speed is 3|1-2t| sqrt((1-2t)^2 + 1), a line that turns
// back), a long-double reference quadrature on a mesh graded geometrically toward the known
// minimum of |B'|, exact degree elevation, and properties (additivity, exact rotation and
// scaling, reversal, 3-D embedding, the inverse round trip). Most hold at every tolerance
// from 1e-2 to the API's 1e-12: the error within the tolerance and within the error_bound
// reported, two answers for one length within the sum of their bounds.

#include "core/measure/arc_length.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "core/curve/derivative.hpp"
#include "core/numeric/unit_roundoff.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

constexpr double kTolerance = 1e-12;

/// The API's tolerance and looser ones a kernel caller may ask for (the loosest are met by
/// the lowest rules on few pieces, where an estimate that understates the error would show).
constexpr std::array<double, 6> kTolerances = {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12};

ArcLengthOptions at(double tolerance) {
  ArcLengthOptions options;
  options.relative_tolerance = tolerance;
  return options;
}

/// The length holds its tolerance: relative error <= tolerance, the reported bound met and
/// covering the actual error.
void expect_length(const ArcLength& got, long double exact, double tolerance = kTolerance) {
  EXPECT_TRUE(got.tolerance_met);
  const long double error = std::fabs(static_cast<long double>(got.length) - exact);
  EXPECT_LE(error, tolerance * exact) << "length " << got.length << " exact " << static_cast<double>(exact)
                                      << " tolerance " << tolerance;
  EXPECT_LE(got.error_bound, tolerance * got.length);
  EXPECT_GE(got.error_bound, static_cast<double>(error))
      << "the bound does not cover the error at tolerance " << tolerance;
}

/// |B'(t)| in long double from the curve's control points (hodograph and de Casteljau).
long double reference_speed(const Curve& curve, long double t) {
  const auto p = curve.points();
  const std::size_t n = p.size() - 1;
  std::vector<long double> x, y;
  for (std::size_t i = 0; i < n; ++i) {
    x.push_back(n * (static_cast<long double>(p[i + 1].x) - p[i].x));
    y.push_back(n * (static_cast<long double>(p[i + 1].y) - p[i].y));
  }
  for (std::size_t level = x.size() - 1; level > 0 && !x.empty(); --level) {
    for (std::size_t k = 0; k < level; ++k) {
      x[k] = (1 - t) * x[k] + t * x[k + 1];
      y[k] = (1 - t) * y[k] + t * y[k + 1];
    }
  }
  return std::hypot(x[0], y[0]);
}

/// ∫ |B'| on [a, b] by 5-point Gauss-Legendre in long double on a mesh graded
/// geometrically toward `focus` (cells [focus + 2^-(k+1) w, focus + 2^-k w], each in 32),
/// which resolves a kink or a near-kink of |B'| at focus.
long double reference_length(const Curve& curve, long double a, long double b, long double focus) {
  const long double r = std::sqrt(10.0L / 7.0L);
  const long double nodes[5] = {0.0L, std::sqrt(5 - 2 * r) / 3, -std::sqrt(5 - 2 * r) / 3,
                                std::sqrt(5 + 2 * r) / 3, -std::sqrt(5 + 2 * r) / 3};
  const long double s70 = std::sqrt(70.0L);
  const long double weights[5] = {128.0L / 225, (322 + 13 * s70) / 900, (322 + 13 * s70) / 900,
                                  (322 - 13 * s70) / 900, (322 - 13 * s70) / 900};
  const auto cell = [&](long double lo, long double hi) {
    long double sum = 0;
    for (int j = 0; j < 32; ++j) {
      const long double c0 = lo + (hi - lo) * j / 32, c1 = lo + (hi - lo) * (j + 1) / 32;
      const long double mid = (c0 + c1) / 2, half = (c1 - c0) / 2;
      for (int k = 0; k < 5; ++k) sum += weights[k] * half * reference_speed(curve, mid + half * nodes[k]);
    }
    return sum;
  };
  const auto graded = [&](long double from, long double to) {  // graded toward `from`
    long double sum = 0, outer = to;
    for (int k = 1; k <= 64; ++k) {
      const long double inner = from + (to - from) * std::ldexp(1.0L, -k);
      sum += cell(inner, outer);
      outer = inner;
    }
    return sum;
  };
  long double total = 0;
  if (a < focus) total += std::fabs(graded(focus, a));
  if (focus < b) total += std::fabs(graded(focus, b));
  return total;
}

TEST(ArcLength, LineIsItsChord) {
  for (const double tolerance : kTolerances) {
    expect_length(arc_length(Curve({{0, 0}, {3, 4}}), 0, 1, at(tolerance)), 5.0L, tolerance);
    expect_length(arc_length(Curve({{1, 1}, {4, 5}, {7, 9}}), 0, 1, at(tolerance)), 10.0L, tolerance);
    // x = 3t^2, y = 4t^2: |B'| = 10t vanishes at the start; length 5.
    expect_length(arc_length(Curve({{0, 0}, {0, 0}, {3, 4}}), 0, 1, at(tolerance)), 5.0L, tolerance);
    // A piece of a line on [1/4, 3/4]: half the chord.
    expect_length(arc_length(Curve({{0, 0}, {6, 8}}), 0.25, 0.75, at(tolerance)), 5.0L, tolerance);
  }
}

TEST(ArcLength, LineThatTurnsBackIsTheDistanceTravelled) {
  // Along (3, 4)/5: s(t) = 5 (6t - 7t^2) turns at t = 3/7 (B' = 0 there, a cusp) at
  // s = 45/7, ends at -5: length 45/7 + 45/7 + 5 = 125/7.
  for (const double tolerance : kTolerances) {
    expect_length(arc_length(Curve({{0, 0}, {9, 12}, {-3, -4}}), 0, 1, at(tolerance)), 125.0L / 7.0L, tolerance);
  }
}

TEST(ArcLength, ParabolaClosedForm) {
  // y = x^2 on [0, 1]: ∫ sqrt(1 + 4x^2) dx = sqrt(5)/2 + asinh(2)/4.
  const long double exact = std::sqrt(5.0L) / 2 + std::asinh(2.0L) / 4;
  // y = 64 x^2 on [0, 1]: the speed varies by a factor of 128 (asinh(128)/256 + sqrt(16385)/2).
  const long double steep = std::asinh(128.0L) / 256 + std::sqrt(16385.0L) / 2;
  const double s = 0x1p20;
  for (const double tolerance : kTolerances) {
    expect_length(arc_length(Curve({{0, 0}, {0.5, 0}, {1, 1}}), 0, 1, at(tolerance)), exact, tolerance);
    // Scaled by 2^20 and moved: the same relative accuracy.
    expect_length(arc_length(Curve({{7 * s, -3 * s}, {7.5 * s, -3 * s}, {8 * s, -2 * s}}), 0, 1, at(tolerance)),
                  exact * s, tolerance);
    expect_length(arc_length(Curve({{0, 0}, {0.5, 0}, {1, 64}}), 0, 1, at(tolerance)), steep, tolerance);
  }
}

TEST(ArcLength, CuspCubicClosedForm) {
  // B' = 3 (1 - 2t) ((1 - 2t), 1): with u = 1 - 2t, L = 3 ∫_0^1 u sqrt(u^2 + 1) du = 2 sqrt(2) - 1.
  const Curve cusp({{0, 0}, {1, 1}, {0, 1}, {1, 0}});
  for (const double tolerance : kTolerances) {
    expect_length(arc_length(cusp, 0, 1, at(tolerance)), 2 * std::sqrt(2.0L) - 1, tolerance);
    // Each half: (2 sqrt(2) - 1) / 2.
    expect_length(arc_length(cusp, 0, 0.5, at(tolerance)), (2 * std::sqrt(2.0L) - 1) / 2, tolerance);
    expect_length(arc_length(cusp, 0.5, 1, at(tolerance)), (2 * std::sqrt(2.0L) - 1) / 2, tolerance);
  }
}

TEST(ArcLength, NearCuspAgainstGradedReference) {
  // Hodograph 3 ((1-2t)^2 + d, 1 - 2t): |B'| has its minimum 3d at t = 1/2, a kink smoothed
  // over a width of about d.
  for (const double d : {0x1p-4, 0x1p-10, 0x1p-20, 0x1p-30}) {
    const Curve curve({{0, 0}, {1 + d, 1}, {d, 1}, {1 + 2 * d, 0}});
    const long double whole = reference_length(curve, 0, 1, 0.5L);
    const long double part = reference_length(curve, 0.125, 0.625, 0.5L);
    for (const double tolerance : kTolerances) {
      expect_length(arc_length(curve, 0, 1, at(tolerance)), whole, tolerance);
      expect_length(arc_length(curve, 0.125, 0.625, at(tolerance)), part, tolerance);
    }
  }
}

TEST(ArcLength, RandomCurvesAgainstReference) {
  test::Mulberry32 rng(20);
  int compared = 0;
  for (int degree = 1; degree <= 9; degree += 2) {
    for (int i = 0; i < 6; ++i) {
      std::vector<Point2> pts;
      for (int k = 0; k <= degree; ++k) pts.push_back({rng.uniform(-1, 1), rng.uniform(-1, 1)});
      const Curve curve(pts);
      // Two references on differently graded meshes; a curve where they disagree (a near-cusp
      // away from both foci) has no trustworthy reference here and is left out.
      const long double reference = reference_length(curve, 0, 1, 0.0L);
      const long double other = reference_length(curve, 0, 1, 0.5L);
      if (std::fabs(reference - other) > 1e-15L * reference) continue;
      ++compared;
      for (const double tolerance : kTolerances) expect_length(arc_length(curve, 0, 1, at(tolerance)), reference, tolerance);
    }
  }
  EXPECT_GE(compared, 15);
}

TEST(ArcLength, DegreeElevationLeavesLengthUnchanged) {
  // Elevation Q_i = i/(n+1) P_{i-1} + (1 - i/(n+1)) P_i is exact in doubles for n + 1 = 4
  // and small integer coordinates; the length of the same curve must agree.
  const std::vector<Point2> cubic = {{0, 0}, {4, 4}, {0, 4}, {4, 0}};
  std::vector<Point2> quartic = {cubic[0]};
  for (int i = 1; i <= 3; ++i) {
    const double w = i / 4.0;
    quartic.push_back(w * cubic[static_cast<std::size_t>(i - 1)] + (1 - w) * cubic[static_cast<std::size_t>(i)]);
  }
  quartic.push_back(cubic[3]);
  const double l3 = arc_length(Curve(cubic), 0, 1).length;
  const double l4 = arc_length(Curve(quartic), 0, 1).length;
  EXPECT_NEAR(l3, l4, 2 * kTolerance * l3);
  EXPECT_NEAR(l3, 4 * (2 * std::sqrt(2.0) - 1), 4 * kTolerance * l3);
}

/// |x - y| is covered by the bounds of x and y (each covers its own error) and `slack`.
void expect_within_bounds(double x, double x_bound, double y, double y_bound, double slack, const char* what) {
  EXPECT_LE(std::fabs(x - y), x_bound + y_bound + slack) << what << ": " << x << " against " << y;
}

TEST(ArcLength, AdditiveReversibleAndInvariant) {
  // Two answers for the same length differ by at most the sum of their error bounds, at any
  // tolerance; each answer holds its tolerance.
  test::Mulberry32 rng(7);
  for (int i = 0; i < 20; ++i) {
    const int degree = 1 + i % 7;
    std::vector<Point2> pts, rotated, moved;
    for (int k = 0; k <= degree; ++k) {
      // Multiples of 2^-20: the rotation-scaling [[3,-4],[4,3]] (factor 5) is exact on them.
      const double x = std::ldexp(std::floor(rng.uniform(-1, 1) * 0x1p20), -20);
      const double y = std::ldexp(std::floor(rng.uniform(-1, 1) * 0x1p20), -20);
      pts.push_back({x, y});
      rotated.push_back({3 * x - 4 * y, 4 * x + 3 * y});
      moved.push_back({x + 1024, y - 4096});
    }
    const Curve curve(pts), back = reversed(curve);
    const double t = rng.next();  // a multiple of 2^-32: 1 - t is exact
    for (const double tolerance : kTolerances) {
      const ArcLengthOptions options = at(tolerance);
      const ArcLength whole = arc_length(curve, 0, 1, options);
      const ArcLength left = arc_length(curve, 0, t, options), right = arc_length(curve, t, 1, options);
      const ArcLength turned = arc_length(Curve(rotated), 0, 1, options);
      const ArcLength shifted = arc_length(Curve(moved), 0, 1, options);
      const ArcLength back_whole = arc_length(back, 0, 1, options), back_left = arc_length(back, 1 - t, 1, options);
      for (const ArcLength* got : {&whole, &left, &right, &turned, &shifted, &back_whole, &back_left}) {
        EXPECT_TRUE(got->tolerance_met);
        EXPECT_LE(got->error_bound, tolerance * got->length);
      }
      // The sum and the product by 5 round within u of their value.
      const double rounding = 5 * kUnitRoundoff * whole.length;
      expect_within_bounds(left.length + right.length, left.error_bound + right.error_bound, whole.length,
                           whole.error_bound, rounding, "additivity");
      expect_within_bounds(turned.length, turned.error_bound, 5 * whole.length, 5 * whole.error_bound, rounding,
                           "rotation");
      expect_within_bounds(shifted.length, shifted.error_bound, whole.length, whole.error_bound, 0.0, "translation");
      expect_within_bounds(back_whole.length, back_whole.error_bound, whole.length, whole.error_bound, 0.0,
                           "reversal");
      expect_within_bounds(back_left.length, back_left.error_bound, left.length, left.error_bound, 0.0,
                           "reversal of a part");
    }
  }
}

TEST(ArcLength, SpaceCurves) {
  // The parabola y = x^2 in the plane spanned by (1, 0, 0) and (0, 3/5, 4/5), scaled by 5.
  const long double exact = 5 * (std::sqrt(5.0L) / 2 + std::asinh(2.0L) / 4);
  for (const double tolerance : kTolerances) {
    // A 3-D line: |(1, 2, 2)| = 3.
    expect_length(arc_length(Curve3({{0, 0, 0}, {1, 2, 2}}), 0, 1, at(tolerance)), 3.0L, tolerance);
    expect_length(arc_length(Curve3({{0, 0, 0}, {2.5, 0, 0}, {5, 3, 4}}), 0, 1, at(tolerance)), exact, tolerance);
    // The cusp cubic tilted the same way.
    expect_length(arc_length(Curve3({{0, 0, 0}, {5, 3, 4}, {0, 3, 4}, {5, 0, 0}}), 0, 1, at(tolerance)),
                  5 * (2 * std::sqrt(2.0L) - 1), tolerance);
  }
}

TEST(ArcLength, SpeedConcentratedAtOneEnd) {
  // P_0 = 0 and P_1 = ... = P_20 = (1, 2, 2): B' = 20 (1-t)^19 (1, 2, 2), so length(a, b) =
  // 3 ((1-a)^20 - (1-b)^20). The hodograph's largest point is 10^4 times the length on
  // [1/4, 3/4]: the rounding bound must follow the speed, not that point.
  std::vector<Point3> pts(21, Point3{1, 2, 2});
  pts[0] = Point3{0, 0, 0};
  const long double exact = 3 * (std::pow(0.75L, 20) - std::pow(0.25L, 20));
  for (const double tolerance : kTolerances) expect_length(arc_length(Curve3(pts), 0.25, 0.75, at(tolerance)), exact, tolerance);
}

TEST(ArcLength, CoordinatesNearTheDoubleRange) {
  // The cusp cubic scaled by 2^1000 and by 2^-1000: its hodograph's squared length would
  // overflow or underflow; the length scales exactly.
  for (const int e : {1000, -1000}) {
    const double s = std::ldexp(1.0, e);
    const Curve big({{0, 0}, {s, s}, {0, s}, {s, 0}});
    expect_length(arc_length(big, 0, 1), (2 * std::sqrt(2.0L) - 1) * static_cast<long double>(s));
    const ArcLength whole = arc_length(big, 0, 1);
    EXPECT_NEAR(parameter_at_length(big, whole, whole.length / 2), 0.5, 1e-7);
  }
}

TEST(ArcLength, EmptyIntervalIsZero) {
  const ArcLength got = arc_length(Curve({{0, 0}, {1, 1}, {0, 1}, {1, 0}}), 0.3, 0.3);
  EXPECT_EQ(got.length, 0.0);
  EXPECT_EQ(got.error_bound, 0.0);
  EXPECT_EQ(parameter_at_length(Curve({{0, 0}, {1, 1}}), got, 0.0), 0.3);
}

TEST(ArcLength, ParameterAtLengthRoundTrips) {
  const Curve cusp({{0, 0}, {1, 1}, {0, 1}, {1, 0}});
  for (const auto& [a, b] : {std::pair{0.0, 1.0}, std::pair{0.2, 0.9}}) {
    const ArcLength whole = arc_length(cusp, a, b);
    double previous = a;
    for (int k = 0; k <= 16; ++k) {
      const double l = whole.length * k / 16;
      const double t = parameter_at_length(cusp, whole, l);
      ASSERT_GE(t, a);
      ASSERT_LE(t, b);
      EXPECT_GE(t, previous);
      previous = t;
      EXPECT_NEAR(arc_length(cusp, a, t).length, l, 2 * kTolerance * whole.length) << "k " << k;
    }
    EXPECT_EQ(parameter_at_length(cusp, whole, 0.0), a);
    EXPECT_EQ(parameter_at_length(cusp, whole, whole.length), b);
  }
  // The cusp at t = 1/2 is at half the length: (2 sqrt(2) - 1) / 2 of each side.
  const ArcLength whole = arc_length(cusp, 0, 1);
  EXPECT_NEAR(parameter_at_length(cusp, whole, whole.length / 2), 0.5, 1e-10);
  // On a line x = 3t^2 (speed 10t), length l is at t = sqrt(l / 5).
  const Curve accelerating({{0, 0}, {0, 0}, {3, 4}});
  const ArcLength line = arc_length(accelerating, 0, 1);
  for (const double l : {0.05, 1.25, 2.0, 4.999}) {
    EXPECT_NEAR(parameter_at_length(accelerating, line, l), std::sqrt(l / 5), 1e-12);
  }
}

TEST(ArcLength, ParameterAtLengthHoldsTheBoundAtEveryTolerance) {
  // The parameter found from a partition at a loose tolerance has its length from a within
  // that partition's error bound (measured at the API's tolerance, whose own bound is added).
  const Curve cusp({{0, 0}, {1, 1}, {0, 1}, {1, 0}});
  const Curve wave({{0, 0}, {0.25, 3}, {0.5, -3}, {0.75, 3}, {1, 0}});
  for (const Curve* curve : {&cusp, &wave}) {
    for (const double tolerance : kTolerances) {
      const ArcLength whole = arc_length(*curve, 0.1, 0.95, at(tolerance));
      for (int k = 0; k <= 8; ++k) {
        const double l = whole.length * k / 8;
        const double t = parameter_at_length(*curve, whole, l);
        ASSERT_GE(t, 0.1);
        ASSERT_LE(t, 0.95);
        const ArcLength check = arc_length(*curve, 0.1, t);
        EXPECT_LE(std::fabs(check.length - l), whole.error_bound + check.error_bound + 8 * kUnitRoundoff * whole.length)
            << "tolerance " << tolerance << ", k " << k;
      }
    }
  }
}

TEST(ArcLength, ChargesItsEvaluationsAndSumsToTheBudget) {
  // The cusp cubic, where the quadrature halves toward t = 1/2: with enough work the budget
  // pays for the answer the overload with a budget of its own gives, bit for bit; every
  // charge is a whole number of evaluations of |B'| (speed_evaluation_cost(3) = 10 units)
  // plus the sums, so at least the 7-point rule on each first piece.
  const Curve cusp({{0, 0}, {1, 1}, {0, 1}, {1, 0}});
  const ArcLength alone = arc_length(cusp, 0, 1);
  WorkBudget budget(10000000);
  const ArcLength charged = arc_length(cusp, 0, 1, {}, budget);
  EXPECT_FALSE(budget.exhausted());
  EXPECT_TRUE(charged.tolerance_met);
  EXPECT_EQ(charged.length, alone.length);
  EXPECT_EQ(charged.error_bound, alone.error_bound);
  EXPECT_EQ(charged.pieces.size(), alone.pieces.size());
  EXPECT_GE(budget.spent(), 7 * speed_evaluation_cost(3) * 2);
}

TEST(ArcLength, RunningOutOfWorkExhaustsTheBudget) {
  // The same cusp with room for its first rules and little more: the quadrature stops short
  // of its tolerance with an honest bound, and says why through the budget.
  const Curve cusp({{0, 0}, {1, 1}, {0, 1}, {1, 0}});
  WorkBudget budget(400);
  const ArcLength got = arc_length(cusp, 0, 1, {}, budget);
  EXPECT_TRUE(budget.exhausted());
  EXPECT_FALSE(got.tolerance_met);
  EXPECT_GT(got.error_bound, kTolerance * got.length);
  const long double exact = 2 * std::sqrt(2.0L) - 1;
  EXPECT_LE(std::fabs(static_cast<long double>(got.length) - exact), 1e-2L * exact);
  // The overload with a budget of its own reports the same as tolerance_met false.
  ArcLengthOptions tight;
  tight.max_work = 400;
  EXPECT_FALSE(arc_length(cusp, 0, 1, tight).tolerance_met);
}

}  // namespace
}  // namespace bezier::core
