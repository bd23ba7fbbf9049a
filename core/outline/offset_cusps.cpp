#include "core/outline/offset_cusps.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "core/bernstein/roots.hpp"
#include "core/numeric/binomial.hpp"
#include "core/numeric/power_of_two.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

/// The hodograph's control points n (P_{i+1} - P_i).
std::vector<Point2> hodograph(const std::vector<Point2>& p) {
  const double n = static_cast<double>(p.size() - 1);
  std::vector<Point2> h;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) h.push_back(n * (p[i + 1] - p[i]));
  return h;
}

/// The Bernstein coefficients of the product of two polynomials given by theirs, with the
/// pair's product f(a_i, b_j) (cross, dot or a plain product).
template <class A, class B, class F>
std::vector<double> product(const std::vector<A>& a, const std::vector<B>& b, F f) {
  const int m = static_cast<int>(a.size()) - 1, k = static_cast<int>(b.size()) - 1;
  std::vector<double> r(static_cast<std::size_t>(m + k + 1), 0.0);
  for (int i = 0; i <= m; ++i) {
    for (int j = 0; j <= k; ++j) {
      const double weight =
          core::binomial(m, i) * core::binomial(k, j) / core::binomial(m + k, i + j);
      r[static_cast<std::size_t>(i + j)] +=
          weight * f(a[static_cast<std::size_t>(i)], b[static_cast<std::size_t>(j)]);
    }
  }
  return r;
}

std::vector<double> times(const std::vector<double>& a, const std::vector<double>& b) {
  return product(a, b, [](double x, double y) { return x * y; });
}

double evaluate(std::vector<double> c, double t) {
  for (std::size_t k = c.size() - 1; k > 0; --k)
    for (std::size_t i = 0; i < k; ++i) c[i] = (1.0 - t) * c[i] + t * c[i + 1];
  return c.front();
}

}  // namespace

std::vector<double> offset_cusps(const core::Curve& curve, double d) {
  const int n = curve.degree();
  if (n < 2 || d == 0.0) return {};  // a line, or the curve itself: no cusps
  // Scale by a power of two so that the largest coordinate is about 1.
  const double scale = core::scale(curve);
  if (scale == 0.0) return {};  // a point
  const int e = -core::exponent_of(scale);
  const std::vector<Point2> p = core::scaled_by_power_of_two(curve.points(), e);
  const double scaled_d = core::PowerOfTwo(e).times(d);

  const std::vector<Point2> first = hodograph(p);
  const std::vector<Point2> second = hodograph(first);
  const std::vector<double> c =
      product(first, second, [](Point2 a, Point2 b) { return core::cross(a, b); });
  const std::vector<double> s =
      product(first, first, [](Point2 a, Point2 b) { return core::dot(a, b); });
  // d^2 c^2, raised from degree 4n - 6 to 6n - 6 by the product with 1 (all coefficients 1).
  std::vector<double> squared = times(c, c);
  for (double& x : squared) x *= scaled_d * scaled_d;
  const std::vector<double> raised =
      times(squared, std::vector<double>(static_cast<std::size_t>(2 * n + 1), 1.0));
  const std::vector<double> cubed = times(times(s, s), s);
  std::vector<double> poly(raised.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    poly[i] = raised[i] - cubed[i];
    largest = std::max({largest, std::fabs(raised[i]), std::fabs(cubed[i])});
  }
  if (largest == 0.0) return {};

  std::vector<double> cusps;
  for (const double t : core::bernstein_roots(poly).roots) {
    const double st = evaluate(s, t);
    if (!(st * st * st > 1e-12 * largest)) continue;  // B' = 0: a cusp of B, not of O
    if (scaled_d * evaluate(c, t) > 0.0) cusps.push_back(t);
  }
  return cusps;
}

}  // namespace bezier::outline
