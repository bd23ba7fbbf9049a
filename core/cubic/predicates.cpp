#include "core/cubic/predicates.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

#include "core/numeric/expansion.hpp"
#include "core/numeric/power_of_two.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {

namespace {

// The error bounds below (multiples of u = kUnitRoundoff) are evaluated in floating point
// themselves: a handful of roundings, each at most u relative, all on nonnegative terms. This factor covers them (and the
// (1 + u) factors between computed and true magnitudes) with room to spare.
constexpr double kBoundSlack = 1.0 + 0x1p-20;
// The filter runs only when the largest coordinate difference m lies in [2^-200, 2^200]:
// then no value overflows (degree 4 in the differences stays below 2^810) and every error
// term stays far above the subnormal range, where rounding stops being relative.
constexpr double kFilterMin = 0x1p-200;
constexpr double kFilterMax = 0x1p200;
// The exact path scales the largest |coordinate| into [2^200, 2^201). A product of two
// doubles has an exact rounding error (via fma) when the exponents of their least
// significant bits sum to at least -1074; a degree-4 product of coordinate differences
// then needs every nonzero coordinate's lsb at or above 2^-268, which holds for every
// scaled coordinate of magnitude >= 2^-216, i.e. within 2^416 of the largest.
constexpr int kExactTopExponent = 200;
constexpr double kExactSmallest = 0x1p-216;

int sign_of(double v) noexcept {
  return (v > 0.0) - (v < 0.0);
}

// The sign of a value whose error is at most `bound`, or nothing when the bound straddles 0.
bool is_certain(double value, double bound) noexcept {
  return std::fabs(value) > bound * kBoundSlack;
}

double cross(double ax, double ay, double bx, double by) noexcept {
  return ax * by - ay * bx;
}

Expansion cross(const Expansion& ax, const Expansion& ay, const Expansion& bx,
                const Expansion& by) {
  return ax * by - ay * bx;
}

}  // namespace

CubicPredicates cubic_predicates(std::span<const Point2, 4> p) {
  // Differences from P0: translation then changes nothing (exact inputs give exact
  // differences whenever the subtraction is exact, e.g. by Sterbenz's lemma).
  const double ux = p[1].x - p[0].x, uy = p[1].y - p[0].y;
  const double vx = p[2].x - p[0].x, vy = p[2].y - p[0].y;
  const double wx = p[3].x - p[0].x, wy = p[3].y - p[0].y;
  // std::max, not std::fmax: the inputs are finite (precondition), and fmax is a libm call.
  const double m = std::max(
      std::max(std::max(std::fabs(ux), std::fabs(uy)), std::max(std::fabs(vx), std::fabs(vy))),
      std::max(std::fabs(wx), std::fabs(wy)));
  // The inputs, not their differences: finite coordinates more than DBL_MAX apart have
  // infinite differences (m = inf then takes the exact path, which rescales first).
  assert(std::isfinite(p[0].x) && std::isfinite(p[0].y) && std::isfinite(p[1].x) &&
         std::isfinite(p[1].y) && std::isfinite(p[2].x) && std::isfinite(p[2].y) &&
         std::isfinite(p[3].x) && std::isfinite(p[3].y) &&
         "cubic_predicates: coordinates must be finite");
  if (!(kFilterMin <= m && m <= kFilterMax)) return cubic_predicates_exact(p);

  const double uxv = cross(ux, uy, vx, vy);
  const double uxw = cross(ux, uy, wx, wy);
  const double vxw = cross(vx, vy, wx, wy);
  const double d1 = uxv;
  const double d2 = uxw - 3.0 * uxv;
  const double d3 = (3.0 * uxv - 2.0 * uxw) + vxw;
  const double vertex = d2 + 2.0 * d3;
  const double i1 = (d1 + d2) + d3;

  // A-priori bounds on |computed - exact| for the exact differences, in units of u m^2.
  // A cross product of computed differences carries four roundings per term:
  // |error| <= 4.0001 u (|a_x b_y| + |a_y b_x|) <= 8.0002 u m^2, and |cross| <= 2.0001 m^2.
  // Then 3 uxv: 24.01 + 6.01 (its own rounding) = 30.02; d2 = uxw - 3 uxv: 8.01 + 30.02
  // + 8.04 (rounding of |d2| <= 8.04 m^2) < 47; 3 uxv - 2 uxw: 30.02 + 16.01 + 10.04 = 56.07,
  // plus vxw: 64.08 + 12.06 < 77 (|d3| <= 12.06 m^2); d2 + 2 d3: 47 + 154 + 32.2 < 235;
  // (d1 + d2) + d3: 9 + 47 + 77 + 10.1 + 22.2 < 167.
  const double unit = kUnitRoundoff * m * m;
  const double e1 = 9.0 * unit, e2 = 47.0 * unit, e3 = 77.0 * unit;
  const double e_vertex = 235.0 * unit, e_i1 = 167.0 * unit;

  // Degree 4, one bound for all three: with A = max |d~i|, each product's propagated error is
  // |d~i d~j − di dj| <= |d~i| e_j + (|d~j| + e_j) e_i <= A (e_i + e_j) + e_i e_j, and each
  // rounding (products, the scalings by 3, the sums) at most u times the sum of the absolute
  // terms. Summed over l1 = d2² + d2 d3 + d3² − 3 d1 d3, the largest of the three:
  // (94 + 124 + 154 + 3·86) A U + (47² + 47·77 + 77² + 3·9·77) U² + u (4·6 + 3) A²
  // = 630 A U + 13836 U² + 27 u A²; disc (438, 4981, 10) and l0 (352, 4288, 11) are smaller.
  // Looser than per-predicate bounds by a small factor, and a third of the work.
  const double a = std::max(std::max(std::fabs(d1), std::fabs(d2)), std::fabs(d3));
  const double disc = d2 * d2 - 4.0 * (d1 * d3);
  const double l0 = d2 * d2 - 3.0 * (d1 * d3);
  const double l1 = ((d2 * d2 + d2 * d3) + d3 * d3) - 3.0 * (d1 * d3);
  const double bound4 = (630.0 * a + 13836.0 * unit) * unit + 27.0 * kUnitRoundoff * a * a;
  const double smallest4 = std::min(std::min(std::fabs(disc), std::fabs(l0)), std::fabs(l1));

  // Bitwise & (on ints: clang's -Wbitwise-instead-of-logical): six well-predicted tests
  // without six branches.
  const bool all_certain =
      (int{is_certain(d1, e1)} & int{is_certain(d2, e2)} & int{is_certain(d3, e3)} &
       int{is_certain(vertex, e_vertex)} & int{is_certain(i1, e_i1)} &
       int{is_certain(smallest4, bound4)}) != 0;
  // Near an edge (or a degenerate configuration: some value is zero) the filter cannot
  // decide; the exact path decides everything, and its approximations are the better ones.
  if (!all_certain) return cubic_predicates_exact(p);

  CubicPredicates out;
  out.d1 = d1;
  out.d2 = d2;
  out.d3 = d3;
  out.x_num = uxw;
  out.y_num = cross(p[1].x - p[2].x, p[1].y - p[2].y, wx, wy);
  out.disc = disc;
  out.l0 = l0;
  out.l1 = l1;
  out.sign = {sign_of(d1), sign_of(d2),   sign_of(d3), sign_of(vertex),
              sign_of(i1), sign_of(disc), sign_of(l0), sign_of(l1)};
  out.exact = true;
  return out;
}

CubicPredicates cubic_predicates_exact(std::span<const Point2, 4> p) {
  CubicPredicates out;
  double largest = 0.0;
  for (const Point2& q : p) largest = std::fmax(largest, max_abs_coordinate(q));
  assert(std::isfinite(largest) && "cubic_predicates: coordinates must be finite");
  if (largest == 0.0) return out;  // all points at the origin: every value is zero

  // Scale by 2^k (exact unless a tiny coordinate falls into the subnormal range, which the
  // window check reports) so nothing overflows and the products stay exact.
  const int k = kExactTopExponent - exponent_of(largest);
  std::array<Point2, 4> q{};
  for (std::size_t i = 0; i < 4; ++i) {
    q[i] = {std::ldexp(p[i].x, k), std::ldexp(p[i].y, k)};
    const bool x_lost = p[i].x != 0.0 && !(std::fabs(q[i].x) >= kExactSmallest);
    const bool y_lost = p[i].y != 0.0 && !(std::fabs(q[i].y) >= kExactSmallest);
    if (x_lost || y_lost) out.exact = false;
  }

  const Expansion ux = Expansion::difference(q[1].x, q[0].x);
  const Expansion uy = Expansion::difference(q[1].y, q[0].y);
  const Expansion vx = Expansion::difference(q[2].x, q[0].x);
  const Expansion vy = Expansion::difference(q[2].y, q[0].y);
  const Expansion wx = Expansion::difference(q[3].x, q[0].x);
  const Expansion wy = Expansion::difference(q[3].y, q[0].y);
  const Expansion uxv = cross(ux, uy, vx, vy);
  const Expansion uxw = cross(ux, uy, wx, wy);
  const Expansion vxw = cross(vx, vy, wx, wy);
  const Expansion y_num =
      cross(Expansion::difference(q[1].x, q[2].x), Expansion::difference(q[1].y, q[2].y), wx, wy);

  const Expansion& d1 = uxv;
  const Expansion d2 = uxw - uxv * 3.0;
  const Expansion d3 = uxv * 3.0 - uxw * 2.0 + vxw;
  const Expansion vertex = d2 + d3 * 2.0;
  const Expansion i1 = d1 + d2 + d3;
  const Expansion p22 = d2 * d2;
  const Expansion p13 = d1 * d3;
  const Expansion disc = p22 - p13 * 4.0;
  const Expansion l0 = p22 - p13 * 3.0;
  const Expansion l1 = p22 + d2 * d3 + d3 * d3 - p13 * 3.0;

  out.d1 = d1.estimate();
  out.d2 = d2.estimate();
  out.d3 = d3.estimate();
  out.x_num = uxw.estimate();
  out.y_num = y_num.estimate();
  out.disc = disc.estimate();
  out.l0 = l0.estimate();
  out.l1 = l1.estimate();
  out.sign = {d1.sign(), d2.sign(),   d3.sign(), vertex.sign(),
              i1.sign(), disc.sign(), l0.sign(), l1.sign()};
  if (!out.exact && p[2] == p[3]) {
    // P2 = P3 (B'(1) = 0): w = v, so d2 = −2 d1, d3 = d1 and then d2 + 2 d3 = I(1) = disc
    // = l1 = 0, l0 = d1², identically. With coordinates lost to underflow the products
    // above are not exact and can break these identities (a cusp at t = 1 read as a loop
    // closing there with t1 = t2 = 1); restore them from d1.
    const double e1 = out.d1;
    const int s1 = out.sign.d1;
    out.d2 = -2.0 * e1;
    out.d3 = e1;
    out.disc = 0.0;
    out.l0 = e1 * e1;
    out.l1 = 0.0;
    out.sign = {s1, -s1, s1, 0, 0, 0, s1 * s1, 0};
  }
  return out;
}

}  // namespace bezier::core
