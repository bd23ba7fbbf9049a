#include "core/outline/tight_side_cover.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/curve/evaluate.hpp"
#include "core/curve/polar.hpp"
#include "core/measure/bernstein_product.hpp"
#include "core/numeric/power_of_two.hpp"
#include "core/outline/stroke_shapes.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

constexpr int kMostHalvings = 64;
/// The unit roundoff u.
constexpr double kUnit = std::numeric_limits<double>::epsilon() / 2.0;

std::vector<Point2> hodograph(std::span<const Point2> p) {
  const double n = static_cast<double>(p.size() - 1);
  std::vector<Point2> h;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) h.push_back(n * (p[i + 1] - p[i]));
  return h;
}

double largest_length(std::span<const Point2> p) {
  double m = 0.0;
  for (const Point2 q : p) m = std::max(m, core::length(q));
  return m;
}

/// The hull test's upper bound of the radius of curvature on the curve q where it turns to
/// `side` (+1 left, -1 right) throughout: M1^3 / min(side cross(B', B'')), the minimum over
/// the Bernstein coefficients of cross(B', B'') (degree 2n - 3, products of the first and
/// second hodographs' control points). Infinity when a coefficient is not of the side's sign.
/// The radius scales with the curve, so it is computed for the curve scaled by 2^-e (e the
/// exponent of the first hodograph's largest coordinate; exact) and scaled back: on q itself
/// M1^3 underflows for coordinates near 1e-109 (a bound of 0 would accept every part) and
/// overflows above about 1e+102. Infinity where the radius scaled back is not a normal double.
double radius_of_curvature_bound(std::span<const Point2> q, double side) {
  std::vector<Point2> h1 = hodograph(q);
  if (h1.size() < 2) return std::numeric_limits<double>::infinity();
  double largest_coordinate = 0.0;
  for (const Point2 p : h1)
    largest_coordinate = std::max(largest_coordinate, core::max_abs_coordinate(p));
  if (!(largest_coordinate > 0.0)) return std::numeric_limits<double>::infinity();
  const int e = core::exponent_of(largest_coordinate);
  const core::PowerOfTwo down(-e);
  for (Point2& p : h1) p = down.times(p);
  const std::vector<Point2> h2 = hodograph(h1);
  const int m = static_cast<int>(h1.size()) - 1, k = static_cast<int>(h2.size()) - 1;
  std::vector<double> c(static_cast<std::size_t>(m + k + 1), 0.0);
  for (int i = 0; i <= m; ++i) {
    for (int j = 0; j <= k; ++j) {
      const double weight = core::choose(m, i) * core::choose(k, j) / core::choose(m + k, i + j);
      c[static_cast<std::size_t>(i + j)] +=
          weight * core::cross(h1[static_cast<std::size_t>(i)], h2[static_cast<std::size_t>(j)]);
    }
  }
  double least = std::numeric_limits<double>::infinity();
  for (const double v : c) least = std::min(least, side * v);
  // Rounding of the coefficients: each is a sum of (m + 1)(k + 1) products, within
  // 4 (m + k + 2) u of the sum of their magnitudes.
  double magnitude = 0.0;
  for (const Point2 a : h1)
    for (const Point2 b : h2) magnitude = std::max(magnitude, core::length(a) * core::length(b));
  least -= 4.0 * (m + k + 2) * std::numeric_limits<double>::epsilon() * magnitude;
  if (!(least > 0.0)) return std::numeric_limits<double>::infinity();
  const double speed = largest_length(h1);
  const double radius = core::PowerOfTwo(e).times(speed * speed * speed / least);
  return radius >= std::numeric_limits<double>::min() ? radius
                                                       : std::numeric_limits<double>::infinity();
}

/// A scalar polynomial in Bernstein form and a bound of each coefficient's distance from the
/// exact polynomial's (its rounding, and what the control points' own errors make of it).
struct Bounded {
  std::vector<double> c;
  double error = 0.0;

  [[nodiscard]] double magnitude() const {
    double m = 0.0;
    for (const double v : c) m = std::max(m, std::fabs(v));
    return m;
  }
  /// +1 or -1 when every coefficient is beyond its error on that side, else 0.
  [[nodiscard]] int sign() const {
    const bool positive = std::all_of(c.begin(), c.end(), [&](double v) { return v > error; });
    const bool negative = std::all_of(c.begin(), c.end(), [&](double v) { return v < -error; });
    return positive ? 1 : negative ? -1 : 0;
  }
};

/// The product of two Bernstein polynomials (Farouki & Rajan 1988: b_{i,m} b_{j,k} =
/// C(m,i) C(k,j) / C(m+k,i+j) b_{i+j,m+k}). Each coefficient is a convex combination of at
/// most min(m, k) + 1 products f_i g_j: its rounding is within (m + k + 4) u F G (F, G the
/// largest magnitudes, the inputs' errors included), and the inputs' errors move it by at most
/// F e_g + e_f G + e_f e_g.
Bounded product(const Bounded& f, const Bounded& g) {
  const int m = static_cast<int>(f.c.size()) - 1, k = static_cast<int>(g.c.size()) - 1;
  Bounded out;
  out.c.assign(static_cast<std::size_t>(m + k + 1), 0.0);
  for (int i = 0; i <= m; ++i) {
    const double ci = core::choose(m, i);
    for (int j = 0; j <= k; ++j) {
      out.c[static_cast<std::size_t>(i + j)] += core::product_weight(m, k, i, j, ci) *
                                                 f.c[static_cast<std::size_t>(i)] *
                                                 g.c[static_cast<std::size_t>(j)];
    }
  }
  const double fm = f.magnitude(), gm = g.magnitude();
  out.error = fm * g.error + f.error * gm + f.error * g.error +
              (m + k + 4) * kUnit * (fm + f.error) * (gm + g.error);
  return out;
}

/// The Bernstein coefficients of a(t) ∘ b(t) for vector polynomials a, b (control points
/// within e_a, e_b of the exact ones), ∘ the cross or the dot product: as product(), each
/// term within 3 u |a_i| |b_j| of its exact value and moved by at most |a| e_b + e_a |b| +
/// e_a e_b by the inputs' errors.
template <class Op>
Bounded pair_polynomial(std::span<const Point2> a, double error_a, std::span<const Point2> b,
                        double error_b, Op op) {
  const int m = static_cast<int>(a.size()) - 1, k = static_cast<int>(b.size()) - 1;
  Bounded out;
  out.c.assign(static_cast<std::size_t>(m + k + 1), 0.0);
  for (int i = 0; i <= m; ++i) {
    const double ci = core::choose(m, i);
    for (int j = 0; j <= k; ++j) {
      out.c[static_cast<std::size_t>(i + j)] +=
          core::product_weight(m, k, i, j, ci) *
          op(a[static_cast<std::size_t>(i)], b[static_cast<std::size_t>(j)]);
    }
  }
  const double am = largest_length(a), bm = largest_length(b);
  out.error = am * error_b + error_a * bm + error_a * error_b +
              (m + k + 7) * kUnit * (am + error_a) * (bm + error_b);
  return out;
}

/// p'(t) in Bernstein form: d (c_{i+1} - c_i), each within 2 d e + 4 d u max|c| of the exact.
Bounded derivative(const Bounded& p) {
  Bounded out;
  const core::Coeffs d_coeffs = core::bernstein_derivative(p.c);
  out.c.assign(d_coeffs.begin(), d_coeffs.end());
  const double d = static_cast<double>(p.c.size() - 1);
  out.error = 2.0 * d * p.error + 4.0 * d * kUnit * (p.magnitude() + p.error);
  return out;
}

}  // namespace

bool tangent_disk_holds(std::span<const Point2> piece, Point2 centre, double point_error,
                        double centre_error, double margin, double side,
                        const CoverSizes& sizes) {
  const std::size_t n = piece.size() - 1;
  if (n < 2) return false;
  // The curvature certificates on the part scaled by a power of two (exact), so that the
  // cubes of speeds neither overflow nor underflow.
  double size = sizes.reach;
  for (const Point2 p : piece) size = std::max(size, core::max_abs_coordinate(p));
  const int exponent = -core::exponent_of(size);
  const core::PowerOfTwo factor(exponent);
  std::vector<Point2> scaled;
  scaled.reserve(piece.size());
  for (const Point2 p : piece) scaled.push_back(factor.times(p));
  const double e0 = factor.times(point_error);
  const std::vector<Point2> h1 = hodograph(scaled);
  const std::vector<Point2> h2 = hodograph(h1);
  const double m1 = largest_length(h1), m2 = largest_length(h2);
  const auto degree = static_cast<double>(n);
  // The hodographs' errors: differences of points within e0 (times the degree), and their
  // own rounding.
  const double e1 = 2.0 * degree * e0 + 3.0 * kUnit * m1;
  const double e2 = 2.0 * (degree - 1.0) * e1 + 3.0 * kUnit * m2;

  // The quarter turn: every h_i within 44 degrees of d, the mean of the end directions.
  const double first = core::length(h1.front()), last = core::length(h1.back());
  if (!(first > e1) || !(last > e1)) return false;
  Point2 d = h1.front() / first + h1.back() / last;
  const double d_length = core::length(d);
  if (!(d_length > 0.5)) return false;
  d = d / d_length;
  for (const Point2 h : h1) {
    if (!(core::dot(d, h) > 0.72 * (core::length(h) + e1) + 1.01 * e1)) return false;
  }

  // X = side · cross(B', B'') > 0 throughout; the hull bound of ρ.
  Bounded x = pair_polynomial(h1, e1, h2, e2, [&](Point2 a, Point2 b) {
    return side * core::cross(a, b);
  });
  if (x.sign() != 1) return false;
  const double least = *std::min_element(x.c.begin(), x.c.end()) - x.error;
  const double rounding = 1.0 + 16.0 * kUnit;
  const auto cube = [](double v) { return v * v * v; };
  double rho = cube(m1 + e1) / least * rounding;
  // Where ρ is monotone on the part, the larger of its ends' values.
  const Bounded y_first =
      product(pair_polynomial(h1, e1, h2, e2, [](Point2 a, Point2 b) { return core::dot(a, b); }),
              x);
  const Bounded y_second = product(
      pair_polynomial(h1, e1, h1, e1, [](Point2 a, Point2 b) { return core::dot(a, b); }),
      derivative(x));
  Bounded y;
  y.c.resize(y_first.c.size());
  for (std::size_t i = 0; i < y.c.size(); ++i) y.c[i] = 3.0 * y_first.c[i] - y_second.c[i];
  y.error = 3.0 * y_first.error + y_second.error +
            3.0 * kUnit * (3.0 * y_first.magnitude() + y_second.magnitude());
  if (y.sign() != 0) {
    const double at_start = cube(first + e1) / (x.c.front() - x.error) * rounding;
    const double at_end = cube(last + e1) / (x.c.back() - x.error) * rounding;
    rho = std::min(rho, std::max(at_start, at_end));
  }
  if (!(rho < std::numeric_limits<double>::infinity())) return false;
  rho = std::ldexp(rho, -exponent);

  // The distance bound, in the piece's own units.
  double spread = 0.0;
  for (const Point2 p : piece) spread = std::max(spread, core::length(p - centre));
  const double l = spread * (1.0 + 2.0 * kUnit) + point_error + centre_error;
  const double depth = std::min(rho, sizes.radius);
  const double l2 = l * l;
  const double far = l2 * std::max(0.0, 1.0 - depth / rho) + depth * depth;
  const double bound = std::sqrt(std::max(l2, far)) * (1.0 + 4.0 * kUnit);
  return bound + centre_error + margin < sizes.reach;
}

void cover_tight_side(const core::Curve& segment, double c0, double c1, double side,
                      const CoverSizes& sizes, OutlineSink& sink, std::vector<Point2>& centres) {
  struct Part {
    double a, b;
    int depth;
  };
  const core::Curve q = core::portion(segment, c0, c1);
  const auto n = static_cast<std::int64_t>(q.degree());
  const double margin = 64.0 * std::numeric_limits<double>::epsilon() *
                        (core::scale(q) + sizes.reach);
  // How far the parts' computed control points may be from the exact ones (two portions by
  // blossoms, each within a few roundings of the segment's scale), and the centres from the
  // exact parts' middle points.
  const double point_error = 16.0 * static_cast<double>(n) * kUnit * core::scale(segment);
  const double centre_error = point_error + 4.0 * kUnit * core::scale(segment);
  std::vector<Part> stack{{0.0, 1.0, 0}};
  while (!stack.empty()) {
    const Part part = stack.back();
    stack.pop_back();
    if (!sink.charge(16 * (n + 1) * (n + 1))) return;
    const core::Curve piece = core::portion(q, part.a, part.b);
    const Point2 centre = core::evaluate(piece, 0.5);
    const double depth =
        std::min(radius_of_curvature_bound(piece.points(), side), sizes.radius) + margin;
    auto hull_holds = [&](Point2 c) {
      double spread = 0.0;
      for (const Point2 p : piece.points()) spread = std::max(spread, core::length(p - c));
      return depth + spread < sizes.reach;
    };
    if (!sink.charge(static_cast<std::int64_t>(centres.size()) * (n + 1))) return;
    if (std::any_of(centres.begin(), centres.end(), hull_holds)) continue;
    bool holds = hull_holds(centre);
    if (!holds) {
      // The tangent-disk test: products of degree up to 4n - 6.
      if (!sink.charge(64 * (n + 1) * (n + 1))) return;
      holds = tangent_disk_holds(piece.points(), centre, point_error, centre_error, margin, side,
                                 sizes);
    }
    if (holds) {
      if (!sink.charge(16 * static_cast<std::int64_t>(sizes.circle_pieces))) return;
      sink.add(circle(centre, sizes.disk_radius, sizes.circle_pieces));
      centres.push_back(centre);
      continue;
    }
    if (part.depth >= kMostHalvings) {
      sink.fail_work();
      return;
    }
    const double mid = 0.5 * (part.a + part.b);
    stack.push_back({mid, part.b, part.depth + 1});
    stack.push_back({part.a, mid, part.depth + 1});
  }
}

}  // namespace bezier::outline
