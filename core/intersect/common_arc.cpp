#include "core/intersect/common_arc.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "core/bernstein/roots.hpp"
#include "core/numeric/binomial.hpp"
#include "core/bernstein/bernstein1d.hpp"
#include "core/numeric/min_max.hpp"
#include "core/numeric/double_double.hpp"
#include "core/intersect/gauss_newton.hpp"
#include "core/bernstein/monomial.hpp"
#include "core/numeric/linear_solve.hpp"
#include "core/numeric/unit_roundoff.hpp"
#include "core/intersect/tuning.hpp"

namespace bezier::core {

using namespace intersect_tuning;

namespace {

/// Monomial coefficients, constant first.
using Monomial = std::vector<double>;

using bernstein::max_abs;

/// The monic right factor p (with p(0) = 0) of degree k of a polynomial a of degree n = d k
/// (monomial coefficients a[0..n]): p + e = (a / a_n)^(1/d) truncated at infinity. With
/// z = 1/t, (p + e)(t) = t^k (1 + sum_j e_j z^j) and a / a_n = t^n (1 + sum_j g_j z^j),
/// g_j = a_(n-j) / a_n; the coefficients of F = G^(1/d) follow from G F' = (1/d) G' F:
/// j e_j = sum_{i=1..j} ((1/d + 1) i - j) g_i e_(j-i), e_0 = 1.
Monomial right_factor(const Coeffs& a, int n, int k) {
  const double alpha = 1.0 / (n / k);
  std::vector<double> g(static_cast<std::size_t>(k) + 1), e(static_cast<std::size_t>(k) + 1);
  for (int j = 1; j <= k; ++j)
    g[j] = a[static_cast<std::size_t>(n - j)] / a[static_cast<std::size_t>(n)];
  e[0] = 1.0;
  for (int j = 1; j <= k; ++j) {
    double sum = 0.0;
    for (int i = 1; i <= j; ++i) sum += ((alpha + 1) * i - j) * g[i] * e[j - i];
    e[j] = sum / j;
  }
  Monomial p(static_cast<std::size_t>(k) + 1, 0.0);
  p[static_cast<std::size_t>(k)] = 1.0;
  for (int j = 1; j < k; ++j) p[static_cast<std::size_t>(k - j)] = e[j];
  return p;  // e_k, the constant, is dropped: p(0) = 0
}

/// True when x (monomial, degree <= n) is a polynomial in the monic p to within
/// kDivisionFilter of `size`, the largest coefficient of both coordinates: every remainder
/// of the repeated division by p is a constant. A filter only: relative to a coordinate's
/// own coefficients, one of low degree (h's x = 10 u) fails on the rounding that the
/// divisions carry down from the other's; the price is that a line x = t beside a
/// decomposable y = T_20(2t - 1) passes, and factor_through turns it down.
bool is_polynomial_in(const Coeffs& x, int n, const Monomial& p, double size) {
  const int k = static_cast<int>(p.size()) - 1;
  Monomial r(x.begin(), x.begin() + n + 1);
  const double tol = kDivisionFilter * size * max2(1.0, max_abs(p));
  const auto constant_below = [&](int degree) {
    for (int j = 1; j <= degree; ++j)
      if (!(std::fabs(r[static_cast<std::size_t>(j)]) <= tol)) return false;
    return true;
  };
  for (int degree = n; degree >= k; degree -= k) {
    Monomial quotient(static_cast<std::size_t>(degree - k) + 1);
    for (int top = degree; top >= k; --top) {
      const double c = r[static_cast<std::size_t>(top)];
      quotient[static_cast<std::size_t>(top - k)] = c;
      for (int l = 0; l <= k; ++l)
        r[static_cast<std::size_t>(top - k + l)] -= c * p[static_cast<std::size_t>(l)];
    }
    if (!constant_below(k - 1)) return false;
    r = std::move(quotient);
  }
  return constant_below(static_cast<int>(r.size()) - 1);
}

/// Bernstein coefficients on [0, 1] of a monomial polynomial: b_i = sum_{j<=i} C(i,j)/C(m,j) a_j.
Coeffs bernstein_from(const Monomial& a) {
  const int m = static_cast<int>(a.size()) - 1;
  Coeffs b(a.size());
  for (int i = 0; i <= m; ++i) {
    double sum = 0.0;
    for (int j = 0; j <= i; ++j)
      sum += binomial(i, j) / binomial(m, j) * a[static_cast<std::size_t>(j)];
    b[static_cast<std::size_t>(i)] = sum;
  }
  return b;
}

double value(const Coeffs& c, double t) {
  return bernstein::evaluate(c, t);
}

/// c(t) by de Casteljau in doubles (the hi parts): good to about 2 n u of c's magnitude,
/// far below every tolerance here, at a tenth of the double-double evaluation's cost.
Point2 point_of(const WorkingCurve& c, double t) {
  return {value(c.x, t), value(c.y, t)};
}

/// A t in [lo, hi] with c(t) = u, where c(lo) <= u <= c(hi) or c(lo) >= u >= c(hi)
/// (bisection on the sign of c - u: a crossing, monotone or not), to within `width`; lo
/// may be the larger end.
double crossing(const Coeffs& c, double lo, double hi, double u, double width) {
  const bool rising = value(c, hi) >= value(c, lo);
  while (std::fabs(hi - lo) > width) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    if ((value(c, mid) < u) == rising)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

/// Where the polynomial c (Bernstein, [0, 1]) turns, and the pieces between: [0, 1] split
/// at the roots of c' where c changes direction.
std::vector<ParamInterval> monotone_pieces(const Coeffs& c) {
  std::vector<double> breaks{0.0};
  if (c.size() > 2) {
    Coeffs d(c.size() - 1);
    for (std::size_t i = 0; i + 1 < c.size(); ++i) d[i] = c[i + 1] - c[i];
    for (const double r : bernstein_roots(d.span()).roots) {
      if (r > kTurnSeparation && r < 1 - kTurnSeparation && r - breaks.back() > kTurnSeparation)
        breaks.push_back(r);
    }
  }
  breaks.push_back(1.0);
  // A first piece within the noise joins the next one.
  if (breaks.size() > 2 && std::fabs(value(c, breaks[1]) - value(c, 0.0)) <= kTurnNoise) {
    breaks.erase(breaks.begin() + 1);
  }
  std::vector<ParamInterval> pieces;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const ParamInterval next{breaks[i], breaks[i + 1]};
    // A turn within the rounding of c's coefficients (a factor's noise near a double root
    // at an end, such as t^2 computed as t^2 - 1e-16 t) is no turn: its piece joins the
    // last one.
    if (std::fabs(value(c, next.hi) - value(c, next.lo)) <= kTurnNoise && !pieces.empty()) {
      pieces.back().hi = next.hi;
      continue;
    }
    // A root of c' where c keeps its direction (an inflection of c) splits nothing.
    if (!pieces.empty()) {
      const ParamInterval last = pieces.back();
      const bool last_rises = value(c, last.hi) >= value(c, last.lo);
      const bool next_rises = value(c, next.hi) >= value(c, next.lo);
      if (last_rises == next_rises) {
        pieces.back().hi = next.hi;
        continue;
      }
    }
    pieces.push_back(next);
  }
  return pieces;
}

/// The factorisation c = h(p) for a right factor p (monomial, monic) of degree k, n = d k,
/// not yet checked: p scaled to the range [0, 1] over [0, 1], h interpolated at the
/// Chebyshev-Lobatto nodes of u (each node's t found on p by bisection between where p
/// is 0 and 1).
std::optional<Factorisation> interpolated(const WorkingCurve& c, const Monomial& p_monic, int d) {
  Coeffs p = bernstein_from(p_monic);
  double t_lo = 0.0, t_hi = 0.0, lo = p[0], hi = p[0];
  std::vector<double> extremes{1.0};
  for (const ParamInterval piece : monotone_pieces(p)) extremes.push_back(piece.lo);
  for (const double t : extremes) {
    const double v = value(p, t);
    if (v < lo) lo = v, t_lo = t;
    if (v > hi) hi = v, t_hi = t;
  }
  if (!(hi - lo > 0)) return std::nullopt;
  for (double& v : p.span()) v = (v - lo) / (hi - lo);
  const std::size_t size = static_cast<std::size_t>(d) + 1;
  // Columns 0 and 1 of the right-hand side: the x and y of the curve at the nodes.
  DenseMatrix<double> m(size, size), rhs(size, 2);
  for (std::size_t j = 0; j < size; ++j) {
    const double u = 0.5 * (1 - std::cos(std::numbers::pi * static_cast<double>(j) / d));
    const double t =
        j == 0 ? t_lo : j + 1 == size ? t_hi : crossing(p, t_lo, t_hi, u, kNodeAccuracy);
    const double uj = j == 0 ? 0.0 : j + 1 == size ? 1.0 : value(p, t);
    for (int i = 0; i <= d; ++i)
      m(j, static_cast<std::size_t>(i)) =
          binomial(d, i) * std::pow(uj, i) * std::pow(1 - uj, d - i);
    const Point2 q = point_of(c, t);
    rhs(j, 0) = q.x;
    rhs(j, 1) = q.y;
  }
  const std::optional<DenseMatrix<double>> h = solve_linear(std::move(m), std::move(rhs));
  if (!h) return std::nullopt;
  Factorisation out;
  out.hx = Coeffs(size);
  out.hy = Coeffs(size);
  for (std::size_t i = 0; i < size; ++i) {
    out.hx[i] = (*h)(i, 0);
    out.hy[i] = (*h)(i, 1);
  }
  out.p = std::move(p);
  return out;
}

/// c(t) - h(p(t)) at 2n + 1 uniform t, both coordinates, relative to c's magnitude.
std::vector<double> misfit(const WorkingCurve& c, const Factorisation& f) {
  const int samples = 2 * c.degree + 1;
  std::vector<double> r;
  r.reserve(2 * static_cast<std::size_t>(samples));
  for (int i = 0; i < samples; ++i) {
    const double t = static_cast<double>(i) / (samples - 1);
    const Point2 a = point_of(c, t);
    const double u = value(f.p, t);
    r.push_back((value(f.hx, u) - a.x) / c.magnitude);
    r.push_back((value(f.hy, u) - a.y) / c.magnitude);
  }
  return r;
}

/// The factor refined on the curve itself: Gauss-Newton on p's free coefficients
/// p_1 .. p_(k-1) (monic, p(0) = 0) minimising c - h(p) at the samples of misfit, h
/// interpolated anew for each p, with a forward-difference Jacobian. The truncated root
/// of right_factor takes p from the top coefficients of the power form, which cancel most
/// (at degree 20, s^2 - 3 s can come out as s^2 - 2.9999985 s, a misfit of 1e-5); a few steps
/// bring it to the rounding. A step that does not reduce the misfit ends it.
Monomial refined_on_curve(const WorkingCurve& c, Monomial p, int d) {
  const std::size_t unknowns = p.size() - 2;
  const auto misfit_of = [&](const Monomial& q) -> std::optional<std::vector<double>> {
    const std::optional<Factorisation> f = interpolated(c, q, d);
    if (!f) return std::nullopt;
    return misfit(c, *f);
  };
  std::optional<std::vector<double>> r = misfit_of(p);
  if (!r) return p;
  double size = max_abs(*r);
  for (int iteration = 0; iteration < kFactorRefineSteps && size > kUnitRoundoff; ++iteration) {
    std::vector<std::vector<double>> jacobian(unknowns);
    for (std::size_t u = 0; u < unknowns; ++u) {
      Monomial q = p;
      const double h =
          intersect_tuning::kFactorJacobianStep * max2(1.0, std::fabs(p[u + 1]));
      q[u + 1] += h;
      const std::optional<std::vector<double>> shifted = misfit_of(q);
      if (!shifted) return p;
      jacobian[u].resize(r->size());
      for (std::size_t i = 0; i < r->size(); ++i) jacobian[u][i] = ((*shifted)[i] - (*r)[i]) / h;
    }
    // The normal equations J^T J step = -J^T r.
    DenseMatrix<double> normal(unknowns, unknowns), gradient(unknowns, 1);
    for (std::size_t a = 0; a < unknowns; ++a) {
      for (std::size_t b = 0; b < unknowns; ++b) {
        double sum = 0.0;
        for (std::size_t i = 0; i < r->size(); ++i) sum += jacobian[a][i] * jacobian[b][i];
        normal(a, b) = sum;
      }
      double sum = 0.0;
      for (std::size_t i = 0; i < r->size(); ++i) sum += jacobian[a][i] * (*r)[i];
      gradient(a, 0) = -sum;
    }
    const std::optional<DenseMatrix<double>> step =
        solve_linear(std::move(normal), std::move(gradient));
    if (!step) break;
    Monomial next = p;
    for (std::size_t u = 0; u < unknowns; ++u) next[u + 1] += (*step)(u, 0);
    const std::optional<std::vector<double>> next_r = misfit_of(next);
    if (!next_r || !(max_abs(*next_r) < size)) break;
    p = std::move(next);
    r = next_r;
    size = max_abs(*r);
  }
  return p;
}

/// interpolated(c, p, d) when it fits c to within kFactorFit of its magnitude at the
/// samples of misfit (p refined on the curve first when it misses by less than
/// kRefineBelow).
std::optional<Factorisation> factor_through(const WorkingCurve& c, const Monomial& p_monic, int d) {
  std::optional<Factorisation> f = interpolated(c, p_monic, d);
  if (!f) return std::nullopt;
  const double first = max_abs(misfit(c, *f));
  if (first <= kFactorFit) return f;
  // A wrong factor misses by the curve's own size; only a near miss is worth refining, and
  // only with a few free coefficients (each costs an interpolation per step).
  if (!(first <= kRefineBelow) || p_monic.size() - 1 > kRefineDegree) return std::nullopt;
  f = interpolated(c, refined_on_curve(c, p_monic, d), d);
  if (f && max_abs(misfit(c, *f)) <= kFactorFit) return f;
  return std::nullopt;
}

/// A proper curve as its own factorisation: h = c, p(t) = t.
Factorisation identity(const WorkingCurve& c) {
  Factorisation out;
  out.hx = c.x;
  out.hy = c.y;
  out.p = Coeffs(2);
  out.p[1] = 1.0;
  return out;
}

/// Newton's method for a turning point of c's parametrisation (c'(t) = 0 where the curve
/// retraces itself): t minimising |c'|, from a guess close to it. Steps above
/// kGaussNewtonLargestStep end it.
double refine_turn(const WorkingCurve& c, double t) {
  const int n = c.degree;
  if (n < 2) return t;
  Coeffs d1x(static_cast<std::size_t>(n)), d1y(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < d1x.size(); ++i) {
    d1x[i] = n * (c.x[i + 1] - c.x[i]);
    d1y[i] = n * (c.y[i + 1] - c.y[i]);
  }
  Coeffs d2x(d1x.size() - 1), d2y(d1x.size() - 1);
  for (std::size_t i = 0; i < d2x.size(); ++i) {
    d2x[i] = (n - 1) * (d1x[i + 1] - d1x[i]);
    d2y[i] = (n - 1) * (d1y[i + 1] - d1y[i]);
  }
  return gauss_newton(t, kArcNewtonSteps, kProjectionConverged, [&](double u) {
    return ResidualAndSlope{{value(d1x, u), value(d1y, u)}, {value(d2x, u), value(d2y, u)}};
  });
}

/// A t in the monotone piece with c(t) = u, clamped to the piece.
double preimage(const Coeffs& c, ParamInterval piece, double u) {
  const double a = value(c, piece.lo), b = value(c, piece.hi);
  if (u <= min2(a, b)) return a <= b ? piece.lo : piece.hi;
  if (u >= max2(a, b)) return a <= b ? piece.hi : piece.lo;
  return crossing(c, piece.lo, piece.hi, u, kPreimageAccuracy);
}

/// True when f on [t0, t1] lies on g: at 2 (m + n) + 1 points of it, f's point projected
/// onto g (Gauss-Newton from the matching point q^-1(p(t)) of g's piece, within about 1e-9
/// of it; p and q: f's and g's factors) is within coincidence_tolerance of g (which covers
/// the rounding of evaluations in doubles, a few n u of the magnitude).
bool piece_lies_on(const WorkingCurve& f, const WorkingCurve& g, const Coeffs& p, const Coeffs& q,
                   double t0, double t1, ParamInterval s_piece) {
  const double floor = coincidence_tolerance(f, g);
  const int samples = 2 * (f.degree + g.degree) + 1;
  for (int i = 0; i < samples; ++i) {
    const double t = t0 + (t1 - t0) * ((i + 0.5) / samples);
    const Point2 pt = point_of(f, t);
    const auto on_g = [&](double s) {
      const PointAndTangent e = evaluate_with_tangent(g, s);
      return ResidualAndSlope{e.point - pt, e.tangent};
    };
    const double s =
        gauss_newton(preimage(q, s_piece, value(p, t)), kArcNewtonSteps, kArcSampleConverged, on_g);
    const Point2 r = on_g(s).r;
    if (!(std::fabs(r.x) <= floor && std::fabs(r.y) <= floor)) return false;
  }
  return true;
}

/// Which pairs of monotone pieces arc_pieces looks at.
struct PieceSelection {
  /// Only pairs (i, j) with j > i: a curve against itself, each retraced pair once.
  bool later_pieces_only = false;
  /// Only pieces whose boxes meet t_window x s_window.
  ParamInterval t_window{0.0, 1.0};
  ParamInterval s_window{0.0, 1.0};
};

/// What arc_pieces finds: the overlaps to report and the boxes around pieces too short to
/// report (CommonArc::searched), or verified = false when a piece long enough to report
/// failed its verification.
struct ArcPieces {
  bool verified = true;
  std::vector<Overlap> overlaps;
  std::vector<std::pair<ParamInterval, ParamInterval>> searched;
};

/// The overlaps of the pieces of f (t) and g (s) on which arc.p and arc.q are monotone.
ArcPieces arc_pieces(const WorkingCurve& f, const WorkingCurve& g, const CommonArc& arc,
                     const PieceSelection& selection) {
  ArcPieces result;
  const ParamInterval t_window = selection.t_window, s_window = selection.s_window;
  const std::vector<ParamInterval> t_pieces = monotone_pieces(arc.p);
  const std::vector<ParamInterval> s_pieces = monotone_pieces(arc.q);
  const double end_tol = coincidence_tolerance(f, g);
  for (std::size_t i = 0; i < t_pieces.size(); ++i) {
    const ParamInterval I = t_pieces[i];
    const double p0 = value(arc.p, I.lo), p1 = value(arc.p, I.hi);
    for (std::size_t j = selection.later_pieces_only ? i + 1 : 0; j < s_pieces.size(); ++j) {
      const ParamInterval J = s_pieces[j];
      const double q0 = value(arc.q, J.lo), q1 = value(arc.q, J.hi);
      const double p_lo = min2(p0, p1), p_hi = max2(p0, p1);
      const double q_lo = min2(q0, q1), q_hi = max2(q0, q1);
      const double u_lo = max2(p_lo, q_lo), u_hi = min2(p_hi, q_hi);
      if (u_hi < u_lo - kArcSlack) continue;  // the pieces trace different parts of h
      // Each end of the shared range is an end of f's piece (an end of f or a turning point
      // on f) whose point lies on g, or one of g's on f, or both ends at once when their
      // bounds agree (Newton could not move from a turning point). p and q say which; they
      // fit the curves only to the factor's accuracy, so the point pair must agree too, and
      // when it does not, the other curve's end is tried (f's end at the origin on curves 1e9
      // long is not to be paired with g's nearest point 0.99 away:
      // CommonArc.AnOverlapEndsWhereBothCurvesAre).
      const auto agree = [&](double t, double s) {
        const Point2 d = point_of(f, t) - point_of(g, s);
        return std::fabs(d.x) <= end_tol && std::fabs(d.y) <= end_tol;
      };
      double ends_t[2], ends_s[2];
      for (int e = 0; e < 2; ++e) {
        const double u = e == 0 ? u_lo : u_hi;
        const double p_end = e == 0 ? p_lo : p_hi, q_end = e == 0 ? q_lo : q_hi;
        double t_end = (e == 0) == (p0 <= p1) ? I.lo : I.hi;
        if (t_end != 0.0 && t_end != 1.0) t_end = refine_turn(f, t_end);
        double s_end = (e == 0) == (q0 <= q1) ? J.lo : J.hi;
        if (s_end != 0.0 && s_end != 1.0) s_end = refine_turn(g, s_end);
        ends_t[e] = t_end;
        ends_s[e] = s_end;
        if (std::fabs(p_end - q_end) <= kTurnNoise && agree(t_end, s_end)) continue;
        const bool f_first = e == 0 ? p_lo >= q_lo : p_hi <= q_hi;
        bool found = false;
        for (int attempt = 0; attempt < 2 && !found; ++attempt) {
          if ((attempt == 0) == f_first) {
            ends_t[e] = t_end;
            ends_s[e] = locate_on_curve(g, evaluate_dd(f, t_end), preimage(arc.q, J, u));
          } else {
            ends_s[e] = s_end;
            ends_t[e] = locate_on_curve(f, evaluate_dd(g, s_end), preimage(arc.p, I, u));
          }
          found = agree(ends_t[e], ends_s[e]);
        }
        if (!found) return ArcPieces{false, {}, {}};  // neither end lies on the other curve
      }
      const ParamInterval t_range{min2(ends_t[0], ends_t[1]),
                                  max2(ends_t[0], ends_t[1])};
      const ParamInterval s_range{min2(ends_s[0], ends_s[1]),
                                  max2(ends_s[0], ends_s[1])};
      const auto meets = [](ParamInterval a, ParamInterval b, double pad) {
        return a.lo - pad <= b.hi && b.lo <= a.hi + pad;
      };
      if (!meets(t_range, t_window, kShortestOverlap) ||
          !meets(s_range, s_window, kShortestOverlap))
        continue;
      if (!(u_hi - u_lo > kArcSlack) || !(t_range.width() > kShortestOverlap) ||
          !(s_range.width() > kShortestOverlap)) {
        result.searched.push_back({{t_range.lo - kShortestOverlap, t_range.hi + kShortestOverlap},
                                {s_range.lo - kShortestOverlap, s_range.hi + kShortestOverlap}});
        continue;
      }
      // Both ways: a factor that only nearly fits (a curve on a line, taken for a quadratic
      // through a quadratic within the tolerance of the frame's magnitude) misplaces the
      // ends, and only the other curve's points show it (a piece of f beginning at its end
      // point, 8e-8 of the 0.4-long g away from g:
      // CommonArc.ACurveBesideALineSegmentDoesNotOverlapIt).
      if (!piece_lies_on(f, g, arc.p, arc.q, t_range.lo, t_range.hi, J) ||
          !piece_lies_on(g, f, arc.q, arc.p, s_range.lo, s_range.hi, I))
        return ArcPieces{false, {}, {}};
      Overlap o;
      o.t_interval = t_range;
      o.s_interval = s_range;
      o.reversed = (p0 <= p1) != (q0 <= q1);
      result.overlaps.push_back(o);
    }
  }
  return result;
}

/// The overlaps as findings that share their arc.
std::vector<OverlapFinding> findings(std::shared_ptr<const CommonArc> arc,
                                     const std::vector<Overlap>& overlaps) {
  std::vector<OverlapFinding> out;
  for (const Overlap& o : overlaps) {
    OverlapFinding found;
    found.overlap = o;
    found.arc = arc;
    out.push_back(found);
  }
  return out;
}

}  // namespace

std::optional<Factorisation> factorise(const WorkingCurve& c) {
  if (c.is_point || c.degree < 4) return std::nullopt;
  const Coeffs ax = monomial(c.x), ay = monomial(c.y);
  const int n = true_degree(ax, ay, c.magnitude);
  const Coeffs& a =
      std::fabs(ax[static_cast<std::size_t>(n)]) >= std::fabs(ay[static_cast<std::size_t>(n)]) ? ax
                                                                                               : ay;
  const double size = max2(max_abs(ax), max_abs(ay));
  // Every common right factor of x and y is one of the largest (Lüroth), so the first k
  // that works, from the top, is the largest.
  for (int k = n / 2; k >= 2; --k) {
    if (n % k != 0) continue;
    const Monomial p = right_factor(a, n, k);
    if (!is_polynomial_in(ax, n, p, size) || !is_polynomial_in(ay, n, p, size)) continue;
    if (auto found = factor_through(c, p, n / k)) return found;
  }
  return std::nullopt;
}

namespace {

bool same_coefficients(const WorkingCurve& f, const WorkingCurve& g) {
  const auto same = [](const Coeffs& a, const Coeffs& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  };
  return same(f.x, g.x) && same(f.y, g.y) && same(f.x_lo, g.x_lo) && same(f.y_lo, g.y_lo);
}

}  // namespace

std::vector<OverlapFinding> find_arc_overlaps(const WorkingCurve& f, const WorkingCurve& g,
                                              ParamInterval t_window, ParamInterval s_window) {
  if (f.is_point || g.is_point || (f.degree < 4 && g.degree < 4)) return {};
  // A curve against itself (one-curve /intersections certifies its pairs so) is factored once.
  const std::optional<Factorisation> ff = factorise(f);
  const std::optional<Factorisation> fg = same_coefficients(f, g) ? ff : factorise(g);
  if (!ff && !fg) return {};
  const Factorisation a = ff ? *ff : identity(f), b = fg ? *fg : identity(g);
  // h_b(v) = h_a(alpha + beta v), found as find_overlaps finds its map, from the top two
  // monomial coefficients of the dominant coordinate.
  const Coeffs ax = monomial(a.hx), ay = monomial(a.hy), bx = monomial(b.hx), by = monomial(b.hy);
  const double a_size = max2(max_abs(a.hx), max_abs(a.hy));
  const double b_size = max2(max_abs(b.hx), max_abs(b.hy));
  const int d = true_degree(ax, ay, a_size);
  if (d < 2 || d != true_degree(bx, by, b_size)) return {};
  const std::size_t top = static_cast<std::size_t>(d);
  const bool use_x = std::fabs(ax[top]) >= std::fabs(ay[top]);
  const Coeffs& A = use_x ? ax : ay;
  const Coeffs& B = use_x ? bx : by;
  const double r = B[top] / A[top];
  std::vector<double> betas;
  if (d % 2 == 1) {
    betas.push_back(std::copysign(std::pow(std::fabs(r), 1.0 / d), r));
  } else if (r > 0) {
    betas.push_back(std::pow(r, 1.0 / d));
    betas.push_back(-betas.back());
  }
  for (const double beta : betas) {
    const double alpha = (B[top - 1] / std::pow(beta, d - 1) - A[top - 1]) / (d * A[top]);
    if (!std::isfinite(alpha) || !std::isfinite(beta) || beta == 0.0) continue;
    bool same = true;
    for (int i = 0; i <= 4 && same; ++i) {
      const double v = i / 4.0, u = alpha + beta * v;
      same = std::fabs(value(b.hx, v) - value(a.hx, u)) <= kArcFilter * b_size &&
             std::fabs(value(b.hy, v) - value(a.hy, u)) <= kArcFilter * b_size;
    }
    if (!same) continue;
    auto arc = std::make_shared<CommonArc>();
    arc->hx = a.hx;
    arc->hy = a.hy;
    arc->h_magnitude = a_size;
    arc->p = a.p;
    arc->q = b.p;
    for (double& v : arc->q.span()) v = alpha + beta * v;
    ArcPieces pieces = arc_pieces(f, g, *arc, PieceSelection{false, t_window, s_window});
    if (!pieces.verified || pieces.overlaps.empty()) continue;
    arc->searched = std::move(pieces.searched);
    return findings(std::move(arc), pieces.overlaps);
  }
  return {};
}

std::vector<OverlapFinding> find_self_arc_overlaps(const WorkingCurve& c) {
  const std::optional<Factorisation> fc = factorise(c);
  if (!fc) return {};
  auto arc = std::make_shared<CommonArc>();
  arc->hx = fc->hx;
  arc->hy = fc->hy;
  arc->h_magnitude = max2(max_abs(fc->hx), max_abs(fc->hy));
  arc->p = fc->p;
  arc->q = fc->p;
  ArcPieces pieces = arc_pieces(c, c, *arc, PieceSelection{true, {0.0, 1.0}, {0.0, 1.0}});
  if (!pieces.verified) return {};
  arc->searched = std::move(pieces.searched);
  return findings(std::move(arc), pieces.overlaps);
}

bool covered_by_arc(const CommonArc& arc, ParamInterval t, ParamInterval s) {
  for (const auto& [bt, bs] : arc.searched) {
    if (t.lo <= bt.hi && bt.lo <= t.hi && s.lo <= bs.hi && bs.lo <= s.hi) return false;
  }
  const Coeffs pt = bernstein::portion<double>(arc.p, t.lo, t.hi);
  const Coeffs qs = bernstein::portion<double>(arc.q, s.lo, s.hi);
  double lo = pt[0], hi = pt[0];
  for (const double v : pt) lo = min2(lo, v), hi = max2(hi, v);
  for (const double v : qs) lo = min2(lo, v), hi = max2(hi, v);
  return injective_on(arc.hx, arc.hy, arc.h_magnitude, lo - kArcSlack, hi + kArcSlack);
}

bool on_arc_overlap(const CommonArc& arc, const Overlap& overlap, double t, double s) {
  if (t < overlap.t_interval.lo - kOnOverlapSlack || t > overlap.t_interval.hi + kOnOverlapSlack)
    return false;
  if (s < overlap.s_interval.lo - kOnOverlapSlack || s > overlap.s_interval.hi + kOnOverlapSlack)
    return false;
  // p and q are as good as h's interpolation (at degree 20, q(0) can be 1.5e-9 for 0).
  return std::fabs(value(arc.p, t) - value(arc.q, s)) <= kArcSlack;
}

}  // namespace bezier::core
