#include "core/outline/stroke.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "core/curve/evaluate.hpp"
#include "core/measure/frame.hpp"
#include "core/measure/nearest.hpp"
#include "core/region/boolean.hpp"
#include "core/region/winding.hpp"
#include "tests/support/mulberry32.hpp"
#include "tests/support/parsed_path.hpp"
#include "tests/support/stroke_checks.hpp"

namespace bezier::outline {
namespace {

using core::Point2;

constexpr std::int64_t kWork = std::int64_t{1} << 36;
constexpr std::size_t kSegments = 1000000;

/// The stroke with a budget of `work` units.
StrokeOutline stroke(const path::Path& path, const StrokeStyle& style, double tolerance,
                     std::int64_t work, std::size_t max_segments) {
  core::WorkBudget budget(work);
  return outline::stroke(path, style, tolerance, budget, max_segments);
}

StrokeStyle round_style(double width) {
  StrokeStyle style;
  style.width = width;
  style.join = LineJoin::round;
  style.cap = LineCap::round;
  return style;
}

/// Points to judge: random ones over the path's box widened by r + 1, and chosen ones just
/// inside r and just beyond r + tolerance along the normals, at the centres of curvature
/// where the radius of curvature is below r (and next to them), and around every segment end.
std::vector<Point2> probe_points(const path::Path& path, double r, double tolerance,
                                 std::uint32_t seed, int random_count) {
  std::vector<Point2> out;
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const core::Curve& s : path.segments)
    for (const Point2 p : s.points()) {
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
  test::Mulberry32 rng(seed);
  for (int i = 0; i < random_count; ++i) {
    out.push_back({rng.uniform(x0 - r - 1, x1 + r + 1), rng.uniform(y0 - r - 1, y1 + r + 1)});
  }
  const std::vector<double> offsets{r - 0.1 * tolerance, r + 1.1 * tolerance, 0.5 * r,
                                    r - 3 * tolerance};
  for (const core::Curve& s : path.segments) {
    for (int i = 0; i <= 40; ++i) {
      const double t = i / 40.0;
      const std::optional<core::Frame<Point2>> f = core::frame(s, t);
      if (!f) continue;
      const Point2 b = core::evaluate(s, t);
      for (const double d : offsets) {
        out.push_back(b + d * *f->normal);
        out.push_back(b - d * *f->normal);
      }
      if (f->curvature != 0.0) {
        const double rho = 1.0 / f->curvature;  // signed: the centre is at b + rho N
        if (std::fabs(rho) < r) {
          for (const double k : {1.0, 0.999, 1.001, 0.99, 1.01}) out.push_back(b + k * rho * *f->normal);
        }
      }
    }
    for (const Point2 end : {s.front(), s.back()}) {
      for (int k = 0; k < 24; ++k) {
        const double a = 2 * std::numbers::pi * k / 24 + 0.1;
        const Point2 e{std::cos(a), std::sin(a)};
        for (const double d : {r - 0.1 * tolerance, r + 1.1 * tolerance, 0.7 * r}) out.push_back(end + d * e);
      }
    }
  }
  return out;
}

void check_round_stroke(const std::string& data, double width, double tolerance,
                        std::uint32_t seed = 1) {
  std::ostringstream trace;
  trace << data << " width " << width;
  SCOPED_TRACE(trace.str());
  const path::Path path = test::parsed_path(data);
  const StrokeOutline outline = stroke(path, round_style(width), tolerance, kWork, kSegments);
  ASSERT_EQ(outline.status, StrokeStatus::ok);
  for (const Contour& c : outline.contours) {
    ASSERT_FALSE(c.empty());
    for (std::size_t k = 0; k < c.size(); ++k) {
      ASSERT_EQ(c[k].back(), c[(k + 1) % c.size()].front()) << "contour not closed exactly";
    }
  }
  const double r = width / 2;
  const test::MembershipCounts counts = test::check_round_membership(
      path, outline, r, tolerance, probe_points(path, r, tolerance, seed, 1500));
  EXPECT_GT(counts.inside, 100);
  EXPECT_GT(counts.outside, 100);
}

TEST(Stroke, RoundIsTheDistanceSetAtSharpJoints) {
  check_round_stroke("M0 0 L10 0 L10 10 L3 2", 3.0, 1e-3);
}

TEST(Stroke, RoundIsTheDistanceSetAtACuspOfTheCurve) {
  // B'(1/2) = 0: x' ∝ (1 - 2t)^2, y' ∝ 1 - 2t.
  check_round_stroke("M0 0 C10 10 0 10 10 0", 2.0, 1e-3);
}

/// The round stroke of `data` (one cubic, `cubic`), simplified: every point judged winds once
/// when closer than width / 2 to the curve, never when farther than width / 2 + tolerance, and
/// 0 or 1 anywhere.
void check_simplified_round_stroke(const std::string& data, const core::Curve& cubic, double width,
                                   double tolerance) {
  SCOPED_TRACE(testing::Message() << data << " width " << width << " tolerance " << tolerance);
  const path::Path path = test::parsed_path(data);
  const StrokeOutline outline = stroke(path, round_style(width), tolerance, kWork, kSegments);
  ASSERT_EQ(outline.status, StrokeStatus::ok);
  path::Path boundary;
  for (const Contour& c : outline.contours) {
    boundary.subpaths.push_back({boundary.segments.size(), c.size(), true});
    for (const core::Curve& s : c) boundary.segments.push_back(s);
  }
  const region::BooleanResult simple =
      region::simplify(region::Region{std::move(boundary), region::FillRule::nonzero}, kWork);
  ASSERT_EQ(simple.status, region::BooleanStatus::ok);
  path::Path result;
  for (const region::ResultContour& c : simple.contours) {
    result.subpaths.push_back({result.segments.size(), c.end_segment - c.first_segment, true});
    for (std::size_t k = c.first_segment; k < c.end_segment; ++k) {
      result.segments.push_back(simple.segments[k].curve);
    }
  }
  const region::RegionWinding winding(region::Region{std::move(result), region::FillRule::nonzero});
  const double r = width / 2;
  int inside = 0, outside = 0;
  for (const Point2 p : probe_points(path, r, tolerance, 7, 1500)) {
    core::WorkBudget work(kWork);
    const std::optional<region::Winding> w = winding.at(p, work);
    ASSERT_TRUE(w);
    if (w->boundary) continue;
    EXPECT_TRUE(w->winding == 0 || w->winding == 1) << p.x << " " << p.y;
    const double d = core::nearest(cubic, p, 0, 1).distance;
    if (d < r - 1e-12) {
      EXPECT_EQ(w->winding, 1) << p.x << " " << p.y;
      ++inside;
    } else if (d > r + tolerance + 1e-12) {
      EXPECT_EQ(w->winding, 0) << p.x << " " << p.y;
      ++outside;
    }
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
}

TEST(Stroke, SimplifiedOutlineOfACuspIsTheDistanceSetWindingOnce) {
  // The cusp at t = 1/2 and the cusps of the parallel curves (radius of curvature R) cut the
  // cubic into pieces whose normal segments at a cut lie on one line; simplify must remove
  // the overlaps.
  const core::Curve cubic({{0, 0}, {10, 10}, {0, 10}, {10, 0}});
  for (const double width : {2.0, 1.0, 3.0}) {
    for (const double tolerance : {1e-2, 1e-3}) {
      check_simplified_round_stroke("M0 0 C10 10 0 10 10 0", cubic, width, tolerance);
    }
  }
}

TEST(Stroke, SimplifiedWideStrokesAtATightTolerance) {
  // At tolerance 1e-4, offset pieces of these wide strokes meet near-tangentially a few
  // times within 1e-8 of each other: slivers thinner than the region layer's ray clearance,
  // whose sides are decided around their vertices (core/region/vertex_sectors.hpp).
  const double tolerance = 1e-4;
  const core::Curve hook({{0, 0}, {12, 0}, {12, 4}, {0, 4}});
  const core::Curve s_curve({{0, 0}, {30, 0}, {-10, 10}, {20, 10}});
  const core::Curve cusp({{0, 0}, {10, 10}, {0, 10}, {10, 0}});
  const core::Curve loop({{0, 0}, {10, 10}, {-10, 10}, {0, 0}});
  for (const double width : {2.0, 7.0}) {
    check_simplified_round_stroke("M0 0 C12 0 12 4 0 4", hook, width, tolerance);
    check_simplified_round_stroke("M0 0 C10 10 0 10 10 0", cusp, width, tolerance);
  }
  check_simplified_round_stroke("M0 0 C30 0 -10 10 20 10", s_curve, 7.0, tolerance);
  check_simplified_round_stroke("M0 0 C10 10 -10 10 0 0 Z", loop, 2.0, tolerance);
}

TEST(Stroke, RoundIsTheDistanceSetForCollinearCurvesThatTurnBack) {
  // B' = 0 where each turns back along its line: the stroke is the set of points within
  // width / 2 of the segments the curve sweeps (a stadium for one back-and-forth run).
  for (const char* data : {"M0 0 Q100 0 50 0", "M0 0 C100 0 -100 0 0 0", "M0 0 C100 0 100 0 50 0",
                           "M0 0 C100 0 -100 0 50 0", "M0 0 C30 30 0 0 10 10"}) {
    check_round_stroke(data, 4.0, 1e-3);
    check_round_stroke(data, 4.0, 2e-7);
  }
  check_round_stroke("M0 0 C3 0 6 0 10 0", 1000.0, 1e-3);
}

TEST(Stroke, SimplifiedRoundStrokesOfCollinearCurvesThatTurnBack) {
  check_simplified_round_stroke("M0 0 Q100 0 50 0", core::Curve({{0, 0}, {100, 0}, {50, 0}}), 4.0,
                                1e-3);
  const core::Curve there_and_back({{0, 0}, {100, 0}, {-100, 0}, {0, 0}});
  check_simplified_round_stroke("M0 0 C100 0 -100 0 0 0", there_and_back, 4.0, 1e-2);
  check_simplified_round_stroke("M0 0 C100 0 -100 0 0 0", there_and_back, 4.0, 1e-3);
  check_simplified_round_stroke("M0 0 C100 0 -100 0 50 0",
                                core::Curve({{0, 0}, {100, 0}, {-100, 0}, {50, 0}}), 4.0, 1e-3);
  // Off the axes the runs' edges along each side overlap where the curve goes back over
  // itself: they must coincide in whole pieces for simplify, also at a tight tolerance and
  // with a stroke far wider than the curve.
  const core::Curve slanted({{0, 0}, {30, 30}, {0, 0}, {10, 10}});
  check_simplified_round_stroke("M0 0 C30 30 0 0 10 10", slanted, 4.0, 6e-8);
  check_simplified_round_stroke("M0 0 C30 30 0 0 10 10", slanted, 4.0, 1e-3);
  check_simplified_round_stroke("M0 0 C30 30 0 0 10 10", slanted, 1000.0, 1e-3);
}

TEST(Stroke, RoundStrokeOfATrueCuspAtATightTolerance) {
  // B'(1/2) = 0; 1e-7 is 1e-8 of the scale, an accepted tolerance.
  const core::Curve cusp({{0, 0}, {10, 10}, {0, 10}, {10, 0}});
  check_round_stroke("M0 0 C10 10 0 10 10 0", 2.0, 1e-7);
  check_simplified_round_stroke("M0 0 C10 10 0 10 10 0", cusp, 2.0, 1e-7);
  // The cusp rounded off its zero by 1e-12 (x' without a real root): the same stroke.
  check_round_stroke("M0 0 C10 10 1e-12 10 10 0", 2.0, 1e-3);
  check_simplified_round_stroke("M0 0 C10 10 1e-12 10 10 0",
                                core::Curve({{0, 0}, {10, 10}, {1e-12, 10}, {10, 0}}), 2.0, 1e-3);
}

TEST(Stroke, RoundIsTheDistanceSetWhereTheRadiusOfCurvatureIsBelowHalfTheWidth) {
  check_round_stroke("M0 0 C12 0 12 4 0 4", 6.0, 1e-3);
  check_round_stroke("M0 0 Q10 10 20 0", 30.0, 1e-2);
  check_round_stroke("M0 0 C30 0 -10 10 20 10", 4.0, 1e-4);
}

TEST(Stroke, ClosedCircleNarrowerThanTheStrokeFillsItsCentre) {
  // Radius 1, half width 1.5: the centre is at distance 1 < 1.5.
  const std::string circle = "M1 0 A1 1 0 0 1 -1 0 A1 1 0 0 1 1 0 Z";
  check_round_stroke(circle, 3.0, 1e-3);
  const path::Path path = test::parsed_path(circle);
  const StrokeOutline wide = stroke(path, round_style(3.0), 1e-3, kWork, kSegments);
  core::WorkBudget work(kWork);
  const auto at_centre = region::RegionWinding(test::outline_region(wide)).at({0, 0}, work);
  ASSERT_TRUE(at_centre);
  EXPECT_NE(at_centre->winding, 0);
  // Half width 0.99: the centre is at distance 1 > 0.99 + tolerance: a hole.
  check_round_stroke(circle, 1.98, 1e-3);
  const StrokeOutline narrow = stroke(path, round_style(1.98), 1e-3, kWork, kSegments);
  work = core::WorkBudget(kWork);
  const auto hole = region::RegionWinding(test::outline_region(narrow)).at({0, 0}, work);
  ASSERT_TRUE(hole);
  EXPECT_EQ(hole->winding, 0);
}

TEST(Stroke, RoundIsTheDistanceSetAcrossZeroLengthSegments) {
  check_round_stroke("M0 0 L5 0 L5 0 L5 5 C5 5 5 5 5 5 L9 1", 2.0, 1e-3);
}

TEST(Stroke, RoundIsTheDistanceSetForRandomCubicPaths) {
  test::Mulberry32 rng(31);
  for (int i = 0; i < 12; ++i) {
    std::ostringstream data;
    for (int sub = 0; sub < 2; ++sub) {
      data << "M" << rng.uniform(0, 10) << " " << rng.uniform(0, 10);
      for (int k = 0; k < 2; ++k) {
        data << " C";
        for (int j = 0; j < 6; ++j) data << " " << rng.uniform(0, 10);
      }
      if (sub == 1) data << " Z";
    }
    const double width = rng.uniform(0.5, 6.0);
    check_round_stroke(data.str(), width, 1e-3, 100 + static_cast<std::uint32_t>(i));
  }
}

TEST(Stroke, SimplifiedRoundStrokesOfRandomCubicsAreTheDistanceSet) {
  // Random cubics stroked wider than their tightest bends at tolerance 1e-4: the tight sides'
  // disks (tight_side_cover.hpp) are most of what simplify takes apart.
  test::Mulberry32 rng(4242);
  for (int i = 0; i < 10; ++i) {
    std::vector<Point2> points;
    std::ostringstream data;
    data.precision(17);
    for (int k = 0; k < 4; ++k) {
      points.push_back({rng.uniform(-10, 10), rng.uniform(-10, 10)});
      data << (k == 0 ? "M" : k == 1 ? " C" : " ") << points.back().x << " " << points.back().y;
    }
    check_simplified_round_stroke(data.str(), core::Curve(points), rng.uniform(2.0, 8.0), 1e-4);
  }
}

TEST(Stroke, RoundIsTheDistanceSetForACurveOfDegreeFive) {
  path::Path path;
  path.segments.push_back(core::Curve({{0, 0}, {8, 9}, {-4, 6}, {9, -3}, {2, 7}, {10, 10}}));
  path.subpaths.push_back({0, 1, false});
  const StrokeOutline outline = stroke(path, round_style(2.5), 1e-3, kWork, kSegments);
  ASSERT_EQ(outline.status, StrokeStatus::ok);
  for (const Contour& c : outline.contours)
    for (const core::Curve& s : c) EXPECT_LE(s.degree(), 3);
  const test::MembershipCounts counts = test::check_round_membership(
      path, outline, 1.25, 1e-3, probe_points(path, 1.25, 1e-3, 5, 1500));
  EXPECT_GT(counts.inside, 100);
  EXPECT_GT(counts.outside, 100);
}

TEST(Stroke, RoundIsTheDistanceSetForCurvesOfHighDegreeWithRepeatedControlPoints) {
  // A zigzag of degree 19 along the line through (0, 0) and (3, 4), turning where B'
  // vanishes; a line of degree 20 whose last 20 control points coincide (B' vanishes to the
  // 19th order at its end); a cubic whose middle control points coincide; both simplified
  // and not: the round stroke is the set of points within width / 2 of the curve.
  std::vector<Point2> zigzag, flat{{0, 0}};
  for (int k = 0; k < 10; ++k) {
    zigzag.push_back({0, 0});
    zigzag.push_back({3, 4});
  }
  for (int k = 0; k < 20; ++k) flat.push_back({4, 0});
  for (const std::vector<Point2>& points :
       {zigzag, flat, std::vector<Point2>{{0, 0}, {5, 5}, {5, 5}, {10, 0}}}) {
    path::Path path;
    path.segments.push_back(core::Curve(points));
    path.subpaths.push_back({0, 1, false});
    for (const double tolerance : {1e-3, 1e-7}) {
      SCOPED_TRACE(testing::Message() << "degree " << points.size() - 1 << " tolerance " << tolerance);
      const StrokeOutline outline = stroke(path, round_style(3.0), tolerance, 22000000, kSegments);
      ASSERT_EQ(outline.status, StrokeStatus::ok);
      const test::MembershipCounts counts = test::check_round_membership(
          path, outline, 1.5, tolerance, probe_points(path, 1.5, tolerance, 9, 1000));
      EXPECT_GT(counts.inside, 100);
      EXPECT_GT(counts.outside, 100);
    }
  }
}

TEST(Stroke, HairpinIsCoveredByItsRibbonsAndAFewDisksAtItsTip) {
  // (0,0), (1,0), (1,g), (0,g): out along the x axis to x = 3/4 and back g above it. Its radius
  // of curvature is below r only next to the tip (offset_cusps_test's hairpins), where B' is
  // small but not zero; the tight side there is shorter than r and turns by a half turn, so
  // a few disks cover it. A chain of disks of radius R along a whole leg (the tight side
  // taken for the whole curve) would need at least 3/4 / (2R) of them; the outline's
  // contours (two sides, a few disks) stay below a quarter of that.
  const double width = 0.01, tolerance = 1e-4, reach = width / 2 + tolerance / 2;
  for (const double g : {3e-4, 1e-6}) {
    SCOPED_TRACE(g);
    path::Path path;
    path.segments.push_back(core::Curve({{0, 0}, {1, 0}, {1, g}, {0, g}}));
    path.subpaths.push_back({0, 1, false});
    const StrokeOutline outline = stroke(path, round_style(width), tolerance, kWork, kSegments);
    ASSERT_EQ(outline.status, StrokeStatus::ok);
    EXPECT_LT(static_cast<double>(outline.contours.size()), 0.75 / (2 * reach) / 4);
    const test::MembershipCounts counts = test::check_round_membership(
        path, outline, width / 2, tolerance, probe_points(path, width / 2, tolerance, 12, 3000));
    EXPECT_GT(counts.inside, 100);
    EXPECT_GT(counts.outside, 100);
  }
}

TEST(Stroke, NearCuspOfTheCurveAtANarrowWidth) {
  // (0,0), (1,1/2), (0,1/2 + e), (1,0): x' = 3 (1 - 2t)^2 and y'(1/2) = 3e/4, so B' nearly
  // vanishes at t = 1/2 and the curve turns back there within a stretch of t of about e; its
  // parallel curves have cusps close on either side, where |B'| is far below its largest.
  for (const double e : {6.053e-7, 1e-7}) {
    SCOPED_TRACE(e);
    path::Path path;
    path.segments.push_back(core::Curve({{0, 0}, {1, 0.5}, {0, 0.5 + e}, {1, 0}}));
    path.subpaths.push_back({0, 1, false});
    const double width = 0.001, tolerance = 1e-6;
    const StrokeOutline outline = stroke(path, round_style(width), tolerance, 22000000, kSegments);
    ASSERT_EQ(outline.status, StrokeStatus::ok);
    const test::MembershipCounts counts = test::check_round_membership(
        path, outline, width / 2, tolerance, probe_points(path, width / 2, tolerance, 13, 3000));
    EXPECT_GT(counts.inside, 100);
    EXPECT_GT(counts.outside, 100);
  }
}

TEST(Stroke, ZeroLengthSubpathIsADotWithRoundCapsASquareWithSquareCapsNothingWithButt) {
  // SVG 2 (stroke-linecap): a zero-length subpath, drawn by a zero-length command or by
  // a moveto closed at once, is a disk of radius width / 2 under round caps, a square of
  // side width along the axes under square caps, nothing under butt caps.
  for (const char* data :
       {"M3 3 L3 3", "M3 3 Z", "M3 3 z z", "M0 0 M3 3 Z", "M3 3 A1 1 0 0 1 3 3 Z"}) {
    SCOPED_TRACE(data);
    const path::Path path = test::parsed_path(data);
    StrokeStyle style = round_style(2.0);
    auto winding_at = [&](const StrokeOutline& o, Point2 p) {
      core::WorkBudget work(kWork);
      return region::RegionWinding(test::outline_region(o)).at(p, work)->winding;
    };
    const StrokeOutline dot = stroke(path, style, 1e-3, kWork, kSegments);
    EXPECT_NE(winding_at(dot, {3.7, 3.7}), 0);   // distance 0.99
    EXPECT_EQ(winding_at(dot, {3.8, 3.8}), 0);   // distance 1.13
    EXPECT_EQ(winding_at(dot, {0.0, 0.0}), 0);   // a moveto alone is not stroked
    style.cap = LineCap::square;
    const StrokeOutline square = stroke(path, style, 1e-3, kWork, kSegments);
    EXPECT_NE(winding_at(square, {3.9, 3.9}), 0);  // inside the square of side 2
    EXPECT_EQ(winding_at(square, {4.1, 3.0}), 0);
    style.cap = LineCap::butt;
    EXPECT_TRUE(stroke(path, style, 1e-3, kWork, kSegments).contours.empty());
  }
}

/// The contours' vertices (segment ends).
std::vector<Point2> vertices(const StrokeOutline& o) {
  std::vector<Point2> out;
  for (const Contour& c : o.contours)
    for (const core::Curve& s : c) out.push_back(s.front());
  return out;
}

int winding_at(const StrokeOutline& o, Point2 p) {
  core::WorkBudget work(kWork);
  const auto w = region::RegionWinding(test::outline_region(o)).at(p, work);
  EXPECT_TRUE(w && !w->boundary);
  return w ? static_cast<int>(w->winding) : 0;
}

TEST(Stroke, MiterTipOfARightAngleIsSvgsPoint) {
  // Left turn by 90° at (10, 0), half width 1: the outer edges y = -1 and x = 11 meet at
  // (11, -1); the miter ratio is 1 / sin(45°) = √2 <= 4.
  const path::Path path = test::parsed_path("M0 0 L10 0 L10 10");
  StrokeStyle style;
  style.width = 2.0;
  const StrokeOutline miter = stroke(path, style, 1e-3, kWork, kSegments);
  const std::vector<Point2> v = vertices(miter);
  EXPECT_NE(std::find(v.begin(), v.end(), Point2{11.0, -1.0}), v.end());
  EXPECT_NE(winding_at(miter, {10.95, -0.95}), 0);
  // A miter limit below √2: a bevel, the line from (10, -1) to (11, 0): x - y = 11.
  style.miter_limit = 1.41;
  const StrokeOutline bevel = stroke(path, style, 1e-3, kWork, kSegments);
  const std::vector<Point2> w = vertices(bevel);
  EXPECT_EQ(std::find(w.begin(), w.end(), Point2{11.0, -1.0}), w.end());
  EXPECT_EQ(winding_at(bevel, {10.6, -0.6}), 0);   // x - y = 11.2
  EXPECT_NE(winding_at(bevel, {10.4, -0.4}), 0);   // x - y = 10.8
  style.miter_limit = 1.42;
  EXPECT_NE(winding_at(stroke(path, style, 1e-3, kWork, kSegments), {10.6, -0.6}), 0);
  style.join = LineJoin::bevel;
  style.miter_limit = 4.0;
  EXPECT_EQ(winding_at(stroke(path, style, 1e-3, kWork, kSegments), {10.6, -0.6}), 0);
}

TEST(Stroke, SquareCapsExtendHalfTheWidthButtCapsNothing) {
  const path::Path path = test::parsed_path("M0 0 L10 0");
  StrokeStyle style;
  style.width = 2.0;
  style.cap = LineCap::square;
  const StrokeOutline square = stroke(path, style, 1e-3, kWork, kSegments);
  const std::vector<Point2> v = vertices(square);
  for (const Point2 corner : {Point2{-1, 1}, Point2{-1, -1}, Point2{11, 1}, Point2{11, -1}}) {
    EXPECT_NE(std::find(v.begin(), v.end(), corner), v.end()) << corner.x << " " << corner.y;
  }
  EXPECT_NE(winding_at(square, {-0.99, 0.5}), 0);
  EXPECT_EQ(winding_at(square, {-1.01, 0.0}), 0);
  EXPECT_NE(winding_at(square, {10.99, -0.99}), 0);
  style.cap = LineCap::butt;
  const StrokeOutline butt = stroke(path, style, 1e-3, kWork, kSegments);
  EXPECT_EQ(winding_at(butt, {-0.01, 0.5}), 0);
  EXPECT_NE(winding_at(butt, {0.01, 0.5}), 0);
  EXPECT_EQ(winding_at(butt, {10.01, 0.0}), 0);
}

TEST(Stroke, ClosedSubpathHasAJoinAndNoCaps) {
  // Bevel join at (0, 0) between the closing edge (going -y) and the first (going +x): the
  // triangle (0, 0), (0, -1), (-1, 0); a square cap would have covered (-0.8, -0.8).
  const path::Path path = test::parsed_path("M0 0 L10 0 L10 10 L0 10 Z");
  StrokeStyle style;
  style.width = 2.0;
  style.join = LineJoin::bevel;
  style.cap = LineCap::square;
  const StrokeOutline o = stroke(path, style, 1e-3, kWork, kSegments);
  EXPECT_EQ(winding_at(o, {-0.8, -0.8}), 0);
  EXPECT_NE(winding_at(o, {-0.3, -0.3}), 0);
  // The same corner of an open path gets the caps.
  const StrokeOutline open = stroke(test::parsed_path("M0 0 L10 0 L10 10 L0 10 L0 1e-3"),
                                    style, 1e-3, kWork, kSegments);
  EXPECT_NE(winding_at(open, {-0.8, -0.8}), 0);
}

TEST(Stroke, SmoothClosedSubpathIsOneContourPerSide) {
  // A circle of four arcs (tangent-continuous joints) of radius 1, half width 0.25: every
  // joint is smooth and the radius of curvature (1) exceeds R on both sides, so the outline is
  // the two parallel curves (outer forward, inner backward), whatever the join, and the
  // region is the distance set: the annulus 0.75 < |p| < 1.25 to the tolerance.
  const std::string circle = "M1 0 A1 1 0 0 1 0 1 A1 1 0 0 1 -1 0 A1 1 0 0 1 0 -1 A1 1 0 0 1 1 0 Z";
  check_round_stroke(circle, 0.5, 1e-4);
  const path::Path path = test::parsed_path(circle);
  for (const LineJoin join : {LineJoin::miter, LineJoin::round, LineJoin::bevel}) {
    StrokeStyle style = round_style(0.5);
    style.join = join;
    const StrokeOutline o = stroke(path, style, 1e-4, kWork, kSegments);
    ASSERT_EQ(o.status, StrokeStatus::ok);
    EXPECT_EQ(o.contours.size(), 2u);
    EXPECT_EQ(winding_at(o, {0, 0}), 0);
    EXPECT_EQ(winding_at(o, {0.76, 0}), 1);
    EXPECT_EQ(winding_at(o, {0, -1.24}), 1);
    EXPECT_EQ(winding_at(o, {1.26, 0}), 0);
  }
}

TEST(Stroke, SmoothOpenChainIsOneContourAndItsCaps) {
  // The joint at (3, 0) arrives along (1, -1) and leaves along (1, -1): smooth. Round caps:
  // the run's contour and the two caps' disks.
  const std::string data = "M0 0 C1 1 2 1 3 0 C4 -1 5 -1 6 0";
  check_round_stroke(data, 0.5, 1e-3);
  const StrokeOutline o =
      stroke(test::parsed_path(data), round_style(0.5), 1e-3, kWork, kSegments);
  ASSERT_EQ(o.status, StrokeStatus::ok);
  EXPECT_EQ(o.contours.size(), 3u);
}

TEST(Stroke, SmoothClosedSubpathWithACuspIsWalkedFromTheCusp) {
  // Both joints are smooth (directions (1, -1) at (10, 0) and (1, 1) at (0, 0) on both
  // sides), and B' vanishes at t = 1/2 of the first cubic: the one run starts and ends there.
  const std::string data = "M0 0 C10 10 0 10 10 0 C11 -1 -1 -1 0 0 Z";
  check_round_stroke(data, 1.0, 1e-3);
  check_round_stroke(data, 3.0, 1e-3, 9);
}

TEST(Stroke, RoundIsTheDistanceSetForSmoothSplines) {
  // Closed Catmull-Rom splines through random points about a circle (tangent-continuous
  // joints up to the rounding of the control points), stroked narrow and wide: the wide ones
  // have tight sides next to smooth joints.
  test::Mulberry32 rng(7);
  for (int i = 0; i < 6; ++i) {
    const int n = 6 + i;
    std::vector<Point2> p;
    for (int k = 0; k < n; ++k) {
      const double a = 2 * std::numbers::pi * k / n, radius = rng.uniform(2.0, 4.0);
      p.push_back({radius * std::cos(a), radius * std::sin(a)});
    }
    std::ostringstream data;
    data.precision(17);
    data << "M" << p[0].x << " " << p[0].y;
    for (int k = 0; k < n; ++k) {
      const Point2 a = p[static_cast<std::size_t>((k + n - 1) % n)], b = p[static_cast<std::size_t>(k)];
      const Point2 c = p[static_cast<std::size_t>((k + 1) % n)], d = p[static_cast<std::size_t>((k + 2) % n)];
      const Point2 c1 = b + (1.0 / 6.0) * (c - a), c2 = c - (1.0 / 6.0) * (d - b);
      data << " C" << c1.x << " " << c1.y << " " << c2.x << " " << c2.y << " " << c.x << " " << c.y;
    }
    data << " Z";
    check_round_stroke(data.str(), i % 2 == 0 ? 0.3 : 2.5, 1e-3, 40 + static_cast<std::uint32_t>(i));
  }
}

TEST(Stroke, RefusesBeyondTheSegmentLimitAndTheWorkCap) {
  const path::Path path = test::parsed_path("M0 0 C10 10 0 10 10 0 L20 0");
  EXPECT_EQ(stroke(path, round_style(2.0), 1e-3, kWork, 5).status,
            StrokeStatus::too_many_segments);
  EXPECT_EQ(stroke(path, round_style(2.0), 1e-3, 1000, kSegments).status,
            StrokeStatus::work_cap_reached);
  EXPECT_TRUE(stroke(path, round_style(2.0), 1e-3, 1000, kSegments).contours.empty());
}

}  // namespace
}  // namespace bezier::outline
