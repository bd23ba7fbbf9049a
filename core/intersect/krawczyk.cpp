#include "core/intersect/krawczyk.hpp"

#include <cmath>

#include "core/bernstein/bernstein1d.hpp"
#include "core/numeric/lerp_error_bound.hpp"
#include "core/numeric/min_max.hpp"
#include "core/base/multiversion.hpp"
#include "core/numeric/tuning.hpp"
#include "core/numeric/unit_roundoff.hpp"
#include "core/intersect/tuning.hpp"

namespace bezier::core {

namespace {

constexpr double kSlack = intersect_tuning::kKrawczykSlack;
/// The degree up to which curves are evaluated on the stack.
constexpr std::size_t kMaxDegree = numeric_tuning::kInlineEntries - 1;
using namespace intersect_tuning;


/// The midpoint and radius of an interval known to hold a quantity.
struct Range {
  double mid = 0.0;
  double rad = 0.0;
};

/// f(t) and f'(t), de Casteljau in doubles on the hi parts; the derivative from the last
/// level, n (b_1 - b_0).
struct PointAndDerivative {
  double x, y, dx, dy;
};

/// de Casteljau down to the last level in the buffers x, y (n + 1 entries each), for the
/// degrees above 3.
PointAndDerivative casteljau_levels(const double* xs, const double* ys, std::size_t n, double t,
                                    double* x, double* y) noexcept {
  for (std::size_t i = 0; i <= n; ++i) {
    x[i] = xs[i];
    y[i] = ys[i];
  }
  for (std::size_t level = n; level > 1; --level) {
    for (std::size_t k = 0; k < level; ++k) {
      x[k] = bernstein::lerp(x[k], x[k + 1], t);
      y[k] = bernstein::lerp(y[k], y[k + 1], t);
    }
  }
  const double dn = static_cast<double>(n);
  return {bernstein::lerp(x[0], x[1], t), bernstein::lerp(y[0], y[1], t), dn * (x[1] - x[0]),
          dn * (y[1] - y[0])};
}

/// The same for N + 1 coefficients fixed at compile time (the same operations).
template <std::size_t N>
PointAndDerivative casteljau_fixed(const double* xs, const double* ys, double t) noexcept {
  const auto x = bernstein::last_casteljau_level(std::span<const double, N + 1>(xs, N + 1), t);
  const auto y = bernstein::last_casteljau_level(std::span<const double, N + 1>(ys, N + 1), t);
  const double dn = static_cast<double>(N);
  return {bernstein::lerp(x[0], x[1], t), bernstein::lerp(y[0], y[1], t), dn * (x[1] - x[0]),
          dn * (y[1] - y[0])};
}

PointAndDerivative casteljau(const WorkingCurve& c, double t) noexcept {
  const std::size_t n = c.x.size() - 1;
  if (n == 3) return casteljau_fixed<3>(c.x.data(), c.y.data(), t);
  if (n == 2) return casteljau_fixed<2>(c.x.data(), c.y.data(), t);
  if (n == 1) return casteljau_fixed<1>(c.x.data(), c.y.data(), t);
  double x[kMaxDegree + 1], y[kMaxDegree + 1];
  return casteljau_levels(c.x.data(), c.y.data(), n, t, x, y);
}

/// How far the computed value of `casteljau` can be from the exact working curve's point:
/// the hi parts are within frame_error of it, and the n levels of lerps round by at most
/// lerp_levels_error_bound.
double value_error(const WorkingCurve& c) noexcept {
  return c.frame_error + lerp_levels_error_bound(c.degree, c.magnitude);
}

/// Ranges holding df/dt over the piece's domain [a, b], per coordinate: the hodograph's
/// coefficients n (P_{i+1} - P_i) of the exact piece, divided by b - a. Each exact
/// difference is within 2 error of the stored points' one, which rounds by u of itself.
bool derivative_ranges(const Piece& p, double a, double b, Range& rx, Range& ry) noexcept {
  const std::size_t n = p.x.size() - 1;
  const double w = b - a;  // within u w of the exact width
  if (n < 1 || !(w > 0.0)) return false;
  const double q = static_cast<double>(n) / w;  // within 2.01 u of n / (b - a)
  const auto range = [&](const Coeffs& c) {
    double lo = c[1] - c[0], hi = lo;
    for (std::size_t i = 1; i < n; ++i) {
      const double d = c[i + 1] - c[i];
      lo = min2(lo, d);
      hi = max2(hi, d);
    }
    const double big = max2(std::fabs(lo), std::fabs(hi));
    const double mid = 0.5 * (lo + hi);
    // Error of each difference, then the rounding of mid and of the half width.
    const double rad = 0.5 * (hi - lo) + 2 * p.error + 3 * kUnitRoundoff * big;
    return Range{q * mid, (q * rad + 4 * kUnitRoundoff * q * (std::fabs(mid) + rad)) * kSlack};
  };
  rx = range(p.x);
  ry = range(p.y);
  return std::isfinite(rx.rad) && std::isfinite(ry.rad);
}

/// Rounds a parameter in [0, 1] to a multiple of 2^-52, so that it plus or minus a power of
/// two in [2^-52, 1] is exact. (1 + t lies in [1, 2], where the doubles are that grid.)
double snap(double t) noexcept {
  return (t + 1.0) - 1.0;
}

/// Where Newton's method starts, inside X and on the 2^-52 grid: where the pieces' chords
/// cross, in the box's parameters (a piece is within O(width^2) of its chord, so this is
/// about that close to a root, where the centre may be half the width away, so a successful
/// test takes fewer Newton steps), or the centre when they do not cross in the box.
void newton_start(const Piece& f_piece, const Piece& g_piece, ParamInterval t, ParamInterval s,
                  double y[2]) noexcept {
  const double fx = f_piece.x.back() - f_piece.x[0], fy = f_piece.y.back() - f_piece.y[0];
  const double gx = g_piece.x.back() - g_piece.x[0], gy = g_piece.y.back() - g_piece.y[0];
  const double rx = g_piece.x[0] - f_piece.x[0], ry = g_piece.y[0] - f_piece.y[0];
  // f0 + u F = g0 + v G by Cramer's rule.
  const double det = fx * gy - fy * gx;
  const double u = (rx * gy - ry * gx) / det, v = (rx * fy - ry * fx) / det;
  if (u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0) {  // false for NaN too
    y[0] = snap(t.lo + (t.hi - t.lo) * u);
    y[1] = snap(s.lo + (s.hi - s.lo) * v);
    if (t.lo <= y[0] && y[0] <= t.hi && s.lo <= y[1] && y[1] <= s.hi) return;
  }
  y[0] = snap(t.lo + (t.hi - t.lo) / 2);
  y[1] = snap(s.lo + (s.hi - s.lo) / 2);
}

}  // namespace

BEZIER_FMA_CLONES KrawczykResult krawczyk(const WorkingCurve& f, const WorkingCurve& g,
                                          const Piece& f_piece, const Piece& g_piece,
                                          ParamInterval t, ParamInterval s, double radius) {
  KrawczykResult out;
  if (f.degree < 1 || g.degree < 1 || f.x.size() > kMaxDegree + 1 || g.x.size() > kMaxDegree + 1)
    return out;
  Range fx, fy, gx, gy;
  if (!derivative_ranges(f_piece, t.lo, t.hi, fx, fy) ||
      !derivative_ranges(g_piece, s.lo, s.hi, gx, gy))
    return out;
  // J(X) = [f'(T), -g'(S)] as midpoint M and radius R.
  const double M[2][2] = {{fx.mid, -gx.mid}, {fy.mid, -gy.mid}};
  const double R[2][2] = {{fx.rad, gx.rad}, {fy.rad, gy.rad}};
  const double det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
  if (!(std::fabs(det) > 0.0) || !std::isfinite(det)) return out;
  const double C[2][2] = {{M[1][1] / det, -M[0][1] / det}, {-M[1][0] / det, M[0][0] / det}};
  // B >= |I - C J| for every J in [M - R, M + R]: |I - C M| (computed, plus its rounding:
  // two products, a sum and a difference, each within u) plus |C| R.
  double B[2][2];
  double rho[2];
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const double delta = i == j ? 1.0 : 0.0;
      const double p0 = C[i][0] * M[0][j], p1 = C[i][1] * M[1][j];
      const double e = delta - (p0 + p1);
      B[i][j] = (std::fabs(e) + 4 * kUnitRoundoff * (delta + std::fabs(p0) + std::fabs(p1)) +
                 std::fabs(C[i][0]) * R[0][j] + std::fabs(C[i][1]) * R[1][j]) *
                kSlack;
    }
    rho[i] = (B[i][0] + B[i][1]) * kSlack;
    if (!(rho[i] <= kMaxRho)) return out;  // also catches NaN
  }

  const double ef = value_error(f), eg = value_error(g);
  double y[2];
  newton_start(f_piece, g_piece, t, s, y);
  for (int iteration = 0; iteration < kNewtonIterations; ++iteration) {
    const PointAndDerivative a = casteljau(f, y[0]), b = casteljau(g, y[1]);
    const double F[2] = {a.x - b.x, a.y - b.y};
    const double eF[2] = {(ef + eg + kUnitRoundoff * std::fabs(F[0])) * kSlack,
                          (ef + eg + kUnitRoundoff * std::fabs(F[1])) * kSlack};
    // C F(y) and how far it can be from C times the exact F(y).
    double step[2], step_error[2];
    for (int i = 0; i < 2; ++i) {
      const double p0 = C[i][0] * F[0], p1 = C[i][1] * F[1];
      step[i] = p0 + p1;
      step_error[i] = (2.01 * kUnitRoundoff * (std::fabs(p0) + std::fabs(p1)) + std::fabs(C[i][0]) * eF[0] +
                       std::fabs(C[i][1]) * eF[1]) *
                      kSlack;
    }
    if (!(std::isfinite(step[0]) && std::isfinite(step[1]))) return out;
    if (iteration == 0) {
      // K(X, y) with y the start (any point of X will do): a root of X would lie in it.
      const ParamInterval X[2] = {t, s};
      const double h[2] = {max2(std::fabs(y[0] - t.lo), std::fabs(t.hi - y[0])) * (1 + 4 * kUnitRoundoff),
                           max2(std::fabs(y[1] - s.lo), std::fabs(s.hi - y[1])) * (1 + 4 * kUnitRoundoff)};
      for (int i = 0; i < 2; ++i) {
        const double centre = y[i] - step[i];
        const double spread =
            (step_error[i] + B[i][0] * h[0] + B[i][1] * h[1]) * kSlack + 4 * kUnitRoundoff * std::fabs(centre);
        if (centre + spread < X[i].lo || centre - spread > X[i].hi) {
          out.verdict = KrawczykResult::Verdict::no_root;
          return out;
        }
      }
    }
    // K(Y, y) inside Y = y +- radius (exact: y is on the 2^-52 grid).
    const ParamInterval Y[2] = {{y[0] - radius, y[0] + radius}, {y[1] - radius, y[1] + radius}};
    if (t.lo <= Y[0].lo && Y[0].hi <= t.hi && s.lo <= Y[1].lo && Y[1].hi <= s.hi &&
        (std::fabs(step[0]) + step_error[0] + rho[0] * radius) * kSlack < radius &&
        (std::fabs(step[1]) + step_error[1] + rho[1] * radius) * kSlack < radius) {
      out.verdict = KrawczykResult::Verdict::one_root;
      out.t = Y[0];
      out.s = Y[1];
      return out;
    }
    // Newton's step with the Jacobian at y (the simplified step C F(y) where it is singular).
    const double j00 = a.dx, j01 = -b.dx, j10 = a.dy, j11 = -b.dy;
    const double jdet = j00 * j11 - j01 * j10;
    double dt = step[0], ds = step[1];
    if (std::fabs(jdet) > 0.0) {
      dt = (j11 * F[0] - j01 * F[1]) / jdet;
      ds = (j00 * F[1] - j10 * F[0]) / jdet;
    }
    y[0] = snap(y[0] - dt);
    y[1] = snap(y[1] - ds);
    if (!(t.lo <= y[0] && y[0] <= t.hi && s.lo <= y[1] && y[1] <= s.hi)) return out;
  }
  return out;
}

}  // namespace bezier::core
