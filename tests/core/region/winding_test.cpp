#include "core/region/winding.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "tests/support/exact.hpp"
#include "tests/support/mulberry32.hpp"
#include "tests/support/parsed_path.hpp"

// Two oracles that share no code with the implementation: for paths of lines, the exact
// answer in rationals (the distance to every edge against the band, then the winding number
// by the quadrant method: a quarter turn per quadrant change of the vector to the target,
// a half turn decided by the exact sign of a cross product); for curves, a polyline of the
// path in long double with a bound on its distance from the curves, trusted only for
// targets clearly farther from it than that bound.

namespace bezier::region {
namespace {

using core::Curve;
using core::Point2;
using test::Rational;

constexpr std::int64_t kWork = 1'000'000'000;

struct Answer {
  bool boundary = false;
  long winding = 0;
  friend bool operator==(const Answer&, const Answer&) = default;
};

std::string describe(const Answer& a) {
  if (a.boundary) return "boundary";
  std::string out = "winding ";
  out += std::to_string(a.winding);
  return out;
}

Answer kernel(const Region& region, Point2 target) {
  const std::optional<Winding> w = winding(region, target, kWork);
  EXPECT_TRUE(w.has_value());
  if (!w) return {};
  return {w->boundary, w->boundary ? 0 : w->winding};
}

Region region_of(const char* data, FillRule rule = FillRule::nonzero) {
  return region_from_path(test::parsed_path(data), rule);
}

// ---- The exact oracle for paths of lines -------------------------------------------------

/// The quadrant of v: 0 for x > 0, y >= 0, then counter-clockwise (v != 0).
int quadrant(const Rational& x, const Rational& y) {
  if (x.sign() > 0 && y.sign() >= 0) return 0;
  if (x.sign() <= 0 && y.sign() > 0) return 1;
  if (x.sign() < 0 && y.sign() <= 0) return 2;
  return 3;
}

Answer exact_polygon_answer(const Region& region, Point2 target) {
  double s = std::fmax(std::fabs(target.x), std::fabs(target.y));
  for (const Curve& c : region.path.segments) {
    EXPECT_EQ(c.degree(), 1) << "the exact oracle takes lines only";
    for (const Point2 p : c.points()) s = std::fmax(s, std::fmax(std::fabs(p.x), std::fabs(p.y)));
  }
  const Rational band = Rational(s) * Rational(std::ldexp(1.0, -50));
  const Rational band2 = band * band;
  const Rational qx(target.x), qy(target.y);
  for (const Curve& c : region.path.segments) {
    const Rational ax(c.front().x), ay(c.front().y), bx(c.back().x), by(c.back().y);
    const Rational dx = bx - ax, dy = by - ay;
    const Rational len2 = dx * dx + dy * dy;
    Rational t(0);
    if (!len2.is_zero()) {
      t = ((qx - ax) * dx + (qy - ay) * dy) / len2;
      if (t < Rational(0)) t = Rational(0);
      if (t > Rational(1)) t = Rational(1);
    }
    const Rational ex = ax + t * dx - qx, ey = ay + t * dy - qy;
    if (ex * ex + ey * ey <= band2) return {true, 0};
  }
  long quarter_turns = 0;
  for (const Curve& c : region.path.segments) {
    const Rational ax = Rational(c.front().x) - qx, ay = Rational(c.front().y) - qy;
    const Rational bx = Rational(c.back().x) - qx, by = Rational(c.back().y) - qy;
    const int change = (quadrant(bx, by) - quadrant(ax, ay) + 4) % 4;
    if (change == 1) ++quarter_turns;
    if (change == 3) --quarter_turns;
    if (change == 2) quarter_turns += (ax * by - ay * bx).sign() > 0 ? 2 : -2;
  }
  EXPECT_EQ(quarter_turns % 4, 0);
  return {false, quarter_turns / 4};
}

void expect_exact(const Region& region, Point2 target, const std::string& what = "") {
  const Answer want = exact_polygon_answer(region, target);
  const Answer got = kernel(region, target);
  EXPECT_EQ(got, want) << what << " target (" << target.x << ", " << target.y << ") kernel "
                       << describe(got) << ", exact " << describe(want);
}

// ---- The polyline oracle for curves ------------------------------------------------------

struct LPoint {
  long double x, y;
};

LPoint evaluate_long(const Curve& c, long double t) {
  std::vector<LPoint> row;
  for (const Point2 p : c.points()) row.push_back({p.x, p.y});
  for (std::size_t level = 1; level < row.size(); ++level) {
    for (std::size_t i = 0; i + level < row.size(); ++i) {
      row[i] = {(1 - t) * row[i].x + t * row[i + 1].x, (1 - t) * row[i].y + t * row[i + 1].y};
    }
  }
  return row[0];
}

/// A polyline of a path: `steps` chords per segment, each with the bound on its distance
/// from its curve: a chord of a degree-n curve over a parameter step h is within
/// n (n - 1) max|Δ²P| h² / 8 of the curve (|B''| <= n (n - 1) max|Δ²P|, and a chord of a
/// C² arc is within max|B''| h² / 8 of it).
struct Polyline {
  std::vector<LPoint> from, to;
  std::vector<long double> deviation;
};

Polyline polyline_of(const Region& region, int steps) {
  Polyline out;
  for (const Curve& c : region.path.segments) {
    const int n = c.degree();
    long double second = 0;
    for (int i = 0; i + 2 <= n; ++i) {
      const long double dx = static_cast<long double>(c[i + 2].x) - 2.0L * c[i + 1].x + c[i].x;
      const long double dy = static_cast<long double>(c[i + 2].y) - 2.0L * c[i + 1].y + c[i].y;
      second = std::fmax(second, std::hypot(dx, dy));
    }
    const long double h = 1.0L / steps;
    const long double deviation = n * (n - 1) * second * h * h / 8;
    LPoint a = {c.front().x, c.front().y};
    for (int k = 1; k <= steps; ++k) {
      const LPoint b = k == steps ? LPoint{c.back().x, c.back().y} : evaluate_long(c, k * h);
      out.from.push_back(a);
      out.to.push_back(b);
      out.deviation.push_back(deviation);
      a = b;
    }
  }
  return out;
}

/// The polyline's winding number around `target` by the quadrant method, or nullopt when
/// the target is within a chord's deviation bound (plus `margin`) of it.
std::optional<long> polyline_winding(const Polyline& line, Point2 target, long double margin) {
  long quarter_turns = 0;
  const auto quad = [](long double x, long double y) {
    if (x > 0 && y >= 0) return 0;
    if (x <= 0 && y > 0) return 1;
    if (x < 0 && y <= 0) return 2;
    return 3;
  };
  for (std::size_t k = 0; k < line.from.size(); ++k) {
    const long double ax = line.from[k].x - target.x, ay = line.from[k].y - target.y;
    const long double bx = line.to[k].x - target.x, by = line.to[k].y - target.y;
    const long double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
    long double t = len2 > 0 ? -(ax * dx + ay * dy) / len2 : 0;
    t = std::fmin(std::fmax(t, 0.0L), 1.0L);
    if (std::hypot(ax + t * dx, ay + t * dy) <= line.deviation[k] + margin) return std::nullopt;
    const int change = (quad(bx, by) - quad(ax, ay) + 4) % 4;
    if (change == 1) ++quarter_turns;
    if (change == 3) --quarter_turns;
    if (change == 2) quarter_turns += ax * by - ay * bx > 0 ? 2 : -2;
  }
  EXPECT_EQ(quarter_turns % 4, 0);
  return quarter_turns / 4;
}

// ---- Polygons ------------------------------------------------------------------------------

TEST(Winding, SquareCountsCounterClockwiseTurnsWithYUp) {
  const Region ccw = region_of("M0 0 H4 V4 H0 Z");
  const Region cw = region_of("M0 0 V4 H4 V0 Z");
  EXPECT_EQ(kernel(ccw, {2, 2}), (Answer{false, 1}));
  EXPECT_EQ(kernel(cw, {2, 2}), (Answer{false, -1}));
  for (const Point2 q : {Point2{5, 2}, Point2{-1, 2}, Point2{2, 5}, Point2{2, -1}, Point2{9, 9}}) {
    EXPECT_EQ(kernel(ccw, q), (Answer{false, 0}));
    EXPECT_EQ(kernel(cw, q), (Answer{false, 0}));
  }
  EXPECT_TRUE(inside(*winding(ccw, {2, 2}, kWork), FillRule::evenodd));
  EXPECT_FALSE(inside(*winding(ccw, {5, 2}, kWork), FillRule::nonzero));
}

TEST(Winding, TargetsOnVerticesAndEdgesAreOnTheBoundary) {
  const Region r = region_of("M0 0 L3 1 L1 4 Z");
  for (const Point2 q : {Point2{0, 0}, Point2{3, 1}, Point2{1, 4}, Point2{1.5, 0.5}, Point2{2, 2.5},
                         Point2{0.5, 2}}) {
    EXPECT_EQ(kernel(r, q), (Answer{true, 0})) << q.x << ", " << q.y;
    expect_exact(r, q);
    EXPECT_TRUE(inside(*winding(r, q, kWork), FillRule::nonzero));
  }
}

TEST(Winding, OneUlpOffAnEdgeOnEitherSideIsWithinTheBand) {
  const Region r = region_of("M0 0 L3 1 L1 4 Z");
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (const Point2 on : {Point2{1.5, 0.5}, Point2{2, 2.5}, Point2{0.5, 2}, Point2{3, 1}}) {
    for (const Point2 q :
         {Point2{std::nextafter(on.x, inf), on.y}, Point2{std::nextafter(on.x, -inf), on.y},
          Point2{on.x, std::nextafter(on.y, inf)}, Point2{on.x, std::nextafter(on.y, -inf)}}) {
      expect_exact(r, q, "one ulp off");
      EXPECT_TRUE(kernel(r, q).boundary);
    }
  }
}

TEST(Winding, TheBandsEdgeIsDecidedToTheUlp) {
  // The square [-1, 1]^2: s = 1 for targets inside it, so the band is 8 u = 2^-50.
  const Region r = region_of("M-1 -1 H1 V1 H-1 Z");
  const double band = std::ldexp(1.0, -50), ulp = std::ldexp(1.0, -53);
  const double bottom = -1.0, left = -1.0;
  EXPECT_EQ(kernel(r, {0.25, bottom + band + ulp}), (Answer{false, 1}));
  EXPECT_EQ(kernel(r, {0.25, bottom + band - ulp}), (Answer{true, 0}));
  EXPECT_EQ(kernel(r, {0.25, bottom + band}), (Answer{true, 0}));
  EXPECT_EQ(kernel(r, {left + band + ulp, -0.375}), (Answer{false, 1}));
  EXPECT_EQ(kernel(r, {left + band - ulp, -0.375}), (Answer{true, 0}));
  // Outside, |y| > 1 sets the scale: the band is 2^-50 |y|, and 2^-52 is one ulp there.
  const double out_ulp = std::ldexp(1.0, -52);
  EXPECT_EQ(kernel(r, {0.25, bottom - band - out_ulp}), (Answer{false, 0}));
  EXPECT_EQ(kernel(r, {0.25, bottom - band + out_ulp}), (Answer{true, 0}));
  // Diagonally off a corner: the distance is Euclidean, not per coordinate.
  const double d = band * 0.75;  // both offsets inside the band, the distance 1.06 band
  EXPECT_EQ(kernel(r, {1 + d, 1 + d}), (Answer{false, 0}));
  EXPECT_EQ(kernel(r, {1 + band * 0.5, 1 + band * 0.5}), (Answer{true, 0}));
  for (const Point2 q : {Point2{0.25, bottom + band + ulp}, Point2{0.25, bottom + band - ulp},
                         Point2{left + band + ulp, -0.375}, Point2{0.25, bottom - band - out_ulp},
                         Point2{0.25, bottom - band + out_ulp}, Point2{1 + d, 1 + d}}) {
    expect_exact(r, q, "band edge");
  }
}

TEST(Winding, NestedContoursUnderBothFillRules) {
  // Outer counter-clockwise; inner the same way (winding 2) or the other way (a hole, 0).
  const Region same = region_of("M0 0 H10 V10 H0 Z M3 3 H7 V7 H3 Z", FillRule::evenodd);
  const Region hole = region_of("M0 0 H10 V10 H0 Z M3 3 V7 H7 V3 Z", FillRule::nonzero);
  const Winding in_same = *winding(same, {5, 5}, kWork);
  const Winding in_hole = *winding(hole, {5, 5}, kWork);
  EXPECT_EQ(in_same.winding, 2);
  EXPECT_EQ(in_hole.winding, 0);
  EXPECT_FALSE(inside(in_same, FillRule::evenodd));
  EXPECT_TRUE(inside(in_same, FillRule::nonzero));
  EXPECT_FALSE(inside(in_hole, FillRule::nonzero));
  EXPECT_EQ(winding(same, {1, 5}, kWork)->winding, 1);
  EXPECT_EQ(winding(hole, {1, 5}, kWork)->winding, 1);
  for (const Point2 q : {Point2{5, 5}, Point2{1, 5}, Point2{3, 5}, Point2{7, 7}, Point2{11, 5}}) {
    expect_exact(same, q);
    expect_exact(hole, q);
  }
}

TEST(Winding, RaysThroughVerticesAndAlongHorizontalEdges) {
  // A notch whose tip (4, 2) touches the ray y = 2 from above and turns back; a step whose
  // horizontal edges lie on the rays y = 1 and y = 2; a vertex the boundary passes through.
  const Region notch = region_of("M0 0 L6 0 L6 4 L4 2 L2 4 L0 4 Z");
  const Region step = region_of("M0 0 L2 0 L2 1 L4 1 L4 2 L6 2 L6 3 L0 3 Z");
  const Region diamond = region_of("M2 0 L4 2 L2 4 L0 2 Z");
  EXPECT_EQ(kernel(notch, {1, 2}), (Answer{false, 1}));
  EXPECT_EQ(kernel(notch, {5, 2}), (Answer{false, 1}));
  EXPECT_EQ(kernel(notch, {4, 2.5}), (Answer{false, 0}));
  EXPECT_EQ(kernel(notch, {4, 2}), (Answer{true, 0}));
  EXPECT_EQ(kernel(step, {1, 1}), (Answer{false, 1}));
  EXPECT_EQ(kernel(step, {1, 2}), (Answer{false, 1}));
  EXPECT_EQ(kernel(step, {-1, 2}), (Answer{false, 0}));
  EXPECT_EQ(kernel(step, {3, 1.5}), (Answer{false, 1}));
  EXPECT_EQ(kernel(diamond, {1, 2}), (Answer{false, 1}));
  EXPECT_EQ(kernel(diamond, {-1, 2}), (Answer{false, 0}));
  EXPECT_EQ(kernel(diamond, {2, 4}), (Answer{true, 0}));
  EXPECT_EQ(kernel(diamond, {2, 5}), (Answer{false, 0}));
  for (double x = -1; x <= 7; x += 0.5) {
    for (double y = -1; y <= 5; y += 0.5) {
      expect_exact(notch, {x, y});
      expect_exact(step, {x, y});
      expect_exact(diamond, {x, y});
    }
  }
}

TEST(Winding, SelfIntersectingPolygonsAndTheFillRules) {
  // A pentagram: the centre winds twice (filled by nonzero, not by evenodd).
  const Region star = region_of("M0 10 L5.878 -8.09 L-9.511 3.09 L9.511 3.09 L-5.878 -8.09 Z");
  const Winding centre = *winding(star, {0, 0}, kWork);
  EXPECT_EQ(std::abs(centre.winding), 2);
  EXPECT_TRUE(inside(centre, FillRule::nonzero));
  EXPECT_FALSE(inside(centre, FillRule::evenodd));
  test::Mulberry32 rng(7);
  for (int i = 0; i < 300; ++i) expect_exact(star, {rng.uniform(-11, 11), rng.uniform(-11, 11)});
}

/// A random polygon like a glyph: an outer loop of `count` vertices around a centre and a
/// hole turning the other way, on a grid of 1/64 so that vertices and edge points repeat.
std::string random_glyph_polygon(test::Mulberry32& rng, int count) {
  std::string data;
  for (const auto& [radius, sense] : {std::pair{100.0, 1.0}, std::pair{40.0, -1.0}}) {
    for (int k = 0; k < count; ++k) {
      const double angle = sense * 2 * M_PI * k / count;
      const double r = radius * rng.uniform(0.6, 1.3);
      const double x = std::round(64 * r * std::cos(angle)) / 64;
      const double y = std::round(64 * r * std::sin(angle)) / 64;
      data += k == 0 ? 'M' : 'L';
      data += std::to_string(x);
      data += ' ';
      data += std::to_string(y);
      data += ' ';
    }
    data += "Z ";
  }
  return data;
}

TEST(Winding, RandomGlyphPolygonsAgreeWithTheExactOracle) {
  test::Mulberry32 rng(2026);
  constexpr double inf = std::numeric_limits<double>::infinity();
#if defined(__SANITIZE_ADDRESS__)
  // The oracle's big-number arithmetic is slow under the sanitizers: the first shape there.
  constexpr int kShapes = 1;
#else
  constexpr int kShapes = 6;
#endif
  for (int shape = 0; shape < kShapes; ++shape) {
    const std::string data = random_glyph_polygon(rng, 5 + 3 * shape);
    for (const FillRule rule : {FillRule::nonzero, FillRule::evenodd}) {
      const Region r = region_of(data.c_str(), rule);
      for (int i = 0; i < 100; ++i) {
        expect_exact(r, {rng.uniform(-140, 140), rng.uniform(-140, 140)}, data);
      }
      // Vertices, points on edges, and one ulp beside them; the grid's rays through them.
      for (const Curve& c : r.path.segments) {
        const Point2 a = c.front(), b = c.back();
        const Point2 mid = {(a.x + b.x) / 2, (a.y + b.y) / 2};
        expect_exact(r, a, data);
        expect_exact(r, mid, data);
        expect_exact(r, {std::nextafter(mid.x, inf), mid.y}, data);
        expect_exact(r, {mid.x, std::nextafter(mid.y, -inf)}, data);
        expect_exact(r, {a.x - 7, a.y}, data);
        expect_exact(r, {a.x + 3, a.y}, data);
      }
    }
  }
}

// ---- Curves --------------------------------------------------------------------------------

TEST(Winding, PointsOfCurvesAreOnTheBoundary) {
  // B(1/2) of these curves is a short binary fraction, a double exactly.
  const Region quad = region_of("M0 0 Q2 4 4 0 Z");       // B(1/2) = (2, 2)
  const Region cubic = region_of("M0 0 C0 4 4 4 4 0 Z");  // B(1/2) = (2, 3)
  EXPECT_EQ(kernel(quad, {2, 2}), (Answer{true, 0}));
  EXPECT_EQ(kernel(cubic, {2, 3}), (Answer{true, 0}));
  EXPECT_EQ(kernel(cubic, {2, std::nextafter(3.0, 4.0)}), (Answer{true, 0}));
  EXPECT_EQ(kernel(cubic, {std::nextafter(2.0, 0.0), 3}), (Answer{true, 0}));
  // Clockwise (y up) closed by the line from (4, 0) to (0, 0): winding -1 inside.
  EXPECT_EQ(kernel(quad, {2, 1.9}), (Answer{false, -1}));
  EXPECT_EQ(kernel(quad, {2, 2.1}), (Answer{false, 0}));
  EXPECT_EQ(kernel(cubic, {2, 2.999}), (Answer{false, -1}));
  EXPECT_EQ(kernel(cubic, {2, 3.001}), (Answer{false, 0}));
  // Just outside and inside the band across the cubic's apex (2, 3) (s = 4, band 2^-48):
  // the apex is the curve's nearest point to a target straight above or below it (within
  // its radius of curvature, 3/2), so the distance is the offset, a multiple of 2^-51.
  const double band = std::ldexp(4.0, -50);
  EXPECT_EQ(kernel(cubic, {2, 3 - band - std::ldexp(1.0, -51)}), (Answer{false, -1}));
  EXPECT_EQ(kernel(cubic, {2, 3 + band + std::ldexp(1.0, -51)}), (Answer{false, 0}));
  EXPECT_EQ(kernel(cubic, {2, 3 + band - std::ldexp(1.0, -51)}), (Answer{true, 0}));
}

/// A closed chain of `count` curves of `degree` around the origin like a glyph's outline:
/// end points on a wobbly circle, inner control points near the chord.
std::vector<Curve> random_outline(test::Mulberry32& rng, int count, int degree, double radius,
                                  double sense) {
  std::vector<Point2> ends;
  for (int k = 0; k < count; ++k) {
    const double angle = sense * 2 * M_PI * k / count;
    const double r = radius * rng.uniform(0.7, 1.3);
    ends.push_back({r * std::cos(angle), r * std::sin(angle)});
  }
  std::vector<Curve> curves;
  for (int k = 0; k < count; ++k) {
    const Point2 a = ends[k], b = ends[(k + 1) % count];
    std::vector<Point2> pts = {a};
    for (int i = 1; i < degree; ++i) {
      const double t = static_cast<double>(i) / degree;
      pts.push_back({a.x + t * (b.x - a.x) + rng.uniform(-0.4, 0.4) * radius,
                     a.y + t * (b.y - a.y) + rng.uniform(-0.4, 0.4) * radius});
    }
    pts.push_back(b);
    curves.emplace_back(std::move(pts));
  }
  return curves;
}

TEST(Winding, RandomCurvedOutlinesAgreeWithThePolylineOracle) {
  test::Mulberry32 rng(30);
  int decided = 0;
  for (int shape = 0; shape < 12; ++shape) {
    const int degree = 1 + shape % 5;  // lines to degree 5
    std::vector<Curve> curves = random_outline(rng, 6 + shape, degree, 100.0, 1.0);
    std::vector<Curve> hole = random_outline(rng, 5, 3, 30.0, -1.0);
    curves.insert(curves.end(), hole.begin(), hole.end());
    const Region r = region_from_curves(curves, FillRule::nonzero);
    const Polyline line = polyline_of(r, 256);
    for (int i = 0; i < 200; ++i) {
      const Point2 q = {rng.uniform(-150, 150), rng.uniform(-150, 150)};
      const std::optional<long> want = polyline_winding(line, q, 1e-9L);
      if (!want) continue;
      ++decided;
      const Answer got = kernel(r, q);
      EXPECT_EQ(got, (Answer{false, *want}))
          << "shape " << shape << " target " << q.x << ", " << q.y;
    }
  }
  EXPECT_GT(decided, 1500);
}

TEST(Winding, TargetsOnRandomCurvesAreOnTheBoundaryAndTheirNeighboursAreNot) {
  // Points of the curves at t = k/8: B(t) rounded to doubles is within a few ulps of the
  // curve (within the band); targets 1e-4 off along the normal (1e-5 of the scale), where
  // the polyline oracle decides, take the winding numbers on either side.
  test::Mulberry32 rng(5);
  int decided = 0;
  for (int shape = 0; shape < 6; ++shape) {
    const int degree = 2 + shape % 4;
    const std::vector<Curve> curves = random_outline(rng, 7, degree, 10.0, 1.0);
    const Region r = region_from_curves(curves, FillRule::evenodd);
    const Polyline line = polyline_of(r, 4096);
    for (const Curve& c : curves) {
      for (int k = 1; k < 8; ++k) {
        const LPoint p = evaluate_long(c, k / 8.0L);
        const Point2 on = {static_cast<double>(p.x), static_cast<double>(p.y)};
        EXPECT_EQ(kernel(r, on), (Answer{true, 0})) << "shape " << shape;
        const LPoint p2 = evaluate_long(c, k / 8.0L + 1e-7L);
        long double nx = -(p2.y - p.y), ny = p2.x - p.x;
        const long double norm = std::hypot(nx, ny);
        if (norm == 0) continue;
        nx /= norm;
        ny /= norm;
        for (const double side : {1e-4, -1e-4}) {
          const Point2 q = {static_cast<double>(p.x + side * nx),
                            static_cast<double>(p.y + side * ny)};
          const std::optional<long> want = polyline_winding(line, q, 1e-12L);
          if (!want) continue;
          ++decided;
          EXPECT_EQ(kernel(r, q), (Answer{false, *want})) << "shape " << shape;
        }
      }
    }
  }
  EXPECT_GT(decided, 400);
}

TEST(Winding, AnswersAreUnchangedByScalingWithPowersOfTwo) {
  test::Mulberry32 rng(11);
  const std::vector<Curve> curves = random_outline(rng, 9, 3, 1.0, 1.0);
  const Region r = region_from_curves(curves, FillRule::nonzero);
  for (const int e : {-1000, -300, 0, 300, 600, 1000}) {
    std::vector<Curve> scaled;
    for (const Curve& c : curves) {
      std::vector<Point2> pts;
      for (const Point2 p : c.points()) pts.push_back({std::ldexp(p.x, e), std::ldexp(p.y, e)});
      scaled.emplace_back(std::move(pts));
    }
    const Region rs = region_from_curves(scaled, FillRule::nonzero);
    test::Mulberry32 targets(3);
    for (int i = 0; i < 100; ++i) {
      const Point2 q = {targets.uniform(-1.5, 1.5), targets.uniform(-1.5, 1.5)};
      EXPECT_EQ(kernel(rs, {std::ldexp(q.x, e), std::ldexp(q.y, e)}), kernel(r, q)) << e;
    }
    const Point2 on = curves[2].front();
    EXPECT_TRUE(kernel(rs, {std::ldexp(on.x, e), std::ldexp(on.y, e)}).boundary);
  }
}

TEST(Winding, DegenerateRegions) {
  // No segment: nothing winds and nothing is on the boundary.
  const Region empty = region_from_path(path::Path{}, FillRule::nonzero);
  EXPECT_EQ(kernel(empty, {0, 0}), (Answer{false, 0}));
  // A curve that is one point: the point is the boundary.
  const Region dot = region_from_curves({Curve({{1, 1}, {1, 1}, {1, 1}})}, FillRule::nonzero);
  EXPECT_EQ(kernel(dot, {1, 1}), (Answer{true, 0}));
  EXPECT_EQ(kernel(dot, {1, 1.5}), (Answer{false, 0}));
  const Region origin = region_from_curves({Curve({{0, 0}, {0, 0}})}, FillRule::nonzero);
  EXPECT_EQ(kernel(origin, {0, 0}), (Answer{true, 0}));
  EXPECT_EQ(kernel(origin, {0, 1e-300}), (Answer{false, 0}));
  // A target far beyond the region's scale.
  const Region square = region_of("M0 0 H1e-200 V1e-200 H0 Z");
  EXPECT_EQ(kernel(square, {1e200, -1e200}), (Answer{false, 0}));
  EXPECT_EQ(kernel(square, {5e-201, 5e-201}), (Answer{false, 1}));
}

TEST(Winding, AZeroAreaSpikeIsBoundaryAlongItAndWindsNothingBeside) {
  // A contour that goes out and comes back along the same line: every point of the spike
  // is on the boundary, and every other point has winding 0.
  const Region spike = region_of("M0 0 L4 4 L0 0 Z");
  EXPECT_EQ(kernel(spike, {1, 1}), (Answer{true, 0}));
  EXPECT_EQ(kernel(spike, {1, 1.0001}), (Answer{false, 0}));
  EXPECT_EQ(kernel(spike, {-1, -1}), (Answer{false, 0}));
  expect_exact(spike, {2, std::nextafter(2.0, 0.0)});
}

TEST(Winding, TheWorkCapStopsIt) {
  const Region r = region_of("M0 0 C0 4 4 4 4 0 Z");
  EXPECT_FALSE(winding(r, {2, 3}, 10).has_value());
  core::WorkBudget none(0);
  const RegionWinding prepared(r);
  EXPECT_FALSE(prepared.at({2, 3}, none).has_value());
  EXPECT_TRUE(none.exhausted());
  core::WorkBudget ample(kWork);
  ASSERT_TRUE(prepared.at({2, 3}, ample).has_value());
  EXPECT_FALSE(ample.exhausted());
  EXPECT_GT(ample.spent(), 0);
  // What one target spent is enough for it, and one unit less is not.
  core::WorkBudget exact(ample.spent());
  EXPECT_TRUE(prepared.at({2, 3}, exact).has_value());
  core::WorkBudget short_by_one(ample.spent() - 1);
  EXPECT_FALSE(prepared.at({2, 3}, short_by_one).has_value());
}

}  // namespace
}  // namespace bezier::region
