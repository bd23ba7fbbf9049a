// Tests of POST /stroke at the handler level: the answer's shape (SVG path data of closed
// contours, `simplified`), the round stroke's region checked at points whose distance to the
// path is known in closed form, the simplified outline's region, and the validation rules.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "api/handler.hpp"
#include "core/measure/nearest.hpp"
#include "core/path/svg_path_data.hpp"
#include "core/region/region.hpp"
#include "core/region/winding.hpp"
#include "tests/support/route_answers.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

json call(const std::string& body, int expected_status, const Limits& limits = {}) {
  return test::route_answer("/stroke", body, expected_status, limits);
}

/// The winding number of the answer's path about p.
long winding_at(const json& answer, core::Point2 p) {
  path::PathDataParse parse = path::parse_svg_path_data(answer["path"].get<std::string>(), 100000);
  EXPECT_FALSE(parse.error);
  const region::Region region = region::region_from_path(std::move(parse.path), region::FillRule::nonzero);
  const std::optional<region::Winding> w = region::winding(region, p, std::int64_t{1} << 40);
  EXPECT_TRUE(w && !w->boundary);
  return w ? w->winding : 0;
}

TEST(StrokeRoute, RoundStrokeOfAPolylineHoldsThePointsCloserThanHalfTheWidth) {
  // Half width 1 about M0 0 L10 0 L10 10: the distance to the path is |y| on 0 <= x <= 10,
  // y <= 0; the distance to the corner (10, 0) beyond it.
  const json r = call(
      R"({"path":"M0 0 L10 0 L10 10","width":2,"join":"round","cap":"round","tolerance":1e-3})",
      200);
  EXPECT_EQ(r["simplified"], false);
  EXPECT_NE(winding_at(r, {5, -0.99}), 0);
  EXPECT_EQ(winding_at(r, {5, -1.01}), 0);
  EXPECT_NE(winding_at(r, {10.7, -0.7}), 0);   // 0.99 from the corner
  EXPECT_EQ(winding_at(r, {10.72, -0.72}), 0);  // 1.018 from it
  EXPECT_NE(winding_at(r, {-0.99, 0}), 0);      // the round cap
  EXPECT_EQ(winding_at(r, {-1.01, 0}), 0);
}

TEST(StrokeRoute, SimplifiedWideRoundStrokesAtATightToleranceAnswer) {
  // Wide strokes at tolerance 1e-4 whose offset pieces meet near-tangentially (slivers thinner
  // than the region layer's ray clearance) answer at the default limits, with the round
  // stroke's region: on a grid of points, winding 1 closer than width / 2 to the curve, 0
  // farther than width / 2 + tolerance (distances by core::nearest on the one cubic).
  struct Case {
    const char* path;
    core::Curve cubic;
    double width;
  };
  const core::Curve hook({{0, 0}, {12, 0}, {12, 4}, {0, 4}});
  const core::Curve cusp({{0, 0}, {10, 10}, {0, 10}, {10, 0}});
  const Case cases[] = {{"M0 0 C12 0 12 4 0 4", hook, 2},
                        {"M0 0 C12 0 12 4 0 4", hook, 7},
                        {"M0 0 C30 0 -10 10 20 10", core::Curve({{0, 0}, {30, 0}, {-10, 10}, {20, 10}}), 7},
                        {"M0 0 C10 10 0 10 10 0", cusp, 2},
                        {"M0 0 C10 10 0 10 10 0", cusp, 7},
                        {"M0 0 C10 10 -10 10 0 0 Z", core::Curve({{0, 0}, {10, 10}, {-10, 10}, {0, 0}}), 2}};
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << c.path << " width " << c.width);
    const json r = call(std::string(R"({"path":")") + c.path + R"(","width":)" +
                            std::to_string(c.width) +
                            R"(,"join":"round","cap":"round","tolerance":1e-4,"simplify":true})",
                        200);
    EXPECT_EQ(r["simplified"], true);
    path::PathDataParse parse = path::parse_svg_path_data(r["path"].get<std::string>(), 100000);
    ASSERT_FALSE(parse.error);
    const region::Region region =
        region::region_from_path(std::move(parse.path), region::FillRule::nonzero);
    const double half = c.width / 2;
    int inside = 0, outside = 0;
    for (int i = 0; i <= 30; ++i) {
      for (int j = 0; j <= 30; ++j) {
        const core::Point2 p{-12 + 44.0 * (i + 0.37) / 31, -6 + 24.0 * (j + 0.61) / 31};
        const double d = core::nearest(c.cubic, p, 0, 1).distance;
        if (d > half - 1e-3 && d < half + 1e-3) continue;
        const std::optional<region::Winding> w = region::winding(region, p, std::int64_t{1} << 40);
        ASSERT_TRUE(w && !w->boundary);
        EXPECT_EQ(w->winding, d < half ? 1 : 0) << p.x << " " << p.y;
        ++(d < half ? inside : outside);
      }
    }
    EXPECT_GT(inside, 20);
    EXPECT_GT(outside, 20);
  }
}

TEST(StrokeRoute, SimplifiedOutlineIsTheSameRegionWithWindingOne) {
  // The ribbons of the two lines and the disks at their ends overlap (winding 2 and 3 about
  // the corner before simplify); simplified, every point inside winds once.
  const std::string body =
      R"({"path":"M0 0 L10 0 L10 10","width":2,"join":"round","cap":"round","tolerance":1e-3,"simplify":true})";
  const json r = call(body, 200);
  EXPECT_EQ(r["simplified"], true);
  EXPECT_EQ(winding_at(r, {9.9, -0.1}), 1);
  EXPECT_EQ(winding_at(r, {5, -0.99}), 1);
  EXPECT_EQ(winding_at(r, {5, -1.01}), 0);
  EXPECT_EQ(winding_at(r, {10.7, -0.7}), 1);
  EXPECT_EQ(winding_at(r, {10.72, -0.72}), 0);
  EXPECT_EQ(winding_at(r, {5, 5}), 0);
  const json plain = call(R"({"path":"M0 0 L10 0 L10 10","width":2,"join":"round","cap":"round","tolerance":1e-3})", 200);
  EXPECT_GT(winding_at(plain, {9.9, -0.1}), 1);
}

/// A grid of points: x from x0 to x1 in steps dx, y from y0 to y1 in steps dy.
struct Grid {
  double x0, x1, dx, y0, y1, dy;
};

/// Judges a simplified round stroke's answer against the distance set of `curve`: every grid
/// point off the boundary winds 0 or 1, once where it is nearer than `half` to the curve
/// (nearest-point kernel), never where it is farther than half + tolerance. Points within
/// `corner_radius` of one of `corners` (where other joins and caps than round ones draw
/// something else) are only checked to wind 0 or 1. Returns how many points were judged.
int judged_against_distance(const json& answer, const core::Curve& curve, double half,
                            double tolerance, const Grid& grid,
                            std::span<const core::Point2> corners = {},
                            double corner_radius = 0.0) {
  EXPECT_EQ(answer["simplified"], true);
  path::PathDataParse parse = path::parse_svg_path_data(answer["path"].get<std::string>(), 100000);
  EXPECT_FALSE(parse.error);
  if (parse.error) return 0;
  const region::RegionWinding winding(
      region::region_from_path(std::move(parse.path), region::FillRule::nonzero));
  int judged = 0;
  for (double x = grid.x0; x <= grid.x1; x += grid.dx) {
    for (double y = grid.y0; y <= grid.y1; y += grid.dy) {
      core::WorkBudget work(std::int64_t{1} << 40);
      const std::optional<region::Winding> w = winding.at({x, y}, work);
      EXPECT_TRUE(w);
      if (!w) return judged;
      if (w->boundary) continue;
      EXPECT_TRUE(w->winding == 0 || w->winding == 1) << x << " " << y;
      if (std::any_of(corners.begin(), corners.end(), [&](core::Point2 c) {
            return core::length(core::Point2{x, y} - c) <= corner_radius;
          })) {
        continue;
      }
      const double d = core::nearest(curve, {x, y}, 0, 1).distance;
      if (d < half - 1e-12) {
        EXPECT_EQ(w->winding, 1) << x << " " << y;
        ++judged;
      } else if (d > half + tolerance + 1e-12) {
        EXPECT_EQ(w->winding, 0) << x << " " << y;
        ++judged;
      }
    }
  }
  return judged;
}

TEST(StrokeRoute, SimplifiedRoundStrokeOfACurveIsItsDistanceSet) {
  // Every point closer than 1 to the arch winds once, every point farther than 1 + 1e-3 not
  // at all (distances from the nearest-point kernel).
  const core::Curve arch({{0, 0}, {5, 5}, {5, 5}, {10, 0}});
  const json r = call(
      R"({"points":[[0,0],[5,5],[5,5],[10,0]],"width":2,"join":"round","cap":"round","tolerance":1e-3,"simplify":true})",
      200);
  EXPECT_GT(judged_against_distance(r, arch, 1, 1e-3, {-1.5, 11.5, 0.13, -1.5, 5.5, 0.11}), 5000);
}

TEST(StrokeRoute, SimplifiedRoundStrokeOfACuspIsItsDistanceSet) {
  // B'(1/2) = 0: the pieces' normal segments at the cuts lie on common lines; simplify
  // answers, and the points judged wind once within 1 of the curve, never beyond 1 + 1e-2.
  const core::Curve cusp({{0, 0}, {10, 10}, {0, 10}, {10, 0}});
  const json r = call(
      R"({"path":"M0 0 C10 10 0 10 10 0","width":2,"tolerance":0.01,"join":"round","cap":"round","simplify":true})",
      200);
  EXPECT_GT(judged_against_distance(r, cusp, 1, 1e-2, {-1.5, 11.5, 0.17, -1.5, 9, 0.13}), 3000);
}

TEST(StrokeRoute, SimplifiedNarrowRoundStrokeOfACuspIsItsDistanceSet) {
  // Half width 0.25 about the cusped cubic: the parallel curves at ±R have cusps of their own
  // next to B's cusp at t = 1/2, where a fitted piece ends within rounding of a cusp. Every
  // point judged winds once within 0.25 of the curve, never beyond 0.25 + tolerance.
  const core::Curve cusp({{0, 0}, {10, 10}, {0, 10}, {10, 0}});
  for (const double tolerance : {1e-2, 1e-3, 1e-4}) {
    SCOPED_TRACE(testing::Message() << "tolerance " << tolerance);
    const json r = call(R"({"path":"M0 0 C10 10 0 10 10 0","width":0.5,"tolerance":)" +
                            std::to_string(tolerance) +
                            R"(,"join":"round","cap":"round","simplify":true})",
                        200);
    EXPECT_GT(judged_against_distance(r, cusp, 0.25, tolerance, {-0.5, 10.5, 0.037, -0.5, 8, 0.043}),
              20000);
  }
}

TEST(StrokeRoute, SimplifiedStrokesOfTightBendsAnswerWithinTheWorkCap) {
  // Two bends tighter than the stroke is wide, at tolerance 1e-4: the S-curve 2 wide (two
  // bends of radius of curvature below 1) and the loop closed at a right-angled corner 7 wide
  // (its whole inner side tight). At the default limits each answers, with every join and
  // cap; with round ones the answer is the distance set, and with the others it is too away
  // from the ends and the corner (farther than r √2 + tolerance from them: the reach of a
  // square cap and of the right angle's miter tip).
  struct Case {
    const char* path;
    core::Curve cubic;
    double width;
    std::vector<core::Point2> corners;
    Grid grid;
  };
  const Case cases[] = {
      {"M0 0 C30 0 -10 10 20 10", core::Curve({{0, 0}, {30, 0}, {-10, 10}, {20, 10}}), 2,
       {{0, 0}, {20, 10}}, {-1.5, 21.5, 0.11, -1.5, 11.5, 0.097}},
      {"M0 0 C10 10 -10 10 0 0 Z", core::Curve({{0, 0}, {10, 10}, {-10, 10}, {0, 0}}), 7,
       {{0, 0}}, {-7, 7, 0.093, -5, 11.5, 0.101}},
  };
  const char* styles[][2] = {{"round", "round"}, {"miter", "butt"}, {"bevel", "square"},
                             {"miter", "square"}, {"bevel", "butt"}};
  for (const Case& c : cases) {
    const double half = c.width / 2;
    for (const auto& [join, cap] : styles) {
      SCOPED_TRACE(testing::Message() << c.path << " width " << c.width << " " << join << " " << cap);
      const json r = call(std::string(R"({"path":")") + c.path + R"(","width":)" +
                              std::to_string(c.width) + R"(,"join":")" + join + R"(","cap":")" +
                              cap + R"(","tolerance":1e-4,"simplify":true})",
                          200);
      const bool round = std::string(join) == "round" && std::string(cap) == "round";
      EXPECT_GT(judged_against_distance(r, c.cubic, half, 1e-4, c.grid, c.corners,
                                        round ? 0.0 : half * std::sqrt(2.0) + 1e-4),
                10000);
    }
  }
}

TEST(StrokeRoute, CurvesThatTurnBackAlongTheirLineAnswer) {
  // Issue 31: collinear curves whose derivative vanishes where they turn back, and a cusp at
  // a tolerance of 1e-8 of its scale, answer at the default limits with every join and cap,
  // simplified or not; the simplified round stroke is the distance set (winding 1 closer than
  // width / 2 to the curve, 0 farther than width / 2 + tolerance, on a grid).
  struct Case {
    const char* path;
    core::Curve curve;
    double width, tolerance;
  };
  const Case cases[] = {
      {"M0 0 Q100 0 50 0", core::Curve({{0, 0}, {100, 0}, {50, 0}}), 4, 1e-3},
      {"M0 0 C100 0 -100 0 0 0", core::Curve({{0, 0}, {100, 0}, {-100, 0}, {0, 0}}), 4, 1e-3},
      {"M0 0 C100 0 -100 0 0 0", core::Curve({{0, 0}, {100, 0}, {-100, 0}, {0, 0}}), 4, 1e-2},
      {"M0 0 C100 0 100 0 50 0", core::Curve({{0, 0}, {100, 0}, {100, 0}, {50, 0}}), 4, 1e-3},
      {"M0 0 C100 0 -100 0 50 0", core::Curve({{0, 0}, {100, 0}, {-100, 0}, {50, 0}}), 4, 1e-3},
      {"M0 0 C10 10 0 10 10 0", core::Curve({{0, 0}, {10, 10}, {0, 10}, {10, 0}}), 2, 1e-7},
  };
  const char* styles[][2] = {{"round", "round"}, {"miter", "butt"}, {"bevel", "square"}};
  for (const Case& c : cases) {
    for (const bool simplify : {false, true}) {
      for (const auto& [join, cap] : styles) {
        SCOPED_TRACE(testing::Message() << c.path << " " << join << " " << cap << " simplify "
                                        << simplify << " tolerance " << c.tolerance);
        std::ostringstream body;
        body.precision(17);
        body << R"({"path":")" << c.path << R"(","width":)" << c.width << R"(,"tolerance":)"
             << c.tolerance << R"(,"join":")" << join << R"(","cap":")" << cap
             << R"(","simplify":)" << (simplify ? "true" : "false") << "}";
        const json r = call(body.str(), 200);
        if (!simplify || std::string(join) != "round") continue;
        const double half = c.width / 2;
        double x0 = 0, x1 = 0, y0 = 0, y1 = 0;  // the control points' box, widened by r + 1
        for (const core::Point2 q : c.curve.points()) {
          x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
        }
        x0 -= half + 1, x1 += half + 1, y0 -= half + 1, y1 += half + 1;
        int inside = 0, outside = 0;
        for (int i = 0; i <= 40; ++i) {
          for (int j = 0; j <= 12; ++j) {
            const core::Point2 p{x0 + (x1 - x0) * (i + 0.37) / 41, y0 + (y1 - y0) * (j + 0.61) / 13};
            const double d = core::nearest(c.curve, p, 0, 1).distance;
            if (d > half - 1e-3 && d < half + 2e-3) continue;
            EXPECT_EQ(winding_at(r, p), d < half ? 1 : 0) << p.x << " " << p.y;
            ++(d < half ? inside : outside);
          }
        }
        EXPECT_GT(inside, 20);
        EXPECT_GT(outside, 20);
      }
    }
  }
}

TEST(StrokeRoute, TakesControlPointsToo) {
  const json r = call(R"({"points":[[0,0],[4,0]],"width":1,"tolerance":1e-6})", 200);
  EXPECT_NE(winding_at(r, {2, 0.49}), 0);
  EXPECT_EQ(winding_at(r, {2, 0.51}), 0);
  EXPECT_EQ(winding_at(r, {-0.01, 0}), 0);  // butt caps by default
}

TEST(StrokeRoute, ValidationPointers) {
  const std::string path = R"("path":"M0 0 L10 0",)";
  EXPECT_EQ(test::error_pointers(call("{" + path + R"("width":0,"tolerance":1e-3})", 422)),
            std::vector<std::string>{"/width"});
  EXPECT_EQ(test::error_pointers(call("{" + path + R"("tolerance":1e-3})", 422)),
            std::vector<std::string>{"/width"});
  EXPECT_EQ(test::error_pointers(call("{" + path + R"("width":1,"tolerance":1e-12})", 422)),
            std::vector<std::string>{"/tolerance"});
  EXPECT_EQ(test::error_pointers(call("{" + path + R"("width":1,"tolerance":1e-3,"miter_limit":0.5})", 422)),
            std::vector<std::string>{"/miter_limit"});
  EXPECT_EQ(test::error_pointers(call("{" + path + R"("width":1,"tolerance":1e-3,"simplify":"yes"})", 422)),
            std::vector<std::string>{"/simplify"});
  EXPECT_EQ(test::error_pointers(call("{" + path + R"("width":1,"tolerance":1e-3,"distance":1})", 422)),
            std::vector<std::string>{"/distance"});
  EXPECT_EQ(test::error_pointers(call(R"({"width":1,"tolerance":1e-3})", 422)),
            std::vector<std::string>{"/points"});
  const json join = call("{" + path + R"("width":1,"tolerance":1e-3,"join":"rond"})", 422);
  EXPECT_EQ(test::error_pointers(join), std::vector<std::string>{"/join"});
  EXPECT_NE(join.dump().find("did you mean `round`?"), std::string::npos);
  const json cap = call("{" + path + R"("width":1,"tolerance":1e-3,"cap":"sqare"})", 422);
  EXPECT_EQ(test::error_pointers(cap), std::vector<std::string>{"/cap"});
  EXPECT_NE(cap.dump().find("did you mean `square`?"), std::string::npos);
}

TEST(StrokeRoute, TooManySegmentsAndWorkCap) {
  Limits small;
  small.max_path_segments = 6;
  EXPECT_EQ(test::error_pointers(call(
                R"({"path":"M0 0 L10 0 L10 10","width":2,"join":"round","tolerance":1e-6})", 422,
                small)),
            std::vector<std::string>{"/tolerance"});
  Limits tight;
  tight.max_work = 1000;
  const json problem = call(
      R"({"path":"M0 0 C10 10 0 10 10 0","width":2,"join":"round","tolerance":1e-6})", 422, tight);
  EXPECT_NE(problem["detail"].get<std::string>().find("work cap"), std::string::npos);
}

}  // namespace
}  // namespace bezier::api
