// Tests of the tight side's disks (core/outline/tight_side_cover.hpp): whenever the
// tangent-disk test accepts a part, every point B(t) + s N(t) with 0 <= s <= min(ρ(t), r) is
// within R of the centre, checked on a dense grid with the curve's frames (core::frame, not the
// test's Bernstein bounds); and the disks of a whole tight side hold all of its points.

#include "core/outline/tight_side_cover.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/curve/evaluate.hpp"
#include "core/curve/polar.hpp"
#include "core/measure/frame.hpp"
#include "core/measure/nearest.hpp"
#include "core/numeric/power_of_two.hpp"
#include "core/outline/offset_cusps.hpp"
#include "core/outline/stroke_shapes.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::outline {
namespace {

using core::Point2;

constexpr double kUnit = std::numeric_limits<double>::epsilon() / 2.0;

/// Over the sampled points B(t) + s N(t) (t in [t0, t1] of `curve`, 0 <= s <= min(ρ(t), r),
/// N towards `side`): the largest distance to the nearest of `centres`, and the samples where
/// the curve does not turn to the side.
struct Reach {
  double farthest = 0.0;
  int wrong_side = 0;
};

Reach farthest_point(const core::Curve& curve, double t0, double t1, double side, double r,
                     const std::vector<Point2>& centres, int t_steps, int s_steps) {
  Reach out;
  for (int i = 0; i <= t_steps; ++i) {
    const double t = t0 + (t1 - t0) * i / t_steps;
    const std::optional<core::Frame<Point2>> f = core::frame(curve, t);
    if (!f) continue;
    const double turn = side * f->curvature;
    if (!(turn > 0.0)) {
      ++out.wrong_side;
      continue;
    }
    const double depth = std::min(1.0 / turn, r);
    const Point2 b = core::evaluate(curve, t);
    const Point2 normal = side * *f->normal;
    for (int j = 0; j <= s_steps; ++j) {
      const Point2 p = b + (depth * j / s_steps) * normal;
      double nearest = std::numeric_limits<double>::infinity();
      for (const Point2 c : centres) nearest = std::min(nearest, core::length(p - c));
      out.farthest = std::max(out.farthest, nearest);
    }
  }
  return out;
}

TEST(TightSideCover, TangentDiskTestAcceptsOnlyPartsTheDiskHolds) {
  // Random cubic parts, half of them cut next to a point where ρ = R (r = ρ(t0) - ε/2), the
  // case the hull test cannot take: whenever the test accepts, no sampled point of the part's
  // tight side is farther than R from the centre.
  test::Mulberry32 rng(20261206);
  int accepted = 0, accepted_near_reach = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    std::vector<Point2> points;
    for (int i = 0; i < 4; ++i) points.push_back({rng.uniform(-10, 10), rng.uniform(-10, 10)});
    const core::Curve curve(points);
    const double tolerance = std::pow(10.0, rng.uniform(-6, -2));
    const double w = std::pow(10.0, rng.uniform(-3, 0));
    double a = rng.uniform(0, 1 - w), b = a + w;
    double side = rng.next() < 0.5 ? 1.0 : -1.0;
    double r = rng.uniform(0.2, 5);
    const bool near_reach = trial % 2 == 0;
    if (near_reach) {
      // ρ(t0) = R at the part's start or end, the side the curve turns to there.
      const double t0 = rng.next() < 0.5 ? a : b;
      const std::optional<core::Frame<Point2>> f = core::frame(curve, t0);
      if (!f || f->curvature == 0.0) continue;
      side = f->curvature > 0.0 ? 1.0 : -1.0;
      r = 1.0 / std::fabs(f->curvature) - tolerance / 2.0;
      if (!(r > 0.0)) continue;
    }
    const CoverSizes sizes = cover_sizes(r, tolerance);
    const core::Curve piece = core::portion(curve, a, b);
    const Point2 centre = core::evaluate(piece, 0.5);
    const double scale = core::scale(curve);
    const double point_error = 48.0 * kUnit * scale;
    if (!tangent_disk_holds(piece.points(), centre, point_error, point_error + 4 * kUnit * scale,
                            0.0, side, sizes)) {
      continue;
    }
    ++accepted;
    if (near_reach) ++accepted_near_reach;
    const Reach reach = farthest_point(piece, 0.0, 1.0, side, r, {centre}, 300, 16);
    EXPECT_EQ(reach.wrong_side, 0) << "trial " << trial;
    EXPECT_LE(reach.farthest, sizes.reach * (1 + 1e-12)) << "trial " << trial;
  }
  // Not vacuous: both kinds of parts were accepted many times.
  EXPECT_GT(accepted, 200);
  EXPECT_GT(accepted_near_reach, 100);
}

TEST(TightSideCover, RefusesAPartTurningAQuarterTurn) {
  // Circular arcs of radius 1 (cubic approximations, Goldapp's k) stroked 20 wide: every
  // point of the part's tight side is within R of its middle, but the lemma needs less than a
  // quarter turn: a bit more is refused (the contract: false when a certificate fails), a
  // bit less accepted.
  for (const double sweep : {1.05 * M_PI / 2, 0.95 * M_PI / 2}) {
    const double k = 4.0 / 3.0 * std::tan(sweep / 4);
    const core::Curve arc({{1, 0}, {1, k}, {std::cos(sweep) + k * std::sin(sweep), std::sin(sweep) - k * std::cos(sweep)},
                           {std::cos(sweep), std::sin(sweep)}});
    const CoverSizes sizes = cover_sizes(10.0, 1e-3);
    const bool holds = tangent_disk_holds(arc.points(), core::evaluate(arc, 0.5), 1e-15, 1e-15,
                                          0.0, 1.0, sizes);
    EXPECT_EQ(holds, sweep < M_PI / 2) << sweep;
    // Never for the other side (the arc turns left).
    EXPECT_FALSE(tangent_disk_holds(arc.points(), core::evaluate(arc, 0.5), 1e-15, 1e-15, 0.0,
                                    -1.0, sizes));
  }
}

TEST(TightSideCover, RefusesAPartWhoseTightSideLeavesTheDisk) {
  // A nearly straight part (radius of curvature about 50) half a unit long, stroked 2 wide:
  // the points at distance r along the normals at its ends are farther than R from its middle
  // (checked here from the frames), so the disk must not be accepted; a part a hundred times
  // shorter is held.
  const CoverSizes sizes = cover_sizes(1.0, 1e-3);
  for (const double length : {0.5, 0.005}) {
    const core::Curve part({{0, 0}, {length / 2, length * length / 200}, {length, 0}});
    const Point2 centre = core::evaluate(part, 0.5);
    double farthest = 0.0;
    for (const double t : {0.0, 1.0}) {
      const std::optional<core::Frame<Point2>> f = core::frame(part, t);
      ASSERT_TRUE(f && f->curvature < 0.0);  // turns right: the tight side is the right
      const double depth = std::min(1.0 / -f->curvature, sizes.radius);
      farthest = std::max(farthest, core::length(core::evaluate(part, t) - depth * *f->normal - centre));
    }
    const bool holds = tangent_disk_holds(part.points(), centre, 1e-15, 1e-15, 0.0, -1.0, sizes);
    if (length > 0.1) {
      EXPECT_GT(farthest, sizes.reach);
      EXPECT_FALSE(holds);
    } else {
      EXPECT_LT(farthest, sizes.reach);
      EXPECT_TRUE(holds);
    }
  }
}

/// The tight pieces of `side` (the intervals between the parallel curve's cusps at ±R whose
/// middle turns to the side with ρ < R), covered by cover_tight_side: every point of their
/// tight side is within R of a disk's centre, and every centre is on the curve.
void check_tight_sides(const char* name, const core::Curve& curve, double width,
                       double tolerance) {
  SCOPED_TRACE(testing::Message() << name << " width " << width << " tolerance " << tolerance);
  const double r = width / 2;
  const CoverSizes sizes = cover_sizes(r, tolerance);
  int pieces = 0;
  for (const double side : {1.0, -1.0}) {
    std::vector<double> cuts{0.0};
    for (const double t : offset_cusps(curve, side * sizes.reach)) cuts.push_back(t);
    cuts.push_back(1.0);
    for (std::size_t j = 0; j + 1 < cuts.size(); ++j) {
      const double c0 = cuts[j], c1 = cuts[j + 1];
      const std::optional<core::Frame<Point2>> f = core::frame(curve, 0.5 * (c0 + c1));
      if (!(c1 > c0) || !f || !(side * f->curvature * sizes.reach > 1.0)) continue;
      ++pieces;
      core::WorkBudget budget(std::int64_t{1} << 40);
      OutlineSink sink(budget, 1000000);
      std::vector<Point2> centres;
      cover_tight_side(curve, c0, c1, side, sizes, sink, centres);
      ASSERT_TRUE(sink.ok());
      ASSERT_FALSE(centres.empty());
      EXPECT_EQ(sink.segment_count(), centres.size() * sizes.circle_pieces);
      for (const Point2 c : centres) {
        EXPECT_LT(core::nearest(curve, c, 0, 1).distance, 1e-12 * core::scale(curve));
      }
      const Reach reach = farthest_point(curve, c0, c1, side, r, centres, 4000, 24);
      EXPECT_EQ(reach.wrong_side, 0);
      EXPECT_LE(reach.farthest, sizes.reach * (1 + 1e-12));
    }
  }
  EXPECT_GT(pieces, 0);
}

TEST(TightSideCover, DisksHoldTheTightSidesOfBends) {
  const core::Curve s_curve({{0, 0}, {30, 0}, {-10, 10}, {20, 10}});
  const core::Curve loop({{0, 0}, {10, 10}, {-10, 10}, {0, 0}});
  const core::Curve hook({{0, 0}, {12, 0}, {12, 4}, {0, 4}});
  const core::Curve arch({{0, 0}, {10, 10}, {20, 0}});
  for (const double tolerance : {1e-2, 1e-4, 1e-6}) {
    check_tight_sides("s-curve", s_curve, 2.0, tolerance);
    check_tight_sides("s-curve", s_curve, 7.0, tolerance);
    check_tight_sides("loop", loop, 7.0, tolerance);
    check_tight_sides("arch", arch, 30.0, tolerance);
    check_tight_sides("hook", hook, 6.0, tolerance);
  }
}

/// The disks of `curve`'s tight pieces (cuts as check_tight_sides makes them), with every
/// coordinate and size times 2^k.
std::vector<Point2> tight_side_centres(const core::Curve& curve, double width, double tolerance,
                                       int k) {
  const core::PowerOfTwo factor(k);
  std::vector<Point2> points;
  for (const Point2 p : curve.points()) points.push_back(factor.times(p));
  const core::Curve scaled(points);
  const CoverSizes unit = cover_sizes(width / 2, tolerance);
  CoverSizes sizes = unit;
  sizes.radius = factor.times(unit.radius);
  sizes.reach = factor.times(unit.reach);
  sizes.fit_tolerance = factor.times(unit.fit_tolerance);
  sizes.snap = factor.times(unit.snap);
  sizes.disk_radius = factor.times(unit.disk_radius);
  std::vector<Point2> centres;
  for (const double side : {1.0, -1.0}) {
    std::vector<double> cuts{0.0};
    for (const double t : offset_cusps(curve, side * unit.reach)) cuts.push_back(t);
    cuts.push_back(1.0);
    for (std::size_t j = 0; j + 1 < cuts.size(); ++j) {
      const double c0 = cuts[j], c1 = cuts[j + 1];
      const std::optional<core::Frame<Point2>> f = core::frame(curve, 0.5 * (c0 + c1));
      if (!(c1 > c0) || !f || !(side * f->curvature * unit.reach > 1.0)) continue;
      core::WorkBudget budget(std::int64_t{1} << 40);
      OutlineSink sink(budget, 1000000);
      cover_tight_side(scaled, c0, c1, side, sizes, sink, centres);
    }
  }
  return centres;
}

TEST(TightSideCover, TheSameDisksAtEveryPowerOfTwoScale) {
  // Every length the cover compares (spreads, radii of curvature, margins) scales with the
  // curve, so a curve scaled by 2^k gets its disks scaled by 2^k, as long as the bounds are
  // computed where they neither underflow nor overflow: coordinates near 1e-109 make the cube
  // of a hodograph's size underflow, and near 1e+90 overflow, unless it is taken on a scaled
  // copy.
  const core::Curve s_curve({{0, 0}, {30, 0}, {-10, 10}, {20, 10}});
  const core::Curve loop({{0, 0}, {10, 10}, {-10, 10}, {0, 0}});
  const core::Curve arch({{0, 0}, {10, 10}, {20, 0}});
  const core::Curve near_cusp({{0, 0}, {10, 10}, {0.5, 10}, {10, 0}});
  struct Case {
    const char* name;
    const core::Curve* curve;
    double width;
  };
  for (const Case& c : {Case{"s-curve", &s_curve, 7.0}, Case{"loop", &loop, 7.0},
                        Case{"arch", &arch, 30.0}, Case{"near cusp", &near_cusp, 2.0}}) {
    const std::vector<Point2> unit = tight_side_centres(*c.curve, c.width, 1e-4, 0);
    ASSERT_FALSE(unit.empty()) << c.name;
    for (const int k : {-362, 300}) {
      SCOPED_TRACE(testing::Message() << c.name << " at 2^" << k);
      const std::vector<Point2> scaled = tight_side_centres(*c.curve, c.width, 1e-4, k);
      ASSERT_EQ(scaled.size(), unit.size());
      const core::PowerOfTwo factor(k);
      for (std::size_t i = 0; i < unit.size(); ++i) EXPECT_EQ(scaled[i], factor.times(unit[i]));
    }
  }
}

}  // namespace
}  // namespace bezier::outline
