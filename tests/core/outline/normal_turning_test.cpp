// Tests of core/outline/normal_turning.hpp: the bound of |d N''| from the hulls of a piece's
// direction field and its hodographs.
//
// Independent check: |N''| = sqrt(ω'^2 + ω^4) from the exact derivatives of the curve
// (derivatives_at), at dense parameters of random pieces of random cubics and quintics, is
// within the bound computed from the piece's control points; where the piece holds a zero of
// B', no positive least projection exists (the bound's precondition fails, so it is not used).

#include "core/outline/normal_turning.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/curve/derivative.hpp"
#include "core/outline/control_points.hpp"
#include "tests/support/mulberry32.hpp"

namespace bezier::outline {
namespace {

using core::Curve;
using core::Point2;

/// The least projection of the points on the unit direction of their curve at 1/2.
double least_projection_of(const ControlPoints& g) {
  const Point2 mid = point_at(g, 0.5);
  const double length = std::sqrt(squared_length(mid));
  double least = std::numeric_limits<double>::infinity();
  for (const Point2 p : g) least = std::min(least, core::dot(p, mid / length));
  return least;
}

double largest_length(const ControlPoints& g) { return std::sqrt(largest_squared_length(g)); }

/// |N''(u)| of the piece [a, b] at its parameter u, from the curve's exact derivatives:
/// Q = L B', Q' = L^2 B'', Q'' = L^3 B''' (L = b - a).
double normal_second_at(const Curve& curve, double a, double b, double u) {
  const double length = b - a;
  const auto k = core::derivatives_at(curve, a + length * u, 3);
  const Point2 q = length * k[0], q1 = (length * length) * k[1],
               q2 = (length * length * length) * k[2];
  const double s = squared_length(q);
  const double omega = core::cross(q, q1) / s;
  const double omega1 = core::cross(q, q2) / s - 2.0 * core::cross(q, q1) * core::dot(q, q1) / (s * s);
  return std::sqrt(omega1 * omega1 + omega * omega * omega * omega);
}

TEST(NormalTurning, BoundHoldsOnRandomPieces) {
  test::Mulberry32 rng(77);
  int checked = 0;
  double closest = 0.0;  // the largest sampled share of the bound
  for (int trial = 0; trial < 600; ++trial) {
    const int n = trial % 3 == 2 ? 5 : 3;
    std::vector<Point2> p;
    for (int k = 0; k <= n; ++k) p.push_back({rng.uniform(-1, 1), rng.uniform(-1, 1)});
    const Curve curve(p);
    double a = rng.uniform(0, 1), b = rng.uniform(0, 1);
    if (a > b) std::swap(a, b);
    if (!(b - a > 1e-3)) continue;
    ControlPoints h1, piece, q1, q2;
    hodograph_into(curve.points(), h1);
    piece_into(h1, a, b, piece);
    for (Point2& v : piece) v = (b - a) * v;  // Q = d/du of the piece: L B'
    hodograph_into(piece, q1);
    hodograph_into(q1, q2);
    const double w = least_projection_of(piece);
    if (!(w > 0.0)) continue;
    const double d = rng.uniform(-0.5, 0.5);
    const double bound = normal_second_bound(largest_length(q1), largest_length(q2), w, d);
    for (int j = 0; j <= 200; ++j) {
      const double value = std::fabs(d) * normal_second_at(curve, a, b, j / 200.0);
      EXPECT_LE(value, bound * (1 + 1e-9)) << trial << " u " << j / 200.0;
      closest = std::max(closest, value / bound);
    }
    ++checked;
  }
  EXPECT_GT(checked, 200);
  // Not vacuous: on some piece the sampled |d N''| passes half of the bound.
  EXPECT_GT(closest, 0.5);
}

TEST(NormalTurning, PieceHoldingAZeroOfTheDerivativeHasNoPositiveProjection) {
  // B'(1/2) = 0: B' has the control points (3, 3), (-3, 0), (3, -3).
  const Curve cusped({{0, 0}, {1, 1}, {0, 1}, {1, 0}});
  ControlPoints h1, piece;
  hodograph_into(cusped.points(), h1);
  for (const auto& [a, b] : {std::pair{0.0, 1.0}, std::pair{0.4, 0.6}, std::pair{0.25, 0.5}}) {
    piece_into(h1, a, b, piece);
    const Point2 mid = point_at(piece, 0.5);
    if (!(squared_length(mid) > 0.0)) continue;  // no direction at all: not used either
    EXPECT_FALSE(least_projection_of(piece) > 0.0) << a << " " << b;
  }
}

}  // namespace
}  // namespace bezier::outline
