// Properties of the boolean operations on random glyph-like operands, checked against an
// oracle that shares no code with the implementation: winding numbers of finely flattened
// polylines (tests/support/region_checks.hpp) at random points away from every boundary.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/region/boolean.hpp"
#include "tests/support/mulberry32.hpp"
#include "tests/support/parsed_path.hpp"
#include "tests/support/region_checks.hpp"

namespace bezier::region {
namespace {

using core::Point2;

constexpr std::int64_t kWork = 200000000;
constexpr BooleanOperation kOps[] = {BooleanOperation::union_, BooleanOperation::intersection,
                                     BooleanOperation::difference, BooleanOperation::xor_};

double integer(test::Mulberry32& rng, double lo, double hi) { return std::floor(rng.uniform(lo, hi)); }

/// A star-shaped contour around `centre` with integer coordinates (glyph units): corners at
/// increasing angles, each side a line, a quadratic or a cubic whose control points stay in
/// the side's angular wedge.
void add_star(path::Path& path, test::Mulberry32& rng, Point2 centre, double r_lo, double r_hi) {
  const int n = 3 + static_cast<int>(rng.next() * 6);
  std::vector<double> angles;
  for (int i = 0; i < n; ++i) angles.push_back((i + 0.2 + 0.6 * rng.next()) * 2 * std::numbers::pi / n);
  const auto at = [&](double angle, double r) {
    return Point2{std::round(centre.x + r * std::cos(angle)), std::round(centre.y + r * std::sin(angle))};
  };
  std::vector<Point2> corners;
  for (double a : angles) corners.push_back(at(a, rng.uniform(r_lo, r_hi)));
  const std::size_t first = path.segments.size();
  for (int i = 0; i < n; ++i) {
    const Point2 p = corners[static_cast<std::size_t>(i)];
    const Point2 q = corners[static_cast<std::size_t>((i + 1) % n)];
    const double a0 = angles[static_cast<std::size_t>(i)];
    const double a1 = i + 1 < n ? angles[static_cast<std::size_t>(i + 1)] : angles[0] + 2 * std::numbers::pi;
    const int kind = static_cast<int>(rng.next() * 3);
    if (kind == 0 || p == q) {
      path.segments.push_back(core::Curve({p, q}));
    } else if (kind == 1) {
      path.segments.push_back(core::Curve({p, at((a0 + a1) / 2, rng.uniform(r_lo, r_hi)), q}));
    } else {
      path.segments.push_back(core::Curve({p, at(a0 + (a1 - a0) / 3, rng.uniform(r_lo, r_hi)),
                                           at(a0 + 2 * (a1 - a0) / 3, rng.uniform(r_lo, r_hi)), q}));
    }
  }
  path.subpaths.push_back({first, static_cast<std::size_t>(n), true});
}

/// A glyph-like operand: one or two star contours (which may overlap each other).
path::Path random_glyph(test::Mulberry32& rng) {
  path::Path path;
  const int contours = 1 + static_cast<int>(rng.next() * 2);
  for (int c = 0; c < contours; ++c) {
    add_star(path, rng, {integer(rng, -30, 30), integer(rng, -30, 30)}, 20, 60);
  }
  return path;
}

/// b made from a on purpose: a's first contour with some sides kept (shared edges in the same
/// direction) and the others replaced by new random sides, or a translated copy.
path::Path related_glyph(const path::Path& a, test::Mulberry32& rng) {
  path::Path b;
  const path::Subpath& sub = a.subpaths.front();
  if (rng.next() < 0.5) {
    const Point2 shift{integer(rng, -20, 20), integer(rng, -20, 20)};
    for (std::size_t k = 0; k < sub.segment_count; ++k) {
      std::vector<Point2> pts;
      for (Point2 p : a.segments[sub.first_segment + k].points()) pts.push_back(p + shift);
      b.segments.push_back(core::Curve(std::move(pts)));
    }
  } else {
    for (std::size_t k = 0; k < sub.segment_count; ++k) {
      const core::Curve& s = a.segments[sub.first_segment + k];
      if (rng.next() < 0.5) {
        b.segments.push_back(s);
      } else {
        // Another side between the same corners, bulging by a random integer offset.
        const Point2 mid = 0.5 * (s.front() + s.back());
        const Point2 c{std::round(mid.x + rng.uniform(-25, 25)), std::round(mid.y + rng.uniform(-25, 25))};
        b.segments.push_back(core::Curve({s.front(), c, s.back()}));
      }
    }
  }
  b.subpaths.push_back({0, b.segments.size(), true});
  return b;
}

path::Path scaled(const path::Path& p, double factor) {
  path::Path out = p;
  for (core::Curve& s : out.segments) {
    std::vector<Point2> pts;
    for (Point2 q : s.points()) pts.push_back(factor * q);
    s = core::Curve(std::move(pts));
  }
  return out;
}

path::Path translated(const path::Path& p, Point2 by) {
  path::Path out = p;
  for (core::Curve& s : out.segments) {
    std::vector<Point2> pts;
    for (Point2 q : s.points()) pts.push_back(q + by);
    s = core::Curve(std::move(pts));
  }
  return out;
}

path::Path reversed_contours(const path::Path& p) {
  path::Path out;
  for (const path::Subpath& sub : p.subpaths) {
    const std::size_t first = out.segments.size();
    for (std::size_t k = sub.segment_count; k-- > 0;) out.segments.push_back(core::reversed(p.segments[sub.first_segment + k]));
    out.subpaths.push_back({first, sub.segment_count, true});
  }
  return out;
}

struct Case {
  path::Path a;
  path::Path b;
  FillRule rule_a;
  FillRule rule_b;
};

Case random_case(test::Mulberry32& rng) {
  Case c;
  c.a = random_glyph(rng);
  c.b = rng.next() < 0.5 ? random_glyph(rng) : related_glyph(c.a, rng);
  c.rule_a = rng.next() < 0.5 ? FillRule::nonzero : FillRule::evenodd;
  c.rule_b = rng.next() < 0.5 ? FillRule::nonzero : FillRule::evenodd;
  return c;
}

BooleanResult run(BooleanOperation op, const Case& c) {
  return boolean_operation(op, {c.a, c.rule_a}, {c.b, c.rule_b}, kWork);
}

// Areas are sums of Green's integrals of pieces of coordinates up to about 100: rounding of a
// few ulps of 1e4 per segment, far below this.
constexpr double kAreaTolerance = 1e-8;

TEST(BooleanProperties, PointsAwayFromBoundariesFollowTheOperation) {
  test::Mulberry32 rng(20261206);
  for (int trial = 0; trial < 40; ++trial) {
    const Case c = random_case(rng);
    const auto lines_a = test::polylines(c.a, 128);
    const auto lines_b = test::polylines(c.b, 128);
    for (const BooleanOperation op : kOps) {
      SCOPED_TRACE(testing::Message() << "trial " << trial << " op " << static_cast<int>(op));
      const BooleanResult r = run(op, c);
      test::expect_clean(r, c.a, &c.b, 1e-9);
      if (r.status != BooleanStatus::ok) continue;
      const auto lines_r = test::polylines(test::result_path(r), 128);
      int checked = 0;
      for (int k = 0; k < 200; ++k) {
        const Point2 p{rng.uniform(-100, 100), rng.uniform(-100, 100)};
        const test::PolylineWinding wa = test::polyline_winding(lines_a, p);
        const test::PolylineWinding wb = test::polyline_winding(lines_b, p);
        if (wa.distance < 0.1 || wb.distance < 0.1) continue;
        const test::PolylineWinding wr = test::polyline_winding(lines_r, p);
        const bool expected = keeps(op, fills(c.rule_a, wa.winding), fills(c.rule_b, wb.winding));
        ASSERT_EQ(wr.winding, expected ? 1 : 0) << "at " << p.x << ", " << p.y;
        ++checked;
      }
      EXPECT_GT(checked, 60);
    }
  }
}

TEST(BooleanProperties, AreaIdentities) {
  test::Mulberry32 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE(testing::Message() << "trial " << trial);
    const Case c = random_case(rng);
    const BooleanResult u = run(BooleanOperation::union_, c);
    const BooleanResult i = run(BooleanOperation::intersection, c);
    const BooleanResult x = run(BooleanOperation::xor_, c);
    const BooleanResult d_ab = run(BooleanOperation::difference, c);
    const BooleanResult sa = simplify({c.a, c.rule_a}, kWork);
    const BooleanResult sb = simplify({c.b, c.rule_b}, kWork);
    for (const BooleanResult* r : {&u, &i, &x, &d_ab, &sa, &sb}) ASSERT_EQ(r->status, BooleanStatus::ok);
    EXPECT_NEAR(u.area + i.area, sa.area + sb.area, kAreaTolerance);
    EXPECT_NEAR(x.area, u.area - i.area, kAreaTolerance);
    EXPECT_NEAR(d_ab.area, sa.area - i.area, kAreaTolerance);
    // A minus A, A xor A: empty.
    const Case same{c.a, c.a, c.rule_a, c.rule_a};
    EXPECT_TRUE(run(BooleanOperation::difference, same).contours.empty());
    EXPECT_TRUE(run(BooleanOperation::xor_, same).contours.empty());
    EXPECT_NEAR(run(BooleanOperation::union_, same).area, sa.area, kAreaTolerance);
    // simplify is idempotent.
    const path::Path once = test::result_path(sa);
    const BooleanResult twice = simplify({once, FillRule::nonzero}, kWork);
    ASSERT_EQ(twice.status, BooleanStatus::ok);
    EXPECT_NEAR(twice.area, sa.area, kAreaTolerance);
    EXPECT_EQ(twice.contours.size(), sa.contours.size());
    const BooleanResult twice_evenodd = simplify({once, FillRule::evenodd}, kWork);
    EXPECT_NEAR(twice_evenodd.area, sa.area, kAreaTolerance);
  }
}

TEST(BooleanProperties, TranslationScalingByPowersOfTwoAndReversal) {
  test::Mulberry32 rng(99);
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE(testing::Message() << "trial " << trial);
    Case c = random_case(rng);
    c.rule_a = c.rule_b = FillRule::nonzero;
    for (const BooleanOperation op : kOps) {
      const BooleanResult r = run(op, c);
      ASSERT_EQ(r.status, BooleanStatus::ok);
      // Scaling by 2^-10 scales every computed value exactly.
      const Case small{scaled(c.a, 0x1p-10), scaled(c.b, 0x1p-10), c.rule_a, c.rule_b};
      const BooleanResult rs = run(op, small);
      ASSERT_EQ(rs.status, BooleanStatus::ok);
      EXPECT_EQ(rs.area, r.area * 0x1p-20);
      EXPECT_EQ(rs.contours.size(), r.contours.size());
      // Translating both (exactly: integer coordinates) changes only rounding: Green's
      // integrals of coordinates near 1e3 round at a few ulps of 1e6 per segment.
      const Case moved{translated(c.a, {1000, -500}), translated(c.b, {1000, -500}), c.rule_a, c.rule_b};
      const BooleanResult rm = run(op, moved);
      ASSERT_EQ(rm.status, BooleanStatus::ok);
      EXPECT_NEAR(rm.area, r.area, 1e-6);
      EXPECT_EQ(rm.contours.size(), r.contours.size());
      // Reversing every contour keeps the nonzero region.
      const Case back{reversed_contours(c.a), reversed_contours(c.b), c.rule_a, c.rule_b};
      const BooleanResult rb = run(op, back);
      ASSERT_EQ(rb.status, BooleanStatus::ok);
      EXPECT_NEAR(rb.area, r.area, kAreaTolerance);
    }
  }
}


TEST(BooleanProperties, SelfIntersectingOperandsSimplified) {
  // A pentagram (winding 2 in its centre), a cubic crossing itself closed by a line, a
  // degree-5 curve crossing itself three times, and a glyph of two overlapping stars: each
  // simplified under both fill rules, checked on a grid against the flattened oracle.
  std::vector<path::Path> shapes;
  shapes.push_back(test::parsed_path("M0 10 L6 -8 L-9.5 3 L9.5 3 L-6 -8 Z"));
  shapes.push_back(test::parsed_path("M-8 -8 C12 12 -12 12 8 -8 Z"));
  path::Path quintic;
  quintic.segments.push_back(core::Curve({{-9, 0}, {12, 14}, {-14, 7}, {14, -7}, {-12, -14}, {9, 0}}));
  quintic.segments.push_back(core::Curve({{9, 0}, {-9, 0}}));
  quintic.subpaths.push_back({0, 2, true});
  shapes.push_back(quintic);
  test::Mulberry32 rng(5);
  path::Path stars;
  add_star(stars, rng, {-3, 0}, 5, 9);
  add_star(stars, rng, {3, 1}, 5, 9);
  shapes.push_back(stars);
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    const auto lines = test::polylines(shapes[k], 512);
    for (const FillRule rule : {FillRule::nonzero, FillRule::evenodd}) {
      SCOPED_TRACE(testing::Message() << "shape " << k << " rule " << static_cast<int>(rule));
      const BooleanResult r = simplify({shapes[k], rule}, kWork);
      test::expect_clean(r, shapes[k], nullptr, 1e-9);
      const auto result_lines = test::polylines(test::result_path(r), 512);
      int checked = 0;
      for (double x = -12.05; x < 12; x += 0.25) {
        for (double y = -12.05; y < 12; y += 0.25) {
          const test::PolylineWinding w = test::polyline_winding(lines, {x, y});
          if (w.distance < 0.01) continue;
          ASSERT_EQ(test::polyline_winding(result_lines, {x, y}).winding, fills(rule, w.winding) ? 1 : 0)
              << "at " << x << ", " << y;
          ++checked;
        }
      }
      EXPECT_GT(checked, 1000);
    }
  }
}

/// Cells of a 6 x 6 board of unit squares, each its own contour (counter-clockwise or, at
/// random, clockwise), so that neighbouring cells share edges in opposite directions (or the
/// same one, when one is reversed) and four cells meet at each inner corner.
path::Path cells(const std::vector<bool>& chosen, test::Mulberry32& rng) {
  path::Path p;
  for (int k = 0; k < 36; ++k) {
    if (!chosen[static_cast<std::size_t>(k)]) continue;
    const double x = k % 6, y = k / 6;
    std::vector<Point2> corners{{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}};
    if (rng.next() < 0.3) std::swap(corners[1], corners[3]);
    const std::size_t first = p.segments.size();
    for (std::size_t i = 0; i < 4; ++i) p.segments.push_back(core::Curve({corners[i], corners[(i + 1) % 4]}));
    p.subpaths.push_back({first, 4, true});
  }
  return p;
}

TEST(BooleanProperties, BoardCellsGiveExactAreas) {
  // The area of op on two sets of cells is the number of cells where op holds: exact.
  test::Mulberry32 rng(36);
  for (int trial = 0; trial < 30; ++trial) {
    SCOPED_TRACE(testing::Message() << "trial " << trial);
    std::vector<bool> in_a(36), in_b(36);
    for (int k = 0; k < 36; ++k) {
      in_a[static_cast<std::size_t>(k)] = rng.next() < 0.5;
      in_b[static_cast<std::size_t>(k)] = rng.next() < 0.5;
    }
    const path::Path a = cells(in_a, rng), b = cells(in_b, rng);
    for (const BooleanOperation op : kOps) {
      int expected = 0;
      for (std::size_t k = 0; k < 36; ++k) expected += keeps(op, in_a[k], in_b[k]) ? 1 : 0;
      const BooleanResult r = boolean_operation(op, {a, FillRule::nonzero}, {b, FillRule::nonzero}, kWork);
      test::expect_clean(r, a, &b, 0.0);
      EXPECT_EQ(r.area, expected) << static_cast<int>(op);
      // Winding 1 in the cells op keeps, 0 in the others.
      const auto lines = test::polylines(test::result_path(r), 1);
      for (std::size_t k = 0; k < 36; ++k) {
        const Point2 centre{static_cast<double>(k % 6) + 0.5, static_cast<double>(k / 6) + 0.5};
        EXPECT_EQ(test::polyline_winding(lines, centre).winding, keeps(op, in_a[k], in_b[k]) ? 1 : 0);
      }
    }
  }
}

}  // namespace
}  // namespace bezier::region
