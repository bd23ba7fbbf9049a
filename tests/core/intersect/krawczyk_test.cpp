// The Krawczyk test (core/intersect/krawczyk.hpp) on curves whose intersections are known
// in closed form: the line y = 1/4, x = 2t - 1 (degree 1) and the parabola x = 2s - 1,
// y = (2s - 1)^2 (a quadratic with control points (-1, 1), (0, -1), (1, 1)) cross at
// (t, s) = (1/4, 1/4) and (3/4, 3/4); the line y = 0 touches the parabola at (1/2, 1/2).
// A box around a crossing must be certified with a tight box holding the root; a box
// holding no root must never be reported as holding one; a tangency must never be reported
// as root-free.

#include <gtest/gtest.h>

#include "core/intersect/krawczyk.hpp"
#include "core/intersect/working_curve.hpp"

namespace bezier::core {
namespace {

constexpr double kRadius = 0x1p-43;

struct CurvePair {
  WorkingCurve f, g;
};

CurvePair curves(double line_y) {
  const Curve line({{-1.0, line_y}, {1.0, line_y}});
  const Curve parabola({{-1.0, 1.0}, {0.0, -1.0}, {1.0, 1.0}});
  const WorkingFrame frame = working_frame(line, parabola);
  return {to_working(line, frame), to_working(parabola, frame)};
}

KrawczykResult run(const CurvePair& c, ParamInterval t, ParamInterval s) {
  return krawczyk(c.f, c.g, fast_piece(c.f, t.lo, t.hi), fast_piece(c.g, s.lo, s.hi), t, s,
                  kRadius);
}

TEST(Krawczyk, CertifiesATransversalCrossingInATightBox) {
  const CurvePair c = curves(0.25);
  for (const double root : {0.25, 0.75}) {
    for (const double w : {0x1p-5, 0x1p-8, 1e-5}) {
      const ParamInterval t{root - 0.3 * w, root + 0.7 * w}, s{root - 0.6 * w, root + 0.4 * w};
      const KrawczykResult k = run(c, t, s);
      ASSERT_EQ(k.verdict, KrawczykResult::Verdict::one_root) << root << " " << w;
      EXPECT_TRUE(k.t.contains(root));
      EXPECT_TRUE(k.s.contains(root));
      EXPECT_EQ(k.t.width(), 2 * kRadius);
      EXPECT_EQ(k.s.width(), 2 * kRadius);
      EXPECT_TRUE(t.lo <= k.t.lo && k.t.hi <= t.hi);
      EXPECT_TRUE(s.lo <= k.s.lo && k.s.hi <= s.hi);
    }
  }
}

TEST(Krawczyk, ExcludesABoxWithoutRoots) {
  const CurvePair c = curves(0.25);
  // t near 1/4 (x near -1/2) against s near 3/4 (x near 1/2): no common point.
  const KrawczykResult k = run(c, {0.24, 0.26}, {0.74, 0.76});
  EXPECT_EQ(k.verdict, KrawczykResult::Verdict::no_root);
  // A root just outside the box (t = 1/4 is not in [0.2501, 0.27]): never one_root.
  EXPECT_NE(run(c, {0.2501, 0.27}, {0.24, 0.26}).verdict, KrawczykResult::Verdict::one_root);
}

TEST(Krawczyk, LeavesATangencyUndecided) {
  const CurvePair c = curves(0.0);
  // The Jacobian is singular at the contact (1/2, 1/2): no certificate either way.
  for (const double w : {0x1p-5, 1e-4, 1e-8}) {
    const KrawczykResult k = run(c, {0.5 - w, 0.5 + w / 2}, {0.5 - w / 3, 0.5 + w});
    EXPECT_EQ(k.verdict, KrawczykResult::Verdict::inconclusive) << w;
  }
}

TEST(Krawczyk, RootNextToTheBoxEdgeIsNeverLost) {
  const CurvePair c = curves(0.25);
  // The root t = 1/4 lies 2^-48 inside the box, closer than the tight box's radius.
  const KrawczykResult k = run(c, {0.25 - 0x1p-48, 0.26}, {0.24, 0.26});
  EXPECT_NE(k.verdict, KrawczykResult::Verdict::no_root);
  if (k.verdict == KrawczykResult::Verdict::one_root) {
    EXPECT_TRUE(k.t.contains(0.25));
  }
}

}  // namespace
}  // namespace bezier::core
