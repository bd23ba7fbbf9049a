#include "core/intersect/clip/implicit_cubic_clip.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "core/bernstein/bernstein1d.hpp"
#include "core/base/multiversion.hpp"
#include "core/numeric/binomial.hpp"
#include "core/numeric/double_double.hpp"
#include "core/numeric/error_free.hpp"
#include "core/numeric/min_max.hpp"
#include "core/numeric/small_array.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {

namespace {

constexpr double u = kUnitRoundoff;

/// A polynomial in the scaled Bernstein basis C(n,k) (1-t)^(n-k) t^k, coefficients as
/// double-doubles: products are then plain convolutions with no weights to round. mag
/// bounds the Bernstein coefficients' magnitudes (|c_k| / C(n,k)) and err the distance of
/// each Bernstein coefficient to the exact one (so |exact(t) - value(t)| <= err on [0, 1]).
struct Bounded {
  SmallArray<dd::Real> c;
  double mag = 0.0;
  double err = 0.0;
  [[nodiscard]] int degree() const noexcept { return static_cast<int>(c.size()) - 1; }
};

/// The Bernstein magnitude of the coefficients, max_k |c_k| / C(n, k), from their high
/// parts (|lo| <= u |hi|). The largest quotient is chosen by cross products (no division
/// per coefficient; the binomials grow by the exact step C(n,k+1) = C(n,k) (n-k) / (k+1)),
/// a choice within rounding of the largest, which the factor covers.
double bernstein_magnitude(const SmallArray<dd::Real>& c) {
  const int n = static_cast<int>(c.size()) - 1;
  double best = 0.0, best_binomial = 1.0, binomial_k = 1.0;
  for (int k = 0; k <= n; ++k) {
    const double v = std::fabs(c[static_cast<std::size_t>(k)].hi);
    if (v * best_binomial > best * binomial_k) {
      best = v;
      best_binomial = binomial_k;
    }
    binomial_k = binomial_k * (n - k) / (k + 1);
  }
  return best / best_binomial * (1 + 8 * u);
}

/// a + sign b, coefficient by coefficient (equal degrees). A double-double sum is within
/// 3 u^2 of its value (Joldes et al., Algorithm 6), |a + b| <= (A + B) C(n,k).
Bounded combined(const Bounded& a, const Bounded& b, double sign) {
  assert(a.c.size() == b.c.size());
  Bounded out;
  out.c = SmallArray<dd::Real>(a.c.size(), SmallArray<dd::Real>::Uninitialized{});
  for (std::size_t k = 0; k < a.c.size(); ++k)
    out.c[k] = dd::add(a.c[k], sign > 0 ? b.c[k] : dd::neg(b.c[k]));
  out.mag = bernstein_magnitude(out.c);
  out.err = (a.err + b.err + 3.01 * u * u * (a.mag + b.mag)) * (1 + 4 * u);
  return out;
}

/// The product, of degree p + q: c_k = sum_{i+j=k} a_i b_j in the scaled basis. In
/// Bernstein terms (c_k / C(p+q,k)) the weights C(p,i) C(q,j) / C(p+q,k) sum to 1
/// (Vandermonde), so inputs off by ea, eb move a coefficient by at most A eb + B ea +
/// ea eb, and the rounding (each product within 6 u^2, each of at most min(p, q) sums
/// within 3 u^2 of its partial sum, Joldes et al.) by at most (3 min(p, q) + 10) u^2 A B.
Bounded product(const Bounded& a, const Bounded& b) {
  const int p = a.degree(), q = b.degree();
  Bounded out;
  out.c = SmallArray<dd::Real>(static_cast<std::size_t>(p + q + 1), dd::Real{});
  for (int i = 0; i <= p; ++i) {
    for (int j = 0; j <= q; ++j) {
      dd::Real& c = out.c[static_cast<std::size_t>(i + j)];
      c = dd::add(c, dd::mul(a.c[static_cast<std::size_t>(i)], b.c[static_cast<std::size_t>(j)]));
    }
  }
  out.mag = bernstein_magnitude(out.c);
  const double rounding = (3 * std::min(p, q) + 10) * u * u * 1.01 * a.mag * b.mag;
  out.err = (a.mag * b.err + b.mag * a.err + a.err * b.err + rounding) * (1 + 8 * u);
  return out;
}

double norm(Point2 v) { return std::sqrt(dot(v, v)) * (1 + 4 * u); }

/// s a for a double s: each product within 2 u^2 (Joldes et al., Algorithm 9).
Bounded scaled(const Bounded& a, double s) {
  Bounded out;
  out.c = SmallArray<dd::Real>(a.c.size(), SmallArray<dd::Real>::Uninitialized{});
  for (std::size_t k = 0; k < a.c.size(); ++k) out.c[k] = dd::mul(a.c[k], s);
  out.mag = bernstein_magnitude(out.c);
  out.err = std::fabs(s) * (a.err + 2.01 * u * u * a.mag) * (1 + 2 * u);
  return out;
}

/// The index pairs (i, j) of the Bezout matrix's distinct entries L_ij, i > j.
struct Pair {
  int i, j;
};
constexpr Pair kL32{3, 2}, kL31{3, 1}, kL30{3, 0}, kL21{2, 1}, kL20{2, 0}, kL10{1, 0};

double weight(Pair e) { return binomial(3, e.i) * binomial(3, e.j); }

/// L_ij(c(t)) for a curve c with control points `at`: L_ij is affine, so its values at the
/// control points are the Bernstein coefficients (here times C(n,k), exact integers). Each
/// is w cross(P_i - c_k, P_j - c_k) with the differences exact (double-doubles), the cross
/// product in double-double arithmetic (two products within 6 u^2 and a difference within
/// 3 u^2 of their values, Joldes et al.) and the two exact weights applied in double-double
/// (2 u^2 each): within 16 u^2 w |P_i - c_k| |P_j - c_k| in Bernstein terms. A short piece
/// of a cubic is nearly straight, so L is far below |P_i - c_k| |P_j - c_k| there, and J
/// cancels to far below the products that form it: doubles would bury both.
Bounded entry(const Point2 (&p)[4], std::span<const Point2> at, Pair e) {
  const double w = weight(e);
  const int n = static_cast<int>(at.size()) - 1;
  Bounded out;
  out.c = SmallArray<dd::Real>(at.size(), SmallArray<dd::Real>::Uninitialized{});
  double binomial_k = 1.0;  // C(n, k), exact (integers below 2^53 for the degrees here)
  for (std::size_t k = 0; k < at.size(); ++k) {
    const TwoTerm<double> ax = two_sum(p[e.i].x, -at[k].x), ay = two_sum(p[e.i].y, -at[k].y);
    const TwoTerm<double> bx = two_sum(p[e.j].x, -at[k].x), by = two_sum(p[e.j].y, -at[k].y);
    const dd::Real c = dd::sub(dd::mul(dd::Real{ax.hi, ax.lo}, dd::Real{by.hi, by.lo}),
                               dd::mul(dd::Real{ay.hi, ay.lo}, dd::Real{bx.hi, bx.lo}));
    out.c[k] = dd::mul(dd::mul(c, w), binomial_k);
    binomial_k = binomial_k * (n - static_cast<int>(k)) / (static_cast<int>(k) + 1);
    const double lengths = norm(Point2{ax.hi, ay.hi}) * norm(Point2{bx.hi, by.hi}) * (1 + 4 * u);
    out.err = max2(out.err, 16 * u * u * w * lengths * (1 + 4 * u));
  }
  out.mag = bernstein_magnitude(out.c);
  return out;
}

/// The Bezout matrix M = [[a, b, c], [b, d, e], [c, e, f]] along a curve (its entries as
/// polynomials), its cofactors and its determinant.
struct BezoutAlong {
  Bounded a, b, c, d, e, f;
  Bounded c11, c12, c13, c22, c23, c33;
  Bounded det;
};

BezoutAlong bezout_along(const Point2 (&p)[4], std::span<const Point2> at, bool with_determinant) {
  BezoutAlong m;
  m.a = entry(p, at, kL32);
  m.b = entry(p, at, kL31);
  m.c = entry(p, at, kL30);
  m.d = combined(m.c, entry(p, at, kL21), 1.0);
  m.e = entry(p, at, kL20);
  m.f = entry(p, at, kL10);
  m.c11 = combined(product(m.d, m.f), product(m.e, m.e), -1.0);
  m.c12 = combined(product(m.c, m.e), product(m.b, m.f), -1.0);
  m.c13 = combined(product(m.b, m.e), product(m.d, m.c), -1.0);
  m.c22 = combined(product(m.a, m.f), product(m.c, m.c), -1.0);
  m.c23 = combined(product(m.b, m.c), product(m.a, m.e), -1.0);
  m.c33 = combined(product(m.a, m.d), product(m.b, m.b), -1.0);
  if (with_determinant)
    m.det = combined(combined(product(m.a, m.c11), product(m.b, m.c12), 1.0), product(m.c, m.c13), 1.0);
  return m;
}

/// The derivative of the entries along `direction` (a unit axis): L_ij(q + s v) =
/// L_ij(q) + s w cross(P_j - P_i, v).
double entry_slope(const Point2 (&p)[4], Pair e, Point2 v) { return weight(e) * cross(p[e.j] - p[e.i], v); }

/// An upper bound of |grad det M| at the points of the curve: grad det M . v =
/// sum_ab C_ab dM_ab/dv (Jacobi's formula), a polynomial along the curve.
double gradient_bound(const Point2 (&p)[4], const BezoutAlong& m) {
  double squares = 0.0;
  for (const Point2 v : {Point2{1.0, 0.0}, Point2{0.0, 1.0}}) {
    const double sa = entry_slope(p, kL32, v), sb = entry_slope(p, kL31, v),
                 sc = entry_slope(p, kL30, v), sd = sc + entry_slope(p, kL21, v),
                 se = entry_slope(p, kL20, v), sf = entry_slope(p, kL10, v);
    Bounded g = combined(scaled(m.c11, sa), scaled(m.c22, sd), 1.0);
    g = combined(g, scaled(m.c33, sf), 1.0);
    g = combined(g, scaled(m.c12, 2 * sb), 1.0);
    g = combined(g, scaled(m.c13, 2 * sc), 1.0);
    g = combined(g, scaled(m.c23, 2 * se), 1.0);
    const double bound = (g.mag + g.err) * (1 + 2 * u);
    squares += bound * bound;
  }
  return std::sqrt(squares) * (1 + 4 * u);
}

/// An upper bound of |det M(q + e) - det M(q)| for q on the curve (in the hull of `at`) and
/// |e| <= d: the first-order term grad det M(q) . e within `gradient` d; the terms with two
/// or three columns of the change E (multilinearity in the columns) by Hadamard's
/// inequality, with M_k bounding column k's l1 norm (>= its Euclidean norm) over the hull
/// and E_k the l1 norm of its change per unit of d.
double perturbation_band(const Point2 (&p)[4], std::span<const Point2> at, double gradient, double d) {
  double reach[4];
  for (int i = 0; i < 4; ++i) {
    reach[i] = 0.0;
    for (const Point2 h : at) reach[i] = max2(reach[i], norm(p[i] - h));
  }
  const auto bound = [&](Pair e) { return weight(e) * reach[e.i] * reach[e.j] * (1 + 4 * u); };
  const auto change = [&](Pair e) { return weight(e) * norm(p[e.i] - p[e.j]) * (1 + 2 * u); };
  const double m1 = bound(kL32) + bound(kL31) + bound(kL30);
  const double m2 = bound(kL31) + bound(kL30) + bound(kL21) + bound(kL20);
  const double m3 = bound(kL30) + bound(kL20) + bound(kL10);
  const double e1 = change(kL32) + change(kL31) + change(kL30);
  const double e2 = change(kL31) + change(kL30) + change(kL21) + change(kL20);
  const double e3 = change(kL30) + change(kL20) + change(kL10);
  const double second = e1 * e2 * m3 + e1 * m2 * e3 + m1 * e2 * e3;
  const double third = e1 * e2 * e3;
  return (d * gradient + d * d * second + d * d * d * third) * (1 + 16 * u);
}

}  // namespace

// Double-double arithmetic rests on fused multiply-adds: where the processor has them the
// clone that uses them runs (the helpers above inlined into it).
BEZIER_FMA_CLONES Clip implicit_cubic_clip(const Piece& x, const Piece& other) {
  assert(other.degree() == 3);
  Point2 p[4];
  for (std::size_t i = 0; i < 4; ++i) p[i] = {other.x[i], other.y[i]};
  Point2 inline_points[16];
  std::vector<Point2> heap_points;
  std::span<const Point2> xs;
  if (x.x.size() <= 16) {
    for (std::size_t k = 0; k < x.x.size(); ++k) inline_points[k] = {x.x[k], x.y[k]};
    xs = std::span<const Point2>(inline_points, x.x.size());
  } else {
    for (std::size_t k = 0; k < x.x.size(); ++k) heap_points.push_back({x.x[k], x.y[k]});
    xs = heap_points;
  }
  const std::span<const Point2> cubic(p, 4);

  // J(t) = det M(x(t)); the band: the true `other` within e_o of the stored cubic (where
  // det M = 0), the true x within e_x of the stored piece, and J's own rounding.
  const BezoutAlong along_x = bezout_along(p, xs, true);
  const BezoutAlong along_other = bezout_along(p, cubic, false);
  const double root2 = std::sqrt(2.0) * (1 + u);
  const double band_other =
      perturbation_band(p, cubic, gradient_bound(p, along_other), root2 * other.error);
  const double band_x = perturbation_band(p, xs, gradient_bound(p, along_x), root2 * x.error);
  // J's Bernstein coefficients: the scaled ones rounded and divided by C(3n, k), each step
  // within u of the coefficient.
  const Bounded& det = along_x.det;
  const int degree = det.degree();
  Coeffs j(det.c.size(), Coeffs::Uninitialized{});
  double largest = 0.0;
  double binomial_k = 1.0;
  for (int k = 0; k <= degree; ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    j[i] = dd::to_double(det.c[i]) / binomial_k;
    largest = max2(largest, std::fabs(j[i]));
    binomial_k = binomial_k * (degree - k) / (k + 1);
  }
  const double band =
      (band_other + band_x + det.err + 2.01 * u * largest) * (1 + 8 * u);
  const auto [lo, hi] = std::minmax_element(j.begin(), j.end());
  Clip out;
  out.kept = bernstein::hull_clip(j, -band, band);
  out.noisy = 4 * band > (*hi - *lo);
  return out;
}

}  // namespace bezier::core
