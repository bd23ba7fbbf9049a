#include "core/region/boolean.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/curve/evaluate.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/exact_polynomial.hpp"
#include "tests/support/mulberry32.hpp"
#include "tests/support/parsed_path.hpp"
#include "tests/support/region_checks.hpp"

namespace bezier::region {
namespace {

using core::Point2;
using test::parsed_path;
using test::Rational;

constexpr std::int64_t kWork = 100000000;

BooleanResult run(BooleanOperation op, const path::Path& a, const path::Path& b,
                  FillRule rule_a = FillRule::nonzero, FillRule rule_b = FillRule::nonzero) {
  BooleanResult r = boolean_operation(op, {a, rule_a}, {b, rule_b}, kWork);
  test::expect_clean(r, a, &b, 1e-9);
  return r;
}

BooleanResult run_simplify(const path::Path& a, FillRule rule) {
  BooleanResult r = simplify({a, rule}, kWork);
  test::expect_clean(r, a, nullptr, 1e-9);
  return r;
}

/// The signed area a path encloses, exactly (Green's theorem in rationals).
Rational exact_area(const path::Path& path) {
  Rational sum(0);
  for (const core::Curve& s : path.segments) {
    sum = sum + test::exact_green_integral(test::power_form(s), Rational(0), Rational(1));
  }
  return sum;
}

int count_ccw(const BooleanResult& r) {
  int n = 0;
  for (const ResultContour& c : r.contours) n += c.area > 0 ? 1 : 0;
  return n;
}

TEST(Boolean, OverlappingSquares) {
  // [0,2]^2 and [1,3]^2: areas 4 and 4, the common square 1.
  const path::Path a = parsed_path("M0 0 H2 V2 H0 Z");
  const path::Path b = parsed_path("M1 1 H3 V3 H1 Z");
  EXPECT_EQ(run(BooleanOperation::union_, a, b).area, 7.0);
  EXPECT_EQ(run(BooleanOperation::intersection, a, b).area, 1.0);
  EXPECT_EQ(run(BooleanOperation::difference, a, b).area, 3.0);
  EXPECT_EQ(run(BooleanOperation::difference, b, a).area, 3.0);
  EXPECT_EQ(run(BooleanOperation::xor_, a, b).area, 6.0);
  EXPECT_EQ(run(BooleanOperation::union_, a, b).contours.size(), 1u);
  EXPECT_EQ(run(BooleanOperation::intersection, a, b).contours.size(), 1u);
  EXPECT_EQ(run(BooleanOperation::xor_, a, b).contours.size(), 2u);
}

TEST(Boolean, SharedEdgeOppositeDirections) {
  // Side by side: A's right edge runs up x = 1, B's left edge runs down it.
  const path::Path a = parsed_path("M0 0 H1 V1 H0 Z");
  const path::Path b = parsed_path("M1 0 H2 V1 H1 Z");
  const BooleanResult u = run(BooleanOperation::union_, a, b);
  EXPECT_EQ(u.area, 2.0);
  ASSERT_EQ(u.contours.size(), 1u);
  // The shared edge is gone: the union is the rectangle's four sides, cut at x = 1 on the two
  // horizontal ones.
  EXPECT_EQ(u.contours[0].end_segment - u.contours[0].first_segment, 6u);
  const BooleanResult i = run(BooleanOperation::intersection, a, b);
  EXPECT_EQ(i.area, 0.0);
  EXPECT_TRUE(i.contours.empty());
  EXPECT_EQ(run(BooleanOperation::difference, a, b).area, 1.0);
  EXPECT_EQ(run(BooleanOperation::xor_, a, b).area, 2.0);
}

TEST(Boolean, SharedEdgeSameDirection) {
  // [0,2]x[0,1] and [1,2]x[0,2] both run up x = 2 on [0, 1].
  const path::Path a = parsed_path("M0 0 H2 V1 H0 Z");
  const path::Path b = parsed_path("M1 0 H2 V2 H1 Z");
  EXPECT_EQ(run(BooleanOperation::union_, a, b).area, 3.0);
  const BooleanResult i = run(BooleanOperation::intersection, a, b);
  EXPECT_EQ(i.area, 1.0);
  ASSERT_EQ(i.contours.size(), 1u);
  // The shared pieces are taken once, from a.
  for (std::size_t k = 0; k < i.segments.size(); ++k) {
    const ResultSegment& s = i.segments[k];
    const Point2 p = s.curve.front(), q = s.curve.back();
    if (p.x == 2.0 && q.x == 2.0) {
      EXPECT_EQ(s.source, Operand::a);
    }
    if (p.y == 0.0 && q.y == 0.0) {
      EXPECT_EQ(s.source, Operand::a);
    }
  }
  EXPECT_EQ(run(BooleanOperation::difference, a, b).area, 1.0);
  EXPECT_EQ(run(BooleanOperation::difference, b, a).area, 1.0);
  EXPECT_EQ(run(BooleanOperation::xor_, a, b).area, 2.0);
}

TEST(Boolean, CornerSquareSharesTwoEdges) {
  const path::Path a = parsed_path("M0 0 H2 V2 H0 Z");
  const path::Path b = parsed_path("M0 0 H1 V1 H0 Z");
  EXPECT_EQ(run(BooleanOperation::union_, a, b).area, 4.0);
  EXPECT_EQ(run(BooleanOperation::intersection, a, b).area, 1.0);
  const BooleanResult d = run(BooleanOperation::difference, a, b);
  EXPECT_EQ(d.area, 3.0);
  EXPECT_EQ(d.contours.size(), 1u);  // an L shape
  EXPECT_EQ(run(BooleanOperation::xor_, a, b).area, 3.0);
}

TEST(Boolean, VertexTouchingAnEdge) {
  // The triangle's lowest vertex (1, 2) lies on the square's top edge: contact without crossing.
  const path::Path a = parsed_path("M0 0 H2 V2 H0 Z");
  const path::Path b = parsed_path("M1 2 L2 4 L0 4 Z");
  const BooleanResult u = run(BooleanOperation::union_, a, b);
  EXPECT_EQ(u.area, 6.0);
  EXPECT_EQ(count_ccw(u), static_cast<int>(u.contours.size()));
  const BooleanResult i = run(BooleanOperation::intersection, a, b);
  EXPECT_EQ(i.area, 0.0);
  EXPECT_TRUE(i.contours.empty());
  EXPECT_EQ(run(BooleanOperation::difference, a, b).area, 4.0);
  EXPECT_EQ(run(BooleanOperation::xor_, a, b).area, 6.0);
}

TEST(Boolean, FourEdgesThroughACorner) {
  // The triangle (0,0), (3,1), (1,3) (area 4) starts at the square's corner; the parts beyond
  // x = 2 and beyond y = 2 are triangles of area 2/3 each, so A ∩ B = 8/3.
  const path::Path a = parsed_path("M0 0 H2 V2 H0 Z");
  const path::Path b = parsed_path("M0 0 L3 1 L1 3 Z");
  const double eight_thirds = Rational(8, 3).to_double();
  EXPECT_NEAR(run(BooleanOperation::intersection, a, b).area, eight_thirds, 4e-15);
  EXPECT_NEAR(run(BooleanOperation::union_, a, b).area, Rational(16, 3).to_double(), 8e-15);
  EXPECT_NEAR(run(BooleanOperation::difference, a, b).area, Rational(4, 3).to_double(), 4e-15);
  EXPECT_NEAR(run(BooleanOperation::difference, b, a).area, Rational(4, 3).to_double(), 4e-15);
}

TEST(Boolean, CheckerboardEightEdgesThroughOnePoint) {
  // Two diagonal cells of a 2x2 board in each operand: every edge meets (1, 1).
  const path::Path a = parsed_path("M0 0 H1 V1 H0 Z M1 1 H2 V2 H1 Z");
  const path::Path b = parsed_path("M1 0 H2 V1 H1 Z M0 1 H1 V2 H0 Z");
  const BooleanResult u = run(BooleanOperation::union_, a, b);
  EXPECT_EQ(u.area, 4.0);
  EXPECT_EQ(u.contours.size(), 1u);
  EXPECT_EQ(run(BooleanOperation::xor_, a, b).area, 4.0);
  EXPECT_TRUE(run(BooleanOperation::intersection, a, b).contours.empty());
  // simplify of a alone: two squares touching at one point, two contours.
  const BooleanResult s = run_simplify(a, FillRule::nonzero);
  EXPECT_EQ(s.area, 2.0);
  EXPECT_EQ(s.contours.size(), 2u);
}

TEST(Boolean, NestedContoursUnderBothFillRules) {
  // Both squares counter-clockwise: winding 2 in the inner one.
  const path::Path a = parsed_path("M0 0 H4 V4 H0 Z M1 1 H3 V3 H1 Z");
  const BooleanResult nonzero = run_simplify(a, FillRule::nonzero);
  EXPECT_EQ(nonzero.area, 16.0);
  EXPECT_EQ(nonzero.contours.size(), 1u);
  const BooleanResult evenodd = run_simplify(a, FillRule::evenodd);
  EXPECT_EQ(evenodd.area, 12.0);
  ASSERT_EQ(evenodd.contours.size(), 2u);
  EXPECT_EQ(count_ccw(evenodd), 1);  // the outer one; the hole runs clockwise
  // The inner one reversed: a hole under both rules.
  const path::Path holed = parsed_path("M0 0 H4 V4 H0 Z M1 1 V3 H3 V1 Z");
  EXPECT_EQ(run_simplify(holed, FillRule::nonzero).area, 12.0);
  EXPECT_EQ(run_simplify(holed, FillRule::evenodd).area, 12.0);
  // Against a square covering the hole's middle: [1.5, 2.5]^2 inside the hole.
  const path::Path c = parsed_path("M1.5 1.5 H2.5 V2.5 H1.5 Z");
  EXPECT_EQ(run(BooleanOperation::union_, a, c, FillRule::evenodd).area, 13.0);
  EXPECT_EQ(run(BooleanOperation::union_, a, c, FillRule::nonzero).area, 16.0);
  EXPECT_EQ(run(BooleanOperation::intersection, a, c, FillRule::evenodd).area, 0.0);
}

TEST(Boolean, DisjointOperands) {
  const path::Path a = parsed_path("M0 0 H1 V1 H0 Z");
  const path::Path b = parsed_path("M2 0 H3 V1 H2 Z");
  const BooleanResult u = run(BooleanOperation::union_, a, b);
  EXPECT_EQ(u.area, 2.0);
  EXPECT_EQ(u.contours.size(), 2u);
  EXPECT_TRUE(run(BooleanOperation::intersection, a, b).contours.empty());
  EXPECT_EQ(run(BooleanOperation::difference, a, b).area, 1.0);
  EXPECT_EQ(run(BooleanOperation::xor_, a, b).area, 2.0);
}

TEST(Boolean, EqualOperandsAndReversedCopy) {
  const path::Path a = parsed_path("M0 0 H2 Q3 1 2 2 H0 Z");
  const path::Path reversed = parsed_path("M0 0 V2 H2 Q3 1 2 0 Z");
  const double area = exact_area(a).to_double();
  for (const path::Path* b : {&a, &reversed}) {
    const BooleanResult u = run(BooleanOperation::union_, a, *b);
    EXPECT_NEAR(u.area, area, 1e-15);
    EXPECT_EQ(u.contours.size(), 1u);
    for (const ResultSegment& s : u.segments) EXPECT_EQ(s.source, Operand::a);
    EXPECT_NEAR(run(BooleanOperation::intersection, a, *b).area, area, 1e-15);
    EXPECT_TRUE(run(BooleanOperation::difference, a, *b).contours.empty());
    EXPECT_TRUE(run(BooleanOperation::xor_, a, *b).contours.empty());
  }
  // Under evenodd, a plus its reversed copy as one path is winding 0 everywhere.
  const path::Path both = parsed_path("M0 0 H2 Q3 1 2 2 H0 Z M0 0 V2 H2 Q3 1 2 0 Z");
  EXPECT_TRUE(run_simplify(both, FillRule::nonzero).contours.empty());
  EXPECT_TRUE(run_simplify(both, FillRule::evenodd).contours.empty());
}

TEST(Boolean, OneInsideTheOther) {
  const path::Path a = parsed_path("M0 0 H4 V4 H0 Z");
  const path::Path b = parsed_path("M1 1 H2 V2 H1 Z");
  EXPECT_EQ(run(BooleanOperation::union_, a, b).area, 16.0);
  EXPECT_EQ(run(BooleanOperation::intersection, a, b).area, 1.0);
  const BooleanResult d = run(BooleanOperation::difference, a, b);
  EXPECT_EQ(d.area, 15.0);
  ASSERT_EQ(d.contours.size(), 2u);
  EXPECT_EQ(count_ccw(d), 1);
  EXPECT_TRUE(run(BooleanOperation::difference, b, a).contours.empty());
  EXPECT_EQ(run(BooleanOperation::xor_, a, b).area, 15.0);
}

TEST(Boolean, EmptyOperand) {
  const path::Path a = parsed_path("M0 0 H2 V2 H0 Z");
  const path::Path empty;
  EXPECT_EQ(run(BooleanOperation::union_, a, empty).area, 4.0);
  EXPECT_TRUE(run(BooleanOperation::intersection, a, empty).contours.empty());
  EXPECT_EQ(run(BooleanOperation::difference, a, empty).area, 4.0);
  EXPECT_TRUE(run(BooleanOperation::difference, empty, a).contours.empty());
  EXPECT_EQ(run(BooleanOperation::xor_, empty, a).area, 4.0);
  const BooleanResult none = run(BooleanOperation::union_, empty, empty);
  EXPECT_TRUE(none.contours.empty());
  EXPECT_EQ(none.area, 0.0);
}

TEST(Boolean, FigureEightSimplify) {
  // (0,0) -> (2,2) -> (2,0) -> (0,2) -> back: two triangles of area 1 meeting at (1, 1), the
  // left one counter-clockwise (winding 1), the right one clockwise (winding -1).
  const path::Path a = parsed_path("M0 0 L2 2 L2 0 L0 2 Z");
  for (const FillRule rule : {FillRule::nonzero, FillRule::evenodd}) {
    const BooleanResult s = run_simplify(a, rule);
    EXPECT_EQ(s.area, 2.0);
    ASSERT_EQ(s.contours.size(), 2u);
    EXPECT_EQ(s.contours[0].area, 1.0);
    EXPECT_EQ(s.contours[1].area, 1.0);
    // Idempotent.
    const path::Path once = test::result_path(s);
    const BooleanResult twice = run_simplify(once, rule);
    EXPECT_EQ(twice.area, 2.0);
    EXPECT_EQ(twice.contours.size(), 2u);
  }
}

TEST(Boolean, OperandOverlappingItselfInTheSameDirection) {
  // The same square twice in one path: winding 2 inside, its edges shared with themselves.
  const path::Path twice = parsed_path("M0 0 H2 V2 H0 Z M0 0 H2 V2 H0 Z");
  const BooleanResult nonzero = run_simplify(twice, FillRule::nonzero);
  EXPECT_EQ(nonzero.area, 4.0);
  EXPECT_EQ(nonzero.contours.size(), 1u);
  EXPECT_TRUE(run_simplify(twice, FillRule::evenodd).contours.empty());
  // Half of it again, sharing three of its sides' pieces.
  const path::Path with_half = parsed_path("M0 0 H2 V2 H0 Z M0 0 H1 V2 H0 Z");
  EXPECT_EQ(run_simplify(with_half, FillRule::nonzero).area, 4.0);
  EXPECT_EQ(run_simplify(with_half, FillRule::evenodd).area, 2.0);
}

TEST(Boolean, CrossingsCloserThanTheToleranceAreOneVertex) {
  // The triangle's left vertex lies 2^-50 inside the square's right edge: its two sides cross
  // that edge 2^-51 above and below y = 1, and all three points are one vertex (within
  // kVertexMergeRel of scale), so the sliver between them is no contour.
  const double d = 0x1p-50;
  const path::Path a = parsed_path("M0 0 H2 V2 H0 Z");
  path::Path b;
  b.segments.push_back(core::Curve({{2 - d, 1}, {4, 0}}));
  b.segments.push_back(core::Curve({{4, 0}, {4, 2}}));
  b.segments.push_back(core::Curve({{4, 2}, {2 - d, 1}}));
  b.subpaths.push_back({0, 3, true});
  const double area_b = exact_area(b).to_double();
  const BooleanResult u = run(BooleanOperation::union_, a, b);
  EXPECT_NEAR(u.area, 4.0 + area_b, 1e-13);
  EXPECT_TRUE(run(BooleanOperation::intersection, a, b).contours.empty());
  EXPECT_NEAR(run(BooleanOperation::difference, a, b).area, 4.0, 1e-13);
  EXPECT_NEAR(run(BooleanOperation::difference, b, a).area, area_b, 1e-13);
}

TEST(Boolean, SegmentRetracingItself) {
  // A closed cubic that runs out along a line and back (palindromic control points: it
  // retraces itself), inside the square, and another outside it: zero area, they add
  // nothing and take nothing away.
  const path::Path a = parsed_path("M0 0 H2 V2 H0 Z M0.5 0.5 C1.5 1 1.5 1 0.5 0.5 M3 3 C4 4 4 4 3 3");
  for (const FillRule rule : {FillRule::nonzero, FillRule::evenodd}) {
    const BooleanResult s = run_simplify(a, rule);
    EXPECT_EQ(s.area, 4.0);
    EXPECT_EQ(s.contours.size(), 1u);
  }
  // The spike along a shared edge: a retraced piece of the square's bottom side.
  const path::Path b = parsed_path("M0 0 H2 V2 H0 Z M0.5 0 C1.5 0 1.5 0 0.5 0");
  EXPECT_EQ(run_simplify(b, FillRule::nonzero).area, 4.0);
}

TEST(Boolean, ZeroLengthSegmentsAddNothing) {
  // The square with a zero-length segment at a corner and 10000 single-point chains: the
  // same union as without them, and no work spent on the points' pairs.
  const path::Path a = parsed_path("M0 0 H2 L2 0 V2 H0 Z");
  path::Path b = parsed_path("M1 1 H3 V3 H1 Z");
  for (int k = 0; k < 10000; ++k) {
    b.subpaths.push_back({b.segments.size(), 1, true});
    b.segments.push_back(core::Curve({{9, 9}, {9, 9}}));
  }
  const BooleanResult u = run(BooleanOperation::union_, a, b);
  EXPECT_EQ(u.area, 7.0);
  EXPECT_EQ(u.contours.size(), 1u);
  EXPECT_LT(u.work, 1000000);
}

TEST(Boolean, PointsOneBillionthOfScaleOffEveryEdge) {
  // Promise 1 at its stated margin: beside every input edge of polygon operands, 1e-9 of the
  // scale away on either side (and at least that far from every other edge), a point is in
  // the result exactly when op(in a, in b) holds. Windings of polygons from their edges.
  const std::vector<std::pair<std::string, std::string>> pairs = {
      {"M0 0 H2 V2 H0 Z", "M1 1 H3 V3 H1 Z"},
      {"M0 0 H1 V1 H0 Z", "M1 0 H2 V1 H1 Z"},
      {"M0 0 H2 V1 H0 Z", "M1 0 H2 V2 H1 Z"},
      {"M0 0 H1 V1 H0 Z M1 1 H2 V2 H1 Z", "M1 0 H2 V1 H1 Z M0 1 H1 V2 H0 Z"},
      {"M0 0 H2 V2 H0 Z", "M0 0 L3 1 L1 3 Z"},
      {"M0 0 H4 V4 H0 Z M1 1 H3 V3 H1 Z", "M0 2 L4 1 L4 3 Z"},
      {"M0 0 L2 2 L2 0 L0 2 Z", "M0.5 0 H1.5 V2 H0.5 Z"},
  };
  const BooleanOperation ops[] = {BooleanOperation::union_, BooleanOperation::intersection,
                                  BooleanOperation::difference, BooleanOperation::xor_};
  for (const auto& [data_a, data_b] : pairs) {
    const path::Path a = parsed_path(data_a), b = parsed_path(data_b);
    const auto lines_a = test::polylines(a, 1), lines_b = test::polylines(b, 1);
    for (const FillRule rule : {FillRule::nonzero, FillRule::evenodd}) {
      for (const BooleanOperation op : ops) {
        SCOPED_TRACE(testing::Message() << data_a << " | " << data_b << " op " << static_cast<int>(op));
        const BooleanResult r = run(op, a, b, rule, rule);
        const auto lines_r = test::polylines(test::result_path(r), 1);
        for (const path::Path* source : {&a, &b}) {
          for (const core::Curve& edge : source->segments) {
            const Point2 d = edge.back() - edge.front();
            const Point2 n = Point2{-d.y, d.x} / core::length(d);
            for (const double t : {0.1, 0.3, 0.7, 0.9}) {
              for (const double side : {-1e-9, 1e-9}) {
                const Point2 p = core::evaluate(edge, t) + side * 4.0 * n;  // scale 4
                const test::PolylineWinding wa = test::polyline_winding(lines_a, p);
                const test::PolylineWinding wb = test::polyline_winding(lines_b, p);
                // Nearer another edge than the margin (near a vertex): not the promise.
                if (std::min(wa.distance, wb.distance) < 0.9e-9 * 4.0) continue;
                const bool expected = keeps(op, fills(rule, wa.winding), fills(rule, wb.winding));
                EXPECT_EQ(test::polyline_winding(lines_r, p).winding, expected ? 1 : 0)
                    << "at " << p.x << ", " << p.y;
              }
            }
          }
        }
      }
    }
  }
}

std::string circle(double cx, double cy, double r) {
  // Four cubic arcs from the points at 0, 90, 180 and 270 degrees.
  const double k = 0.5522847498307936 * r;
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer,
                "M%.17g %.17g C%.17g %.17g %.17g %.17g %.17g %.17g C%.17g %.17g %.17g %.17g "
                "%.17g %.17g C%.17g %.17g %.17g %.17g %.17g %.17g C%.17g %.17g %.17g %.17g %.17g "
                "%.17g Z",
                cx + r, cy, cx + r, cy + k, cx + k, cy + r, cx, cy + r, cx - k, cy + r, cx - r,
                cy + k, cx - r, cy, cx - r, cy - k, cx - k, cy - r, cx, cy - r, cx + k, cy - r,
                cx + r, cy - k, cx + r, cy);
  return buffer;
}

TEST(Boolean, CirclesTangentAtAJoint) {
  // Unit circles (as cubics) centred at (0,0) and (2,0) touch at (1, 0), where both have a
  // vertical tangent.
  const path::Path a = parsed_path(circle(0, 0, 1));
  const path::Path b = parsed_path(circle(2, 0, 1));
  const double area = exact_area(a).to_double();
  const BooleanResult u = run(BooleanOperation::union_, a, b);
  EXPECT_NEAR(u.area, 2 * area, 1e-14);
  EXPECT_TRUE(run(BooleanOperation::intersection, a, b).contours.empty());
  EXPECT_NEAR(run(BooleanOperation::difference, a, b).area, area, 1e-14);
  EXPECT_NEAR(run(BooleanOperation::xor_, a, b).area, 2 * area, 1e-14);
}

TEST(Boolean, CirclesTangentInsideSegments) {
  // The circle of radius 2 and the unit circle inside it touching at (2, 0) from inside
  // (internal tangency at a joint of both), and a unit circle rotated by 45 degrees,
  // touching the big one inside its arcs.
  const path::Path big = parsed_path(circle(0, 0, 2));
  const path::Path small = parsed_path(circle(1, 0, 1));
  const Rational big_area = exact_area(big), small_area = exact_area(small);
  EXPECT_NEAR(run(BooleanOperation::union_, big, small).area, big_area.to_double(), 1e-13);
  EXPECT_NEAR(run(BooleanOperation::intersection, big, small).area, small_area.to_double(), 1e-13);
  const BooleanResult d = run(BooleanOperation::difference, big, small);
  EXPECT_NEAR(d.area, (big_area - small_area).to_double(), 1e-13);
  // The difference is one region whose hole touches its outer boundary at (2, 0).
  EXPECT_GE(d.contours.size(), 1u);
}

TEST(Boolean, CirclesNearTangentAcrossTheTolerance) {
  // Unit circles (as cubics) whose centres are 2 r(0.3) + gap apart along the direction at
  // 0.3 radians, r(0.3) the first circle's radius there: they cross in a thin lens for
  // gap < 0, touch near gap = 0 and miss for gap > 0, on both sides of every tolerance.
  // Whatever the contacts found, area(A ∪ B) + area(A ∩ B) = area(A) + area(B).
  const path::Path a = parsed_path(circle(0, 0, 1));
  const double area = exact_area(a).to_double();
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = (lo + hi) / 2;
    const Point2 p = core::evaluate(a.segments[0], mid);
    (std::atan2(p.y, p.x) < 0.3 ? lo : hi) = mid;
  }
  const Point2 on = core::evaluate(a.segments[0], lo);
  const double r = std::hypot(on.x, on.y);
  for (const double gap : {1e-9, 1e-12, 1e-14, 0.0, -1e-14, -1e-12, -1e-9}) {
    SCOPED_TRACE(gap);
    const double d = 2 * r + gap;
    const path::Path b = parsed_path(circle(d * std::cos(0.3), d * std::sin(0.3), 1));
    const BooleanResult u = run(BooleanOperation::union_, a, b);
    const BooleanResult i = run(BooleanOperation::intersection, a, b);
    EXPECT_NEAR(u.area + i.area, 2 * area, 1e-13);
    EXPECT_LE(i.area, 1e-12);
  }
}

TEST(Boolean, CircleAndItsCopyMovedATinyDistance) {
  // The four-cubic circle of radius 5 (convex, its height 10 reached at (0, +-5) with level
  // tangents) and its copy moved by (d, 0): A u B covers A and the strip the move sweeps,
  // d x 10, less two cusps of area O(d^3) at the crossings; A n B is A less that strip. The
  // boundaries run within d of each other all the way round, and the answer must come
  // within the service's default work cap of 22 million units.
  const path::Path a = parsed_path(circle(0, 0, 5));
  const double area = exact_area(a).to_double();
  for (const double d : {1e-9, 1e-10, 1e-11}) {
    SCOPED_TRACE(d);
    const path::Path b = parsed_path(circle(d, 0, 5));
    const BooleanResult u = boolean_operation(BooleanOperation::union_, {a, FillRule::nonzero},
                                              {b, FillRule::nonzero}, 22'000'000);
    const BooleanResult i = boolean_operation(BooleanOperation::intersection, {a, FillRule::nonzero},
                                              {b, FillRule::nonzero}, 22'000'000);
    ASSERT_EQ(u.status, BooleanStatus::ok);
    ASSERT_EQ(i.status, BooleanStatus::ok);
    test::expect_clean(u, a, &b, 1e-9);
    test::expect_clean(i, a, &b, 1e-9);
    EXPECT_NEAR(u.area, area + 10 * d, d);
    EXPECT_NEAR(i.area, area - 10 * d, d);
  }
}

TEST(Boolean, MirroredArcsTouchingAtTheirMiddles) {
  // A's right arc runs from -45 to 45 degrees; B is A mirrored about the vertical line through
  // that arc's middle, so the two touch there with a common vertical tangent, inside a segment
  // of each.
  const double s = std::sqrt(0.5), k = 0.5522847498307936;
  const Point2 p[4] = {{s, -s}, {s + k * s, -s + k * s}, {s + k * s, s - k * s}, {s, s}};
  const core::Curve arc({p[0], p[1], p[2], p[3]});
  const double m = core::evaluate(arc, 0.5).x;
  char buffer[1024];
  const auto shape = [&](double sign, double offset) {
    // The arc, then straight lines around the left: a D shape, mirrored when sign = -1.
    std::snprintf(buffer, sizeof buffer, "M%.17g %.17g C%.17g %.17g %.17g %.17g %.17g %.17g L%.17g %.17g L%.17g %.17g Z",
                  offset + sign * p[0].x, p[0].y, offset + sign * p[1].x, p[1].y,
                  offset + sign * p[2].x, p[2].y, offset + sign * p[3].x, p[3].y,
                  offset + sign * -1.0, s, offset + sign * -1.0, -s);
    return parsed_path(buffer);
  };
  const path::Path a = shape(1.0, 0.0);
  const path::Path b = shape(-1.0, 2 * m);
  const double area_a = std::fabs(exact_area(a).to_double());
  const double area_b = std::fabs(exact_area(b).to_double());
  EXPECT_NEAR(run(BooleanOperation::union_, a, b).area, area_a + area_b, 1e-12);
  EXPECT_NEAR(run(BooleanOperation::intersection, a, b).area, 0.0, 1e-12);
  EXPECT_NEAR(run(BooleanOperation::xor_, a, b).area, area_a + area_b, 1e-12);
}

TEST(Boolean, DegreeFiveOperand) {
  // A quintic from (0,0) to (4,0) dipping below the x axis, closed by the line back along it.
  path::Path a;
  a.segments.push_back(core::Curve({{0, 0}, {1, -2}, {1.5, -3}, {2.5, -3}, {3, -2}, {4, 0}}));
  a.segments.push_back(core::Curve({{4, 0}, {0, 0}}));
  a.subpaths.push_back({0, 2, true});
  const double area = exact_area(a).to_double();
  ASSERT_GT(area, 0.0);
  // B: the rectangle below the axis; its top edge runs along a's closing line the other way
  // (B is counter-clockwise: along its top it runs from x = 5 to x = -1, as a's line does).
  const path::Path b = parsed_path("M-1 -10 H5 V0 H-1 Z");
  EXPECT_NEAR(run(BooleanOperation::intersection, a, b).area, area, 1e-14);
  EXPECT_NEAR(run(BooleanOperation::union_, a, b).area, 60.0, 1e-13);
  EXPECT_NEAR(run(BooleanOperation::difference, b, a).area, 60.0 - area, 1e-13);
  EXPECT_TRUE(run(BooleanOperation::difference, a, b).contours.empty());
  const BooleanResult i = run(BooleanOperation::intersection, a, b);
  bool has_quintic = false;
  for (const ResultSegment& seg : i.segments) has_quintic = has_quintic || seg.curve.degree() == 5;
  EXPECT_TRUE(has_quintic);
  EXPECT_NEAR(run_simplify(a, FillRule::nonzero).area, area, 1e-14);
}

/// For points on a grid over `box`, farther than `margin` from both the operand's and the
/// result's boundaries: the result's winding (polylines through its segments) is 1 exactly
/// where the operand's winding satisfies `keep`, and 0 elsewhere.
template <typename Keep>
void expect_region(const BooleanResult& r, const path::Path& operand, double lo, double hi,
                   double margin, Keep keep) {
  const auto in_lines = test::polylines(operand, 1000);
  const auto out_lines = test::polylines(test::result_path(r), 1000);
  int checked = 0;
  for (int i = 0; i <= 40; ++i) {
    for (int j = 0; j <= 40; ++j) {
      const Point2 p{lo + (hi - lo) * (i + 0.31) / 41.0, lo + (hi - lo) * (j + 0.47) / 41.0};
      const test::PolylineWinding w = test::polyline_winding(in_lines, p);
      const test::PolylineWinding v = test::polyline_winding(out_lines, p);
      if (w.distance < margin || v.distance < margin) continue;
      ++checked;
      EXPECT_EQ(v.winding, keep(w.winding) ? 1 : 0) << "at (" << p.x << ", " << p.y << ")";
    }
  }
  EXPECT_GT(checked, 500);
}

TEST(Boolean, OperandWithLoopSegmentsCombinedWithItsCopy) {
  // One contour of two cubics that each start and end at (-3, -8) (one-segment loops crossing
  // each other). Combined with an exact copy of itself, each loop is shared with its copy:
  // A and A = A or A = simplify(A), A minus A and A xor A are empty.
  const path::Path a =
      parsed_path("M-3 -8 C-5.5 4 -8 6.5 -3 -8 C4 4 -8 6.5 -3 -8 Z");
  for (const FillRule rule : {FillRule::evenodd, FillRule::nonzero}) {
    const BooleanResult s = run_simplify(a, rule);
    const auto keep = [rule](int w) { return rule == FillRule::evenodd ? (w & 1) != 0 : w != 0; };
    expect_region(s, a, -10.0, 6.0, 1e-3, keep);
    EXPECT_GT(s.area, 1.0);
    for (const BooleanOperation op : {BooleanOperation::intersection, BooleanOperation::union_}) {
      const BooleanResult r = run(op, a, a, rule, rule);
      EXPECT_NEAR(r.area, s.area, 1e-12 * s.area);
      expect_region(r, a, -10.0, 6.0, 1e-3, keep);
    }
    EXPECT_TRUE(run(BooleanOperation::difference, a, a, rule, rule).contours.empty());
    EXPECT_TRUE(run(BooleanOperation::xor_, a, a, rule, rule).contours.empty());
  }
  // Each loop alone, and with its copy: the loop's area is its Green integral (a simple
  // closed curve), exactly.
  for (const char* loop : {"M-3 -8 C-5.5 4 -8 6.5 -3 -8 Z", "M-3 -8 C4 4 -8 6.5 -3 -8 Z"}) {
    const path::Path l = parsed_path(loop);
    const double area = std::fabs(exact_area(l).to_double());
    EXPECT_NEAR(run_simplify(l, FillRule::nonzero).area, area, 1e-12 * area);
    EXPECT_NEAR(run(BooleanOperation::intersection, l, l).area, area, 1e-12 * area);
    EXPECT_NEAR(run(BooleanOperation::union_, l, l).area, area, 1e-12 * area);
    EXPECT_TRUE(run(BooleanOperation::difference, l, l).contours.empty());
  }
}

TEST(Boolean, NearTangentCrossingsBesideSegmentEnds) {
  // B (Paper.js issue 878's second shape) has a horizontal bottom edge at y = 480 whose ends
  // continue into cubics with horizontal tangents there. A's top edge runs one ulp below it
  // (y = 480 - 2^-44 * 1.0), so each cubic crosses it at an angle of about 4e-7 radians,
  // 3e-7 from B's segment end: a sliver one ulp thick between the two edges, ending in two
  // short cubic pieces whose directions at the crossings decide on which side of A's edge
  // they leave. Every operation is decided, clean, and right at points away from both
  // boundaries; the sliver's area (below 260 * 6e-14) is within the area checks' margin.
  const double below = std::nextafter(480.0, 0.0);
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, "M0 0 L500 0 L500 %.17g L0 %.17g Z", below, below);
  const path::Path rectangle = parsed_path(buffer);
  std::snprintf(buffer, sizeof buffer,
                "M431.90000000000003 %.17g L128.00000000000003 370 L80.00000000000003 %.17g Z",
                below, below);
  const path::Path triangle = parsed_path(buffer);
  const path::Path b =
      parsed_path("M400 480 L140 480 C130 480 300 300 300 300 C300 300 410 480 400 480 Z");
  const double area_b = std::fabs(exact_area(b).to_double());
  const BooleanOperation ops[] = {BooleanOperation::union_, BooleanOperation::intersection,
                                  BooleanOperation::difference, BooleanOperation::xor_};
  for (const path::Path* a : {&rectangle, &triangle}) {
    const double area_a = std::fabs(exact_area(*a).to_double());
    const auto lines_a = test::polylines(*a, 1000), lines_b = test::polylines(b, 1000);
    double areas[4];
    for (std::size_t k = 0; k < 4; ++k) {
      SCOPED_TRACE(static_cast<int>(ops[k]));
      const BooleanResult r = run(ops[k], *a, b);
      ASSERT_EQ(r.status, BooleanStatus::ok);
      areas[k] = r.area;
      const auto lines_r = test::polylines(test::result_path(r), 1000);
      test::Mulberry32 random(878);
      for (int i = 0; i < 1000; ++i) {
        const Point2 p{random.uniform(-10, 510), random.uniform(-10, 490)};
        const test::PolylineWinding wa = test::polyline_winding(lines_a, p);
        const test::PolylineWinding wb = test::polyline_winding(lines_b, p);
        if (std::min(wa.distance, wb.distance) < 0.5) continue;  // beyond the chords' sagitta
        const bool expected = keeps(ops[k], fills(FillRule::nonzero, wa.winding),
                                    fills(FillRule::nonzero, wb.winding));
        EXPECT_EQ(test::polyline_winding(lines_r, p).winding, expected ? 1 : 0)
            << p.x << ", " << p.y;
      }
    }
    EXPECT_NEAR(areas[0] + areas[1], area_a + area_b, 1e-9);
    EXPECT_NEAR(areas[3], areas[0] - areas[1], 1e-9);
    EXPECT_NEAR(areas[2], areas[0] - area_b, 1e-9);
    EXPECT_NEAR(run_simplify(b, FillRule::nonzero).area, area_b, 1e-9);
  }
  // The rectangle holds all of B but the sliver.
  EXPECT_NEAR(run(BooleanOperation::intersection, rectangle, b).area, area_b, 1e-9);
}

TEST(Boolean, SegmentWithACuspAtItsMiddle) {
  // Cubics whose derivative vanishes at t = 1/2 (3/4 (P1 - P0) + 3/2 (P2 - P1) + 3/4 (P3 - P2)
  // = 0), each closed by a line: a region with one boundary curve that has a cusp halfway.
  // Its simplify is itself (one counter-clockwise contour of its exact area, or the
  // reversed region's), and every operation with a square beside it or over it is right at
  // points away from both boundaries.
  for (const char* data : {"M4 0 C6 1 5 0 5 1 Z", "M0 0 C2 2 0 2 2 0 Z", "M2 0 C0 2 2 2 0 0 Z"}) {
    SCOPED_TRACE(data);
    const path::Path a = parsed_path(data);
    const double area = std::fabs(exact_area(a).to_double());
    const BooleanResult s = run_simplify(a, FillRule::nonzero);
    ASSERT_EQ(s.contours.size(), 1u);
    EXPECT_GT(s.contours[0].area, 0.0);
    EXPECT_NEAR(s.area, area, 1e-14);
    const auto lines_a = test::polylines(a, 2000);
    for (const char* other :
         {"M10 10 H11 V11 H10 Z", "M-1 -1 H7 V3 H-1 Z", "M1 0.5 H5.5 V2 H1 Z"}) {
      const path::Path b = parsed_path(other);
      const auto lines_b = test::polylines(b, 1);
      for (const BooleanOperation op : {BooleanOperation::union_, BooleanOperation::intersection,
                                        BooleanOperation::difference, BooleanOperation::xor_}) {
        const BooleanResult r = run(op, a, b);
        ASSERT_EQ(r.status, BooleanStatus::ok);
        const auto lines_r = test::polylines(test::result_path(r), 2000);
        test::Mulberry32 random(5);
        for (int i = 0; i < 400; ++i) {
          const Point2 p{random.uniform(-1, 7), random.uniform(-1, 3)};
          const test::PolylineWinding wa = test::polyline_winding(lines_a, p);
          const test::PolylineWinding wb = test::polyline_winding(lines_b, p);
          if (std::min(wa.distance, wb.distance) < 1e-3) continue;  // beyond the chords' sagitta
          const bool expected =
              keeps(op, fills(FillRule::nonzero, wa.winding), fills(FillRule::nonzero, wb.winding));
          EXPECT_EQ(test::polyline_winding(lines_r, p).winding, expected ? 1 : 0)
              << other << " at " << p.x << ", " << p.y;
        }
      }
    }
  }
}

TEST(Boolean, RetracedNeedleWithinRoundingOfAnEdge) {
  // Paper.js's resolveCrossings test 5: a rounded square and a cubic that runs 2.2e-7 out and
  // back (its control points 1e-13 apart across it), 2e-13 inside the square's bottom
  // corner arc. The needle's two halves are one group each whose edges cancel, and no ray
  // from them clears the arc; they separate nothing, so every operation is decided and the
  // needle adds no area: simplify gives the rounded square, under both fill rules.
  const std::string square =
      "M228.26666666666668,222.72h55.46666666666667c3.05499999999995,0 "
      "5.546666666666624,2.4916666666666742 "
      "5.546666666666624,5.546666666666681v55.46666666666667c0,3.05499999999995 "
      "-2.4916666666666742,5.546666666666624 "
      "-5.546666666666624,5.546666666666624h-55.46666666666667c-3.055000000000007,0 "
      "-5.546666666666681,-2.4916666666666742 "
      "-5.546666666666681,-5.546666666666624v-55.46666666666667c0,-3.055000000000007 "
      "2.4916666666666742,-5.546666666666681 "
      "5.546666666666681,-5.546666666666681z";
  const std::string needle =
      "M283.73333399705655,289.2799999999998c-2.212411231994338e-7,1.1368683772161603e-13 "
      "2.212409526691772e-7,0 0,0z";
  const path::Path a = parsed_path(square + needle);
  const double area = std::fabs(exact_area(parsed_path(square)).to_double());
  for (const FillRule rule : {FillRule::evenodd, FillRule::nonzero}) {
    const BooleanResult s = run_simplify(a, rule);
    ASSERT_EQ(s.status, BooleanStatus::ok);
    ASSERT_EQ(s.contours.size(), 1u);
    EXPECT_NEAR(s.area, area, 1e-9);
    const path::Path other = parsed_path("M250 250 H300 V300 H250 Z");
    const BooleanResult u = run(BooleanOperation::union_, a, other, rule, rule);
    ASSERT_EQ(u.status, BooleanStatus::ok);
    const BooleanResult i = run(BooleanOperation::intersection, a, other, rule, rule);
    ASSERT_EQ(i.status, BooleanStatus::ok);
    EXPECT_NEAR(u.area + i.area, area + 2500.0, 1e-9);
  }
}

TEST(Boolean, WorkCapIsReported) {
  const path::Path a = parsed_path(circle(0, 0, 1));
  const path::Path b = parsed_path(circle(0.5, 0.25, 1));
  const BooleanResult r = boolean_operation(BooleanOperation::union_, {a, FillRule::nonzero},
                                            {b, FillRule::nonzero}, 100);
  EXPECT_EQ(r.status, BooleanStatus::work_cap_reached);
  EXPECT_TRUE(r.contours.empty());
}

}  // namespace
}  // namespace bezier::region
