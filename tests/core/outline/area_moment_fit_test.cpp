// Tests of core/outline/area_moment_fit.hpp: the cubics with given end tangents, area and
// moment.
//
// Independent check: the area ∫ y dx and moment ∫ x y dx of a cubic in the chord frame are
// integrated here by the composite Simpson rule on 4000 intervals (the integrands are
// polynomials of degree 5 and 8: the rule's error is below 1e-14 here), not from the
// closed form the kernel expands. A cubic built from known handles must be among the
// candidates for its own area and moment, and every candidate must reproduce them.

#include "core/outline/area_moment_fit.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "tests/support/mulberry32.hpp"

namespace bezier::outline {
namespace {

using core::Point2;

struct AreaMoment {
  double area = 0.0, moment = 0.0;
};

/// The cubic (0, 0), a t0, (1, 0) - b t3, (1, 0) and its area and moment by Simpson's rule.
AreaMoment area_moment_of(Point2 t0, Point2 t3, double a, double b) {
  const std::array<Point2, 4> p{Point2{0, 0}, a * t0, Point2{1, 0} - b * t3, Point2{1, 0}};
  const int intervals = 4000;
  AreaMoment sum;
  for (int j = 0; j <= intervals; ++j) {
    const double u = static_cast<double>(j) / intervals, v = 1.0 - u;
    const Point2 at = (v * v * v) * p[0] + (3.0 * u * v * v) * p[1] + (3.0 * u * u * v) * p[2] +
                      (u * u * u) * p[3];
    const Point2 d = (3.0 * v * v) * (p[1] - p[0]) + (6.0 * u * v) * (p[2] - p[1]) +
                     (3.0 * u * u) * (p[3] - p[2]);
    const double weight = (j == 0 || j == intervals) ? 1.0 : (j % 2 == 1 ? 4.0 : 2.0);
    sum.area += weight * at.y * d.x;
    sum.moment += weight * at.x * at.y * d.x;
  }
  sum.area /= 3.0 * intervals;
  sum.moment /= 3.0 * intervals;
  return sum;
}

Point2 unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

TEST(AreaMomentFit, FindsTheHandlesOfACubicFromItsAreaAndMoment) {
  test::Mulberry32 rng(31);
  int found = 0;
  const int cases = 400;
  for (int i = 0; i < cases; ++i) {
    const Point2 t0 = unit(rng.uniform(-1.0, 1.0)), t3 = unit(rng.uniform(-1.0, 1.0));
    const double a = rng.uniform(0.05, 1.2), b = rng.uniform(0.05, 1.2);
    const AreaMoment target = area_moment_of(t0, t3, a, b);
    const HandleCandidates candidates = area_moment_handles(t0, t3, target.area, target.moment);
    bool has_it = false;
    for (std::size_t k = 0; k < candidates.count; ++k) {
      const HandleLengths h = candidates.pairs[k];
      EXPECT_GE(h.start, 0.0);
      EXPECT_GE(h.end, 0.0);
      const AreaMoment got = area_moment_of(t0, t3, h.start, h.end);
      EXPECT_NEAR(got.area, target.area, 1e-9) << i;
      // The near roots (area_moment_fit.hpp) match the moment only nearly.
      if (std::fabs(got.moment - target.moment) <= 1e-9 &&
          std::fabs(h.start - a) + std::fabs(h.end - b) <= 1e-6)
        has_it = true;
    }
    found += has_it ? 1 : 0;
  }
  // Every cubic is found but where its root is double or nearly so (two candidates that
  // the search takes as one): a few of the cases at most.
  EXPECT_GE(found, cases - cases / 50);
}

TEST(AreaMomentFit, ArcStartedHandlesReproduceTheAreaAndMoment) {
  // A circular arc through (0, 0) and (1, 0) turning by φ (tangents at ±φ / 2): its cubic
  // is symmetric (the problem is symmetric under the reflection x -> 1 - x, which swaps the
  // two handles), and its area and moment are the arc's.
  for (const double phi : {0.2, 0.8, 1.5, 2.5}) {
    const double r = 0.5 / std::sin(phi / 2.0);
    // The arc's area above the chord: the circular segment of radius r and angle φ, and its
    // moment about x = 0 is its area times 1/2 by symmetry.
    const double area = 0.5 * r * r * (phi - std::sin(phi));
    const double moment = 0.5 * area;
    HandleLengths handles;
    ASSERT_TRUE(arc_started_handles(unit(phi / 2.0), unit(-phi / 2.0), area, moment, handles))
        << phi;
    EXPECT_NEAR(handles.start, handles.end, 1e-9) << phi;
    const AreaMoment got =
        area_moment_of(unit(phi / 2.0), unit(-phi / 2.0), handles.start, handles.end);
    EXPECT_NEAR(got.area, area, 1e-12) << phi;
    EXPECT_NEAR(got.moment, moment, 1e-12) << phi;
  }
}

}  // namespace
}  // namespace bezier::outline
