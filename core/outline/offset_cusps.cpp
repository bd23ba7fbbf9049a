#include "core/outline/offset_cusps.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

#include "core/bernstein/bernstein1d.hpp"
#include "core/bernstein/roots.hpp"
#include "core/measure/bernstein_product.hpp"
#include "core/numeric/binomial.hpp"
#include "core/numeric/power_of_two.hpp"
#include "core/outline/control_points.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

// A root of p where |B'|^3 is below this share of p's largest coefficient is not told apart
// from a zero of B' (a cusp of B itself, where p vanishes too) at this piece's rounding.
constexpr double kStationaryShare = 1e-12;
// Pieces that hold such a root are halved, each half's p built from the hodographs' own
// piece there (whose coefficients are those of B' and B'' on the half, with the rounding of
// the whole curve's), until the root is told apart or the piece is 2^-kCuspDepth wide.
constexpr int kCuspDepth = 48;
// ... but not where |B'| stays below this share of its largest on the curve (the hodograph's
// control points of the piece all that short): a near-cusp of B, whose parallel curves turn
// by a half turn within a stretch of t where B itself hardly moves.
constexpr double kNearCuspSpeed = 0x1p-20;
// Newton steps on the unsquared condition for each cusp found (polished below).
constexpr int kPolishSteps = 8;
// Cusps closer than this in t are one (found on both sides of a split point).
constexpr double kSameCusp = 0x1p-44;

/// The Bernstein coefficients of the product of two polynomials given by theirs, with the
/// pair's product f(a_i, b_j) (cross, dot or a plain product).
template <class A, class B, class F>
std::vector<double> product(std::span<const A> a, std::span<const B> b, F f) {
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

std::vector<double> times(std::span<const double> a, std::span<const double> b) {
  return product(a, b, [](double x, double y) { return x * y; });
}

/// p(t) for the Bernstein coefficients of p.
double evaluate(std::span<const double> c, double t) { return core::bernstein::evaluate(c, t); }

/// A root u of p = d^2 c^2 - s^3 (with d c > 0 and s > 0 there) polished by Newton's method on
/// f = s^(3/2) - d c, which vanishes there too: f keeps the cancellation of two numbers of the
/// size of |B'|^3, where p's coefficients, sixth powers of the whole piece's, round far above
/// its values next to a near-cusp of B. A step is kept while it stays in [0, 1] and |f|
/// falls; at most kPolishSteps.
double polished(const std::vector<double>& c, const std::vector<double>& s, double d, double u) {
  const core::Coeffs dc = core::bernstein_derivative(c), ds = core::bernstein_derivative(s);
  auto f = [&](double x) { return std::pow(evaluate(s, x), 1.5) - d * evaluate(c, x); };
  double fu = f(u);
  for (int step = 0; step < kPolishSteps && fu != 0.0; ++step) {
    const double slope = 1.5 * std::sqrt(evaluate(s, u)) * evaluate(ds, u) - d * evaluate(dc, u);
    const double next = u - fu / slope;
    if (!(next >= 0.0 && next <= 1.0)) break;
    const double fn = f(next);
    if (!(std::fabs(fn) < std::fabs(fu))) break;
    u = next;
    fu = fn;
  }
  return u;
}

/// What cusps_on compares with, from the whole curve's hodographs: the squared speed below
/// which a piece is not halved (kNearCuspSpeed of the largest), and a bound of the rounding of
/// c's coefficients on any piece (16 n u M1 M2, M1 and M2 the largest control points of B' and
/// B'': the pieces' control points carry the rounding of the whole curve's).
struct Limits {
  double floor_squared = 0.0;
  double cross_error = 0.0;
};

/// The cusps on [a, b] of the scaled curve whose hodographs are h1 and h2 (offset_cusps below),
/// appended to `out`; `work` grows by the operations of each piece (its products, and the root
/// search's intervals, each a portion of p).
void cusps_on(std::span<const Point2> h1, std::span<const Point2> h2, double d, double a,
              double b, int depth, const Limits& limits, std::vector<double>& out,
              std::int64_t& work) {
  const auto n = static_cast<std::int64_t>(h1.size());
  work += 16 * n * n;
  ControlPoints f, g;
  piece_into(h1, a, b, f);
  piece_into(h2, a, b, g);
  const std::vector<double> c = product<Point2, Point2>(
      f, g, [](Point2 x, Point2 y) { return core::cross(x, y); });
  // No cusp where d c <= 0 throughout (to within c's rounding): a piece that turns away from
  // d's side, or none at all (a line).
  double towards = 0.0;
  for (const double x : c) towards = std::max(towards, d * x);
  if (!(towards > std::fabs(d) * limits.cross_error)) return;
  const std::vector<double> s = product<Point2, Point2>(
      f, f, [](Point2 x, Point2 y) { return core::dot(x, y); });
  // d^2 c^2, raised from degree 4n - 6 to 6n - 6 by the product with 1 (all coefficients 1).
  std::vector<double> squared = times(c, c);
  for (double& x : squared) x *= d * d;
  const std::vector<double> raised = times(squared, std::vector<double>(2 * f.size() + 1, 1.0));
  const std::vector<double> cubed = times(times(s, s), s);
  std::vector<double> poly(raised.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    poly[i] = raised[i] - cubed[i];
    largest = std::max({largest, std::fabs(raised[i]), std::fabs(cubed[i])});
  }
  if (largest == 0.0) return;
  std::vector<double> found;
  bool unclear = false;
  const core::BernsteinRoots roots = core::bernstein_roots(poly);
  const auto degree = static_cast<std::int64_t>(poly.size());
  work += std::int64_t{roots.intervals} * degree * degree;
  for (const double u : roots.roots) {
    const double su = evaluate(s, u);
    if (!(su * su * su > kStationaryShare * largest)) {
      unclear = true;  // B' = 0 here, or |B'|^3 below the rounding of this piece's p
      continue;
    }
    if (!(d * evaluate(c, u) > 0.0)) continue;
    const double root = polished(c, s, d, u);
    // Where |B'| is below the floor, a near-cusp of B: taken as its zero of B', like the
    // pieces not halved below.
    if (evaluate(s, root) > limits.floor_squared) found.push_back(a + (b - a) * root);
  }
  if (unclear && depth < kCuspDepth && largest_squared_length(f) > limits.floor_squared) {
    const double m = a + 0.5 * (b - a);
    if (a < m && m < b) {
      cusps_on(h1, h2, d, a, m, depth + 1, limits, out, work);
      cusps_on(h1, h2, d, m, b, depth + 1, limits, out, work);
      return;
    }
  }
  out.insert(out.end(), found.begin(), found.end());
}

}  // namespace

std::vector<double> offset_cusps(const core::Curve& curve, double d, std::int64_t* work) {
  std::int64_t done = 0;
  std::vector<double> cusps;
  const int n = curve.degree();
  // A line, or the curve itself, has no cusps; nor has a point.
  const double scale = n < 2 || d == 0.0 ? 0.0 : core::scale(curve);
  if (scale > 0.0) {
    // Scale by a power of two so that the largest coordinate is about 1.
    const int e = -core::exponent_of(scale);
    const std::vector<Point2> p = core::scaled_by_power_of_two(curve.points(), e);
    ControlPoints first, second;
    hodograph_into(p, first);
    hodograph_into(first, second);
    const double m1 = std::sqrt(largest_squared_length(first));
    const double m2 = std::sqrt(largest_squared_length(second));
    const Limits limits{kNearCuspSpeed * kNearCuspSpeed * m1 * m1,
                        16.0 * n * std::numeric_limits<double>::epsilon() * m1 * m2};
    cusps_on(first, second, core::PowerOfTwo(e).times(d), 0.0, 1.0, 0, limits, cusps, done);
    // A cusp at a split point may be found on both sides of it.
    std::sort(cusps.begin(), cusps.end());
    cusps.erase(std::unique(cusps.begin(), cusps.end(),
                            [](double x, double y) { return y - x <= kSameCusp; }),
                cusps.end());
  }
  if (work != nullptr) *work += done;
  return cusps;
}

}  // namespace bezier::outline
