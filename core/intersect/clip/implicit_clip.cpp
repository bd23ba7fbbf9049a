#include "core/intersect/clip/implicit_clip.hpp"

#include <algorithm>
#include <cmath>

#include "core/numeric/binomial.hpp"
#include "core/bernstein/bernstein1d.hpp"
#include "core/numeric/min_max.hpp"
#include "core/numeric/unit_roundoff.hpp"
#include "core/intersect/tuning.hpp"

namespace bezier::core {

namespace {

struct Parabola {
  Point2 q[3];
  double delta = 0.0;  ///< |other(u) - Q(u)| <= delta for every u, exact pieces included
};

Parabola fit_parabola(const Piece& g, const FatCurveOperator& op2) {
  Parabola out;
  const int m = g.degree();
  const double root2 = std::sqrt(2.0) * (1 + kUnitRoundoff);
  if (m == 2) {
    for (int i = 0; i < 3; ++i)
      out.q[i] = {g.x[static_cast<std::size_t>(i)], g.y[static_cast<std::size_t>(i)]};
    out.delta = root2 * g.error;
    return out;
  }
  const FatCurve fx = fat_curve(op2, g.x), fy = fat_curve(op2, g.y);
  for (int i = 0; i < 3; ++i)
    out.q[i] = {fx.p[static_cast<std::size_t>(i)], fy.p[static_cast<std::size_t>(i)]};
  // Per coordinate, the difference of the Bernstein polynomials is bounded by delta_x,
  // delta_y (fat_curve includes the rounding of the elevation).
  out.delta = std::sqrt(fx.delta * fx.delta + fy.delta * fy.delta) * (1 + 4 * kUnitRoundoff) + root2 * g.error;
  return out;
}

/// Bernstein coefficients of the product of two degree-n polynomials (degree 2n).
Coeffs product(const Coeffs& a, const Coeffs& b) {
  const int n = static_cast<int>(a.size()) - 1;
  Coeffs out(static_cast<std::size_t>(2 * n + 1), 0.0);
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      out[static_cast<std::size_t>(i + j)] += binomial(n, i) * binomial(n, j) *
                                              a[static_cast<std::size_t>(i)] *
                                              b[static_cast<std::size_t>(j)];
    }
  }
  for (int k = 0; k <= 2 * n; ++k) out[static_cast<std::size_t>(k)] /= binomial(2 * n, k);
  return out;
}

}  // namespace

Clip implicit_clip(const Piece& x, const Piece& other, const FatCurveOperator& op2) {
  const Clip no_information{ParamInterval{0.0, 1.0}, false, false};
  if (other.degree() < 2) return no_information;
  const Parabola par = fit_parabola(other, op2);
  const Point2 q0 = par.q[0], q1 = par.q[1], q2 = par.q[2];
  const double area = cross(q1 - q0, q2 - q0);  // D, twice the signed area
  // Working-frame coordinates (|x| <= ~1): the squares neither overflow nor underflow
  // harmfully, so sqrt(dot) replaces hypot.
  const auto norm = [](Point2 v) { return std::sqrt(dot(v, v)) * (1 + 4 * kUnitRoundoff); };
  const double l0 = norm(q2 - q1), l1 = norm(q2 - q0), l2 = norm(q1 - q0);  // |grad D_i|
  if (!(std::fabs(area) > intersect_tuning::kStraightParabolaUlps * kUnitRoundoff *
                              max2(l0, max2(l1, l2)) *
                              max2(l0, max2(l1, l2)))) {
    return no_information;  // Q is (nearly) straight: its implicit form degenerates
  }
  const std::size_t n1 = x.x.size();
  Coeffs d0(n1), d1(n1), d2(n1);
  double reach = 0.0, big = 0.0;
  for (std::size_t k = 0; k < n1; ++k) {
    const Point2 p = {x.x[k], x.y[k]};
    d0[k] = cross(q1 - p, q2 - p);
    d1[k] = cross(q2 - p, q0 - p);
    d2[k] = cross(q0 - p, q1 - p);
    for (const Point2 q : par.q) reach = max2(reach, norm(q - p));
    big = max2(
        big,
        max2(std::fabs(d0[k]), max2(std::fabs(d1[k]), std::fabs(d2[k]))));
  }
  // Each D_i at a control point: x's error moves the point by sqrt(2) x.error along a
  // gradient of length <= max l_i; the two differences, two products and the difference of
  // the cross product round with relative error <= 4 u of |a| |b| <= reach^2.
  const double l_max = max2(l0, max2(l1, l2));
  const double e = l_max * std::sqrt(2.0) * x.error * (1 + kUnitRoundoff) + 5 * kUnitRoundoff * reach * reach;
  const Coeffs sq = product(d1, d1), pr = product(d0, d2);
  Coeffs j(sq.size());
  for (std::size_t k = 0; k < j.size(); ++k) j[k] = sq[k] - 4 * pr[k];
  const int n = static_cast<int>(n1) - 1;
  const double a = big + e;
  // |J_exact - J| <= 10 a e + 5 e^2 (perturbed products) plus the rounding of the product
  // formula (weights exact to one rounding, n + 4 roundings per sum) on 5 a^2.
  const double e_j = 10 * a * e + 5 * e * e + (2 * n + 8) * kUnitRoundoff * 5 * a * a;
  // Points of `other`: |I| <= |D| Gamma delta + ||H|| delta^2 / 2.
  const double gamma = 2 * l1 + 4 * l0 + 4 * l2;
  const double hessian = 2 * l1 * l1 + 8 * l0 * l2;
  const auto band_of = [&](double delta) {
    return (std::fabs(area) * gamma * delta + 0.5 * hessian * delta * delta) * (1 + 16 * kUnitRoundoff);
  };
  const double beta = band_of(par.delta);
  const double band = beta + e_j;
  // What of the band is rounding: the pieces' error bounds (inside delta) and e_j.
  const double noise = e_j + band_of(std::sqrt(2.0) * (x.error + other.error));
  const auto [lo, hi] = std::minmax_element(j.begin(), j.end());
  Clip out;
  out.kept = bernstein::hull_clip(j, -band, band);
  out.noisy = 4 * noise > (*hi - *lo) + 2 * beta;
  return out;
}

}  // namespace bezier::core
