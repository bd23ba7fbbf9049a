#include "core/path/elliptical_arc.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/path/svg_path_data.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::path {
namespace {

using core::Curve;
using core::Point2;
using Long = long double;

constexpr std::size_t kNoLimit = std::numeric_limits<std::size_t>::max();
constexpr double kPi = std::numbers::pi;

/// The ellipse of an arc and the arc on it, computed in long double straight from SVG's
/// implementation notes (F.6.5 and F.6.6, with the radii and the centre in the notes'
/// own form, squares and all), independently of the kernel's unit-coordinate form.
struct ReferenceArc {
  Long cx, cy, rx, ry, cos_phi, sin_phi, theta1, delta;

  explicit ReferenceArc(const EllipticalArc& a) {
    rx = std::abs(static_cast<Long>(a.rx));
    ry = std::abs(static_cast<Long>(a.ry));
    const Long phi = std::fmod(static_cast<Long>(a.x_axis_rotation_degrees), 360.0L) *
                     std::numbers::pi_v<Long> / 180.0L;
    cos_phi = std::cos(phi);
    sin_phi = std::sin(phi);
    const Long hx = (static_cast<Long>(a.from.x) - a.to.x) / 2, hy = (static_cast<Long>(a.from.y) - a.to.y) / 2;
    const Long x1 = cos_phi * hx + sin_phi * hy;
    const Long y1 = -sin_phi * hx + cos_phi * hy;
    const Long lambda = x1 * x1 / (rx * rx) + y1 * y1 / (ry * ry);
    if (lambda > 1) {
      rx *= std::sqrt(lambda);
      ry *= std::sqrt(lambda);
    }
    const Long num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
    const Long den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
    // Scaled radii make the radicand exactly 0 (rounding aside): the centre is the midpoint.
    Long coef = lambda >= 1 ? 0 : std::sqrt(std::max<Long>(0, num / den));
    if (a.large_arc == a.sweep) coef = -coef;
    const Long cxp = coef * rx * y1 / ry;
    const Long cyp = -coef * ry * x1 / rx;
    cx = cos_phi * cxp - sin_phi * cyp + (static_cast<Long>(a.from.x) + a.to.x) / 2;
    cy = sin_phi * cxp + cos_phi * cyp + (static_cast<Long>(a.from.y) + a.to.y) / 2;
    const Long ux = (x1 - cxp) / rx, uy = (y1 - cyp) / ry;
    const Long vx = (-x1 - cxp) / rx, vy = (-y1 - cyp) / ry;
    theta1 = std::atan2(uy, ux);
    delta = std::fmod(std::atan2(uy * vx * -1 + ux * vy, ux * vx + uy * vy) + 4 * std::numbers::pi_v<Long>,
                      2 * std::numbers::pi_v<Long>);
    if (!a.sweep && delta > 0) delta -= 2 * std::numbers::pi_v<Long>;
  }

  /// The point in the ellipse's unit coordinates: R(-φ) (p - C) / (rx, ry).
  void unit(Long x, Long y, Long& ux, Long& uy) const {
    const Long dx = x - cx, dy = y - cy;
    ux = (cos_phi * dx + sin_phi * dy) / rx;
    uy = (-sin_phi * dx + cos_phi * dy) / ry;
  }

  /// An upper bound of the distance from (x, y) to the ellipse, from its implicit equation
  /// F = (x'/rx)² + (y'/ry)² = 1: the ellipse point on the ray from the centre through the
  /// point is C + (p - C) / √F, at distance |p - C| |1 - 1/√F|.
  [[nodiscard]] Long distance_bound(Long x, Long y) const {
    Long ux, uy;
    unit(x, y, ux, uy);
    const Long f = ux * ux + uy * uy;
    return std::hypot(x - cx, y - cy) * std::abs(1 - 1 / std::sqrt(f));
  }

  /// How far outside the arc's angular range [θ1, θ1 + Δθ] (a radian count) the point's
  /// eccentric angle is; 0 inside.
  [[nodiscard]] Long angle_outside(Long x, Long y) const {
    Long ux, uy;
    unit(x, y, ux, uy);
    const Long two_pi = 2 * std::numbers::pi_v<Long>;
    // The angle from θ1 in the arc's direction, in [0, 2π).
    Long a = std::atan2(uy, ux) - theta1;
    if (delta < 0) a = -a;
    a = std::fmod(std::fmod(a, two_pi) + two_pi, two_pi);
    const Long span = std::abs(delta);
    if (a <= span) return 0;
    return std::min(a - span, two_pi - a);
  }
};

Long eval_coordinate(const Curve& c, Long t, bool y) {
  const auto p = c.points();
  const Long s = 1 - t;
  const auto v = [&](std::size_t i) { return static_cast<Long>(y ? p[i].y : p[i].x); };
  return s * s * s * v(0) + 3 * s * s * t * v(1) + 3 * s * t * t * v(2) + t * t * t * v(3);
}

ArcSegments cubics(const EllipticalArc& arc, std::optional<double> tolerance) {
  const ArcSegments out = arc_to_cubics(arc, tolerance, kNoLimit);
  EXPECT_EQ(out.status, ArcStatus::ok);
  return out;
}

/// The signed angle the joints of the segments turn through around (cx, cy).
double turned(const std::vector<Curve>& segments, Point2 centre) {
  double total = 0.0;
  for (const Curve& c : segments) {
    const Point2 a = c.front() - centre;
    const Point2 b = c.back() - centre;
    total += std::atan2(cross(a, b), dot(a, b));
  }
  return total;
}

TEST(EllipticalArc, ErrorFormulaIsTheLargestRadialDistanceOfTheCubic) {
  // The unit-circle cubic of angle δ sampled densely in long double: its largest |B| - 1
  // reaches ε(δ) (at u = t (1 - t) = 1/6) and never exceeds it.
  for (const double delta : {0.01, 0.3, kPi / 4, kPi / 2, 2.0, kPi, 5.0}) {
    const Long k = 4.0L / 3.0L * std::tan(static_cast<Long>(delta) / 4);
    const Long c0 = std::cos(static_cast<Long>(delta)), s0 = std::sin(static_cast<Long>(delta));
    const Long px[4] = {1, 1, c0 + k * s0, c0};
    const Long py[4] = {0, k, s0 - k * c0, s0};
    Long largest = 0, smallest = 1;
    for (int i = 0; i <= 20000; ++i) {
      const Long t = i / 20000.0L, s = 1 - t;
      const Long x = s * s * s * px[0] + 3 * s * s * t * px[1] + 3 * s * t * t * px[2] + t * t * t * px[3];
      const Long y = s * s * s * py[0] + 3 * s * s * t * py[1] + 3 * s * t * t * py[2] + t * t * t * py[3];
      largest = std::max(largest, std::hypot(x, y) - 1);
      smallest = std::min(smallest, std::hypot(x, y) - 1);
    }
    const double bound = circular_arc_cubic_error(delta);
    EXPECT_LE(static_cast<double>(largest), bound * (1 + 1e-9) + 1e-18) << delta;
    EXPECT_GE(static_cast<double>(largest), bound * (1 - 1e-6)) << delta;
    EXPECT_GE(static_cast<double>(smallest), -1e-18) << delta;  // never inside the circle
  }
}

TEST(EllipticalArc, QuarterCircleInOneCubicHasTheClassicControlPoints) {
  // A tolerance of 0.01 lets one cubic hold the quarter circle (ε(π/2) ≈ 2.7e-4).
  const ArcSegments out = cubics({{1, 0}, {0, 1}, 1, 1, 0, false, true}, 0.01);
  ASSERT_EQ(out.segments.size(), 1u);
  EXPECT_EQ(out.tolerance, 0.01);
  const auto p = out.segments[0].points();
  const double k = 4.0 / 3.0 * (std::sqrt(2.0) - 1.0);  // 4/3 tan(π/8)
  EXPECT_EQ(p[0], (Point2{1, 0}));
  EXPECT_EQ(p[3], (Point2{0, 1}));
  EXPECT_NEAR(p[1].x, 1.0, 1e-15);
  EXPECT_NEAR(p[1].y, k, 1e-15);
  EXPECT_NEAR(p[2].x, k, 1e-15);
  EXPECT_NEAR(p[2].y, 1.0, 1e-15);
}

TEST(EllipticalArc, QuarterCircleEndsAndTangentsAtTheDefaultTolerance) {
  const ArcSegments out = cubics({{1, 0}, {0, 1}, 1, 1, 0, false, true}, std::nullopt);
  EXPECT_EQ(out.tolerance, 1e-6);  // 1e-6 of the radius
  ASSERT_GE(out.segments.size(), 2u);
  const auto first = out.segments.front().points();
  const auto last = out.segments.back().points();
  EXPECT_EQ(first[0], (Point2{1, 0}));
  EXPECT_EQ(last[3], (Point2{0, 1}));
  // Tangent (0, 1) at the start (counter-clockwise), (-1, 0) at the end.
  EXPECT_NEAR(first[1].x - first[0].x, 0.0, 1e-15);
  EXPECT_GT(first[1].y - first[0].y, 0.0);
  EXPECT_NEAR(last[3].y - last[2].y, 0.0, 1e-15);
  EXPECT_LT(last[3].x - last[2].x, 0.0);
  for (std::size_t j = 1; j < out.segments.size(); ++j) {
    EXPECT_EQ(out.segments[j].front(), out.segments[j - 1].back());
    const Point2 joint = out.segments[j].front();
    EXPECT_NEAR(std::hypot(joint.x, joint.y), 1.0, 1e-15);
  }
}

TEST(EllipticalArc, RadiiTooSmallAreScaledToAHalfEllipse) {
  // A chord of 4 with radius 1: scaled to radius 2 about the chord's midpoint (2, 0). With
  // the sweep flag 1 the angle grows from π: the half circle below the chord, through
  // (2, -2); with 0 the one above.
  for (const bool sweep : {true, false}) {
    const ArcSegments out = cubics({{0, 0}, {4, 0}, 1, 1, 0, false, sweep}, std::nullopt);
    EXPECT_EQ(out.tolerance, 2e-6);
    EXPECT_NEAR(turned(out.segments, {2, 0}), sweep ? kPi : -kPi, 1e-12);
    for (const Curve& c : out.segments) {
      const Point2 joint = c.back();
      EXPECT_NEAR(std::hypot(joint.x - 2, joint.y), 2.0, 1e-14);
      EXPECT_TRUE(sweep ? joint.y <= 0.0 : joint.y >= 0.0) << joint.x << " " << joint.y;
    }
  }
}

TEST(EllipticalArc, ZeroRadiusIsALineAndEqualEndsAreNothing) {
  for (const auto& [rx, ry] : {std::pair{0.0, 5.0}, std::pair{5.0, 0.0}, std::pair{0.0, 0.0}}) {
    const ArcSegments out = cubics({{0, 0}, {3, 4}, rx, ry, 30, true, true}, std::nullopt);
    ASSERT_EQ(out.segments.size(), 1u);
    EXPECT_EQ(out.segments[0], Curve({{0, 0}, {3, 4}}));
    EXPECT_EQ(out.tolerance, 0.0);
  }
  const ArcSegments none = cubics({{1, 2}, {1, 2}, 3, 3, 0, true, true}, std::nullopt);
  EXPECT_TRUE(none.segments.empty());
}

TEST(EllipticalArc, FlagsPickOneOfFourArcs) {
  // Radius 1 through (0, 0) and (1, 1): centres (0, 1) and (1, 0). Counter-clockwise
  // (sweep 1) the small arc has its centre on the left of the chord, (0, 1).
  struct Case {
    bool large, sweep;
    Point2 centre;
    double turn;
  };
  const Case cases[] = {{false, true, {0, 1}, kPi / 2},
                        {true, true, {1, 0}, 3 * kPi / 2},
                        {false, false, {1, 0}, -kPi / 2},
                        {true, false, {0, 1}, -3 * kPi / 2}};
  for (const Case& c : cases) {
    const ArcSegments out = cubics({{0, 0}, {1, 1}, 1, 1, 0, c.large, c.sweep}, std::nullopt);
    EXPECT_NEAR(turned(out.segments, c.centre), c.turn, 1e-12) << c.large << c.sweep;
    for (const Curve& s : out.segments) {
      EXPECT_NEAR(std::hypot(s.back().x - c.centre.x, s.back().y - c.centre.y), 1.0, 1e-15);
    }
  }
}

TEST(EllipticalArc, PathDataReadsArcsWithCompactFlagsAndRelativeEnds) {
  const auto parse = [](std::string_view data) {
    PathDataParse p = parse_svg_path_data(data, kNoLimit);
    EXPECT_FALSE(p.error) << data;
    return p.path;
  };
  const Path spaced = parse("M0 0 a1 1 0 0 0 1 1");
  EXPECT_EQ(parse("M0 0 a1 1 0 00 1 1").segments, spaced.segments);
  EXPECT_EQ(parse("M0 0 a1,1,0,0,0,1,1").segments, spaced.segments);
  EXPECT_EQ(parse("M0 0 A1 1 0 0 0 1 1").segments, spaced.segments);
  EXPECT_EQ(parse("M0 0a1 1 0 001 1").segments, spaced.segments);
  EXPECT_EQ(spaced.arc_tolerance, 1e-6);
  EXPECT_EQ(spaced.segments.front().front(), (Point2{0, 0}));
  EXPECT_EQ(spaced.segments.back().back(), (Point2{1, 1}));
  // Repeated arguments repeat the command; a path without arcs states no tolerance.
  const Path two = parse("M0 0 a1 1 0 0 0 1 1 1 1 0 0 0 1 1");
  EXPECT_EQ(two.segments.back().back(), (Point2{2, 2}));
  EXPECT_EQ(two.subpaths.size(), 1u);
  EXPECT_FALSE(parse("M0 0 L1 1").arc_tolerance);
  // An arc ending where it starts draws nothing; S after an arc reflects nothing.
  EXPECT_EQ(parse("M1 1 A1 1 0 0 1 1 1 L2 2").segments, std::vector<Curve>{Curve({{1, 1}, {2, 2}})});
  const Path after = parse("M0 0 A1 1 0 0 1 1 1 S 3 3 4 4");
  EXPECT_EQ(after.segments.back().points()[1], (Point2{1, 1}));
  // A closing arc back to the start closes the subpath.
  const Path circle = parse("M0 0 A1 1 0 1 1 0 0.000001 Z");
  ASSERT_EQ(circle.subpaths.size(), 1u);
  EXPECT_TRUE(circle.subpaths[0].closed);
  // The given tolerance is the one used.
  const PathDataParse fine = parse_svg_path_data("M0 0 a1 1 0 0 0 1 1", kNoLimit, 1e-9);
  EXPECT_EQ(fine.path.arc_tolerance, 1e-9);
  EXPECT_GT(fine.path.segments.size(), spaced.segments.size());
}

TEST(EllipticalArc, SegmentLimitCountsTheArcsCubics) {
  const std::size_t pieces = parse_svg_path_data("M0 0 L1 0 A5 5 0 1 1 1 1", kNoLimit).path.segments.size();
  const PathDataParse limited = parse_svg_path_data("M0 0 L1 0 A5 5 0 1 1 1 1", pieces - 1);
  ASSERT_TRUE(limited.error);
  EXPECT_EQ(limited.error->kind, PathDataErrorKind::too_many_segments);
  EXPECT_EQ(limited.error->offset, 10u);
  EXPECT_FALSE(parse_svg_path_data("M0 0 L1 0 A5 5 0 1 1 1 1", pieces).error);
  // A tolerance too fine for the limit is refused before any cubic is made.
  const ArcSegments refused = arc_to_cubics({{0, 0}, {1, 1}, 1e6, 1e6, 0, true, true}, 1e-300, 50);
  EXPECT_EQ(refused.status, ArcStatus::too_many_pieces);
  EXPECT_TRUE(refused.segments.empty());
}

TEST(EllipticalArc, PieceCountsGrowAsTheToleranceShrinks) {
  const EllipticalArc arc{{3, -1}, {-2, 4}, 7, 3, 25, true, false};
  const ReferenceArc reference(arc);
  const double radius = static_cast<double>(std::max(reference.rx, reference.ry));
  std::size_t previous = 0;
  for (int e = 0; e <= 14; ++e) {
    const double tolerance = radius * std::pow(10.0, -e);
    const ArcSegments out = cubics(arc, tolerance);
    EXPECT_GE(out.segments.size(), previous) << tolerance;
    previous = out.segments.size();
    // And no fewer than needed: one piece less would break the bound, or a quarter turn.
    const double sweep = std::abs(static_cast<double>(reference.delta));
    if (out.segments.size() > 1 && out.tolerance == tolerance) {
      const double wider = sweep / static_cast<double>(out.segments.size() - 1);
      EXPECT_TRUE(radius * circular_arc_cubic_error(wider) > tolerance / 2 || wider > kPi / 2) << tolerance;
    }
  }
  EXPECT_GT(previous, 20u);
}

TEST(EllipticalArc, EveryCubicStaysWithinTheToleranceOfTheTrueEllipse) {
  bezier::test::Mulberry32 random(0x32a2c);
  const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * random.next(); };
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    EllipticalArc arc;
    arc.from = {uniform(-100, 100), uniform(-100, 100)};
    arc.to = {arc.from.x + uniform(-50, 50), arc.from.y + uniform(-50, 50)};
    arc.rx = uniform(0.5, 80) * (random.next() < 0.1 ? -1 : 1);
    arc.ry = uniform(0.5, 80);
    arc.x_axis_rotation_degrees = uniform(-720, 720);
    arc.large_arc = random.next() < 0.5;
    arc.sweep = random.next() < 0.5;
    const ReferenceArc reference(arc);
    // Radii that barely reach the end points make the centre ill-conditioned (header):
    // keep to arcs clearly inside or clearly scaled.
    Long x1, y1;
    {
      const Long hx = (static_cast<Long>(arc.from.x) - arc.to.x) / 2, hy = (static_cast<Long>(arc.from.y) - arc.to.y) / 2;
      const Long phi = std::fmod(static_cast<Long>(arc.x_axis_rotation_degrees), 360.0L) * std::numbers::pi_v<Long> / 180;
      x1 = std::cos(phi) * hx + std::sin(phi) * hy;
      y1 = -std::sin(phi) * hx + std::cos(phi) * hy;
    }
    const Long lambda = x1 * x1 / (static_cast<Long>(arc.rx) * arc.rx) + y1 * y1 / (static_cast<Long>(arc.ry) * arc.ry);
    if (lambda > 0.9L && lambda < 1.1L) continue;
    const std::optional<double> asked =
        trial % 3 == 0 ? std::nullopt : std::optional<double>(std::pow(10.0, uniform(-11, 0)));
    const ArcSegments out = cubics(arc, asked);
    const double larger = static_cast<double>(std::max(reference.rx, reference.ry));
    EXPECT_GE(out.tolerance, asked.value_or(1e-6 * larger * (1 - 1e-12)));
    ASSERT_FALSE(out.segments.empty());
    EXPECT_EQ(out.segments.front().front(), arc.from);
    EXPECT_EQ(out.segments.back().back(), arc.to);
    for (const Curve& c : out.segments) {
      ASSERT_EQ(c.degree(), 3);
      for (int i = 0; i <= 200; ++i) {
        const Long t = i / 200.0L;
        const Long x = eval_coordinate(c, t, false), y = eval_coordinate(c, t, true);
        const Long d = reference.distance_bound(x, y);
        ASSERT_LE(d, static_cast<Long>(out.tolerance))
            << "trial " << trial << " t " << static_cast<double>(t) << " arc " << arc.from.x << ","
            << arc.from.y << " " << arc.to.x << "," << arc.to.y << " r " << arc.rx << "," << arc.ry
            << " rot " << arc.x_axis_rotation_degrees << " flags " << arc.large_arc << arc.sweep
            << " asked " << asked.value_or(-1) << " pieces " << out.segments.size() << " lambda "
            << static_cast<double>(lambda);
        // On the right arc of the ellipse: angles outside its range only by rounding.
        ASSERT_LE(reference.angle_outside(x, y), 1e-9L) << "trial " << trial;
      }
    }
    // The whole arc is covered: the cubics turn through Δθ.
    const Point2 centre{static_cast<double>(reference.cx), static_cast<double>(reference.cy)};
    if (std::abs(reference.rx - reference.ry) < 1e-300L) {
      EXPECT_NEAR(turned(out.segments, centre), static_cast<double>(reference.delta), 1e-9);
    }
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

TEST(EllipticalArc, ToleranceNeverBelowTheRoundingFloor) {
  // Far from the origin a tolerance below 2^-40 of the coordinates cannot be met in
  // doubles: the one used is the floor, and the cubics keep it.
  const EllipticalArc arc{{1e6, 1e6}, {1e6 + 2, 1e6}, 1, 1, 0, false, true};
  const ArcSegments out = cubics(arc, 1e-20);
  EXPECT_GE(out.tolerance, std::ldexp(1e6, -40));
  const ReferenceArc reference(arc);
  for (const Curve& c : out.segments) {
    for (int i = 0; i <= 50; ++i) {
      const Long t = i / 50.0L;
      EXPECT_LE(reference.distance_bound(eval_coordinate(c, t, false), eval_coordinate(c, t, true)),
                static_cast<Long>(out.tolerance));
    }
  }
}

}  // namespace
}  // namespace bezier::path

namespace bezier::path {
namespace {

TEST(EllipticalArc, ExtremeRadiiAreScaledOrRefusedNeverGarbage) {
  // A subnormal radius is scaled up to the chord's half (the half circle of radius 1).
  const ArcSegments tiny = arc_to_cubics({{0, 0}, {2, 0}, 1e-320, 1e-320, 0, false, true}, std::nullopt, kNoLimit);
  ASSERT_EQ(tiny.status, ArcStatus::ok);
  EXPECT_EQ(tiny.tolerance, 1e-6);
  for (const Curve& c : tiny.segments) EXPECT_NEAR(std::hypot(c.back().x - 1, c.back().y), 1.0, 1e-15);
  // An ellipse reaching past the double range is refused as out of range.
  const ArcSegments huge = arc_to_cubics({{1e308, 0}, {-1e308, 0}, 1.5e308, 1.5e308, 0, true, true}, std::nullopt, kNoLimit);
  EXPECT_EQ(huge.status, ArcStatus::out_of_range);
  EXPECT_TRUE(huge.segments.empty());
}

}  // namespace
}  // namespace bezier::path

namespace bezier::path {
namespace {

/// The distance from p to the segment [a, b], in long double.
Long distance_to_segment(Long px, Long py, Point2 a, Point2 b) {
  const Long dx = static_cast<Long>(b.x) - a.x, dy = static_cast<Long>(b.y) - a.y;
  const Long wx = px - a.x, wy = py - a.y;
  const Long t = std::clamp((wx * dx + wy * dy) / (dx * dx + dy * dy), Long{0}, Long{1});
  return std::hypot(wx - t * dx, wy - t * dy);
}

TEST(EllipticalArc, HugeRadiiBetweenNearEndPointsStayAtTheChord) {
  // The small arc of an ellipse between end points a chord c apart bulges from the chord by
  // at most c² / (8 ρ) (1 + O(c² / ρ²)), ρ = min(rx, ry)² / max(rx, ry) the least radius of
  // curvature of the ellipse. Radii far beyond the chord make the arc its chord to within
  // that: every point of every cubic is there, up to rounding at the end points' scale,
  // however far the centre is. Large arcs of such ellipses go round the far side instead.
  struct Case {
    Point2 from, to;
    double rx, ry, rotation;
  };
  const Case cases[] = {
      {{0, 0}, {10, 0}, 1e6, 1e6, 0},          {{0, 0}, {10, 0}, 1e10, 1e10, 0},
      {{0, 0}, {10, 0}, 1e20, 1e20, 0},        {{0, 0}, {10, 0}, 1e300, 1e300, 0},
      {{1, 2}, {11, 7}, 1e20, 3e19, 30},       {{-3e3, 5}, {-2e3, -7}, 4e15, 1e17, -71},
      {{0.25, 0.5}, {0.5, 0.25}, 1e200, 1e180, 45},
  };
  for (const Case& c : cases) {
    for (const bool sweep : {false, true}) {
      const EllipticalArc arc{c.from, c.to, c.rx, c.ry, c.rotation, false, sweep};
      const ArcSegments out = arc_to_cubics(arc, std::nullopt, kNoLimit);
      ASSERT_EQ(out.status, ArcStatus::ok);
      ASSERT_FALSE(out.segments.empty());
      EXPECT_EQ(out.segments.front().front(), arc.from);
      EXPECT_EQ(out.segments.back().back(), arc.to);
      const Long chord = std::hypot(static_cast<Long>(c.to.x) - c.from.x, static_cast<Long>(c.to.y) - c.from.y);
      const Long rmin = std::min<Long>(c.rx, c.ry), rmax = std::max<Long>(c.rx, c.ry);
      const Long bulge = chord * chord / (8 * (rmin * rmin / rmax)) * 1.01L;
      const Long scale = std::max({std::abs(c.from.x), std::abs(c.from.y), std::abs(c.to.x), std::abs(c.to.y)});
      const Long rounding = 1e-12L * (scale + chord);
      for (const Curve& cubic : out.segments) {
        for (int i = 0; i <= 64; ++i) {
          const Long t = i / 64.0L;
          const Long d = distance_to_segment(eval_coordinate(cubic, t, false), eval_coordinate(cubic, t, true),
                                             c.from, c.to);
          EXPECT_LE(d, bulge + rounding) << c.rx << " " << c.ry << " sweep " << sweep << " t " << static_cast<double>(t);
        }
      }
    }
  }
}

TEST(EllipticalArc, HugeCircleArcBulgesByItsSagittaOnTheFlagsSide) {
  // From (0, 0) to (10, 0) on a circle of radius r: the sagitta is r - √(r² - 25), the
  // middle of the small arc that far from the chord's midpoint, below the chord (y-up) for
  // the sweep flag 1 (angles increasing, centre above) and above it for 0. One cubic at the
  // default tolerance, symmetric, so its middle is the arc's: B(1/2) = (5, ∓sagitta).
  for (const double r : {1e3, 1e5, 1e6}) {
    const Long sagitta = 25.0L / (r + std::sqrt(static_cast<Long>(r) * r - 25.0L));
    for (const bool sweep : {false, true}) {
      const ArcSegments out = arc_to_cubics({{0, 0}, {10, 0}, r, r, 0, false, sweep}, std::nullopt, kNoLimit);
      ASSERT_EQ(out.segments.size(), 1u);
      const Long y = eval_coordinate(out.segments[0], 0.5L, true);
      const Long x = eval_coordinate(out.segments[0], 0.5L, false);
      EXPECT_NEAR(static_cast<double>(x), 5.0, 1e-12);
      EXPECT_NEAR(static_cast<double>(y), static_cast<double>(sweep ? -sagitta : sagitta), 1e-9 * static_cast<double>(sagitta));
    }
  }
}

}  // namespace
}  // namespace bezier::path
