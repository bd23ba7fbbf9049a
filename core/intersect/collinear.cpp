#include "core/intersect/collinear.hpp"

#include <algorithm>
#include <cmath>

#include "core/bernstein/roots.hpp"
#include "core/bernstein/bernstein1d.hpp"
#include "core/bernstein/tuning.hpp"
#include "core/intersect/overlap.hpp"
#include "core/intersect/tuning.hpp"

namespace bezier::core {

using intersect_tuning::kTouch;

namespace {

struct MonotonePiece {
  double t0, t1;  ///< parameter interval
  double u0, u1;  ///< u(t0), u(t1)
};

std::vector<double> positions(const WorkingCurve& c, Point2 origin, Point2 dir, double dd) {
  std::vector<double> u;
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    u.push_back(((c.x[i] - origin.x) * dir.x + (c.y[i] - origin.y) * dir.y) / dd);
  }
  return u;
}

int sign_of(double v) noexcept {
  return (v > 0.0) - (v < 0.0);
}

/// u cut into monotone pieces at its turning points: the roots of u' where u' changes sign.
/// A root of even multiplicity is no turning point; a double root that is not an exact zero
/// of u' (as at an end where P0 and P1 nearly coincide) is known only to about the square
/// root of u''s rounding, and bernstein_roots may report it a few 1e-8 inside the interval:
/// cutting there would leave a sliver of a piece whose range only touches the other curve's
/// (as at the flat end in Collinear.OverlapReachesAFlatEnd).
std::vector<MonotonePiece> monotone_pieces(const std::vector<double>& u) {
  const std::size_t n = u.size() - 1;
  std::vector<double> breaks = {0.0};
  if (n >= 2) {
    std::vector<double> du(n);
    for (std::size_t i = 0; i < n; ++i) du[i] = u[i + 1] - u[i];
    std::vector<double> cuts = {0.0};
    for (const double r : bernstein_roots(du).roots) {
      if (r > cuts.back() + kTouch && r < 1.0 - kTouch) cuts.push_back(r);
    }
    cuts.push_back(1.0);
    // The sign of u' between consecutive roots; a cut stays where it changes (zero: u is
    // flat there, part of either neighbour).
    int running = 0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const int sign = sign_of(bernstein::evaluate(du, cuts[i] + (cuts[i + 1] - cuts[i]) / 2));
      if (sign != 0 && running != 0 && sign != running) breaks.push_back(cuts[i]);
      if (sign != 0) running = sign;
    }
  }
  breaks.push_back(1.0);
  std::vector<MonotonePiece> pieces;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    pieces.push_back({breaks[i], breaks[i + 1], bernstein::evaluate(u, breaks[i]),
                      bernstein::evaluate(u, breaks[i + 1])});
  }
  return pieces;
}

/// Whether the piece's range is a single position to within kTouch: all of it touches.
bool flat(const MonotonePiece& p) noexcept {
  return std::fabs(p.u1 - p.u0) <= kTouch;
}

/// The midpoint of [min(a, b), max(a, b)], inside it even for subnormal ends (a / 2 + b / 2
/// rounds 3 * 2^-1074 / 2 to 2^-1073: Collinear.SubnormalEstimateInsideItsInterval).
double middle(double a, double b) noexcept {
  const double lo = std::min(a, b), hi = std::max(a, b);
  return lo + (hi - lo) / 2;
}

/// The parameter in [p.t0, p.t1] where u = w, on a monotone piece (bisection; the ends
/// themselves when w is at or beyond their values).
double invert(const std::vector<double>& u, const MonotonePiece& p, double w) {
  const bool increasing = p.u1 >= p.u0;
  if (increasing ? w <= p.u0 : w >= p.u0) return p.t0;
  if (increasing ? w >= p.u1 : w <= p.u1) return p.t1;
  double a = p.t0, b = p.t1;
  for (int i = 0; i < bernstein_tuning::kBisectionSteps; ++i) {
    const double m = a + (b - a) / 2;
    if (!(a < m && m < b)) break;
    const double v = bernstein::evaluate(u, m);
    if ((v < w) == increasing)
      a = m;
    else
      b = m;
  }
  return a + (b - a) / 2;
}

/// A quick necessary test without square roots: every control point of c within 2 tol of
/// the line through its first control point and the one farthest from it (the main test
/// below uses the same construction over both curves, whose line is within tol of all).
bool roughly_straight(const WorkingCurve& c, double tol) noexcept {
  const std::size_t n = c.x.size() - 1;
  Point2 d = {0.0, 0.0};
  double dd = 0.0;
  for (std::size_t i = 1; i <= n; ++i) {
    const Point2 v = {c.x[i] - c.x[0], c.y[i] - c.y[0]};
    if (dot(v, v) > dd) {
      dd = dot(v, v);
      d = v;
    }
  }
  if (dd == 0.0) return true;
  for (std::size_t i = 1; i < n; ++i) {
    const double cr = cross(d, Point2{c.x[i] - c.x[0], c.y[i] - c.y[0]});
    if (cr * cr > 4 * tol * tol * dd) return false;
  }
  return true;
}

/// The corners of an overlap's box that are its ends: (t.lo, s.lo) and (t.hi, s.hi), or the
/// other diagonal when reversed.
struct OverlapEnd {
  double* t;
  double* s;
};

/// Makes an exact root part of the answer: an overlap end or a touch within kTouch of it is
/// moved onto it (the bisection and Newton put ends within rounding of it, not on it);
/// otherwise it is a contact of its own.
void hold_exact_root(CollinearOutcome& out, ExactRoot r) {
  for (Overlap& o : out.overlaps) {
    const OverlapEnd ends[2] = {
        {&o.t_interval.lo, o.reversed ? &o.s_interval.hi : &o.s_interval.lo},
        {&o.t_interval.hi, o.reversed ? &o.s_interval.lo : &o.s_interval.hi}};
    for (const OverlapEnd& e : ends) {
      if (std::fabs(*e.t - r.t) <= kTouch && std::fabs(*e.s - r.s) <= kTouch) {
        *e.t = r.t;
        *e.s = r.s;
        return;
      }
    }
    if (o.t_interval.contains(r.t) && o.s_interval.contains(r.s)) return;
  }
  for (CollinearContact& c : out.touches) {
    const bool near_t = r.t >= c.t.lo - kTouch && r.t <= c.t.hi + kTouch;
    const bool near_s = r.s >= c.s.lo - kTouch && r.s <= c.s.hi + kTouch;
    if (near_t && near_s) {
      c.t = {std::min(c.t.lo, r.t), std::max(c.t.hi, r.t)};
      c.s = {std::min(c.s.lo, r.s), std::max(c.s.hi, r.s)};
      c.t_estimate = r.t;
      c.s_estimate = r.s;
      return;
    }
  }
  out.touches.push_back({{r.t, r.t}, {r.s, r.s}, r.t, r.s});
}

/// The line both curves lie on, from `origin` towards `far` (dir = far - origin, of length
/// `length` > 0).
struct CommonLine {
  Point2 origin, dir;
  double length;
};

/// The line through the two control points farthest apart, of both curves, from the
/// lexicographically smaller, when every control point of f and of g lies within
/// coincidence_tolerance of it; nullopt otherwise (or when all control points are one).
/// The same line whichever curve comes first (from f's first control point, the decision
/// near the tolerance would depend on the order:
/// Collinear.NearlyCollinearCurvesOfDifferentSizesCrossOnce). The tolerance is relative to
/// the smaller curve, as the overlap tests': a curve about 2^-14 the size of the other and
/// bent by 4e-9 of its own size lies within the frame's tolerance of the other's line, and
/// its end 1e-4 off that line is no touch
/// (Collinear.ASmallCurveBentAboveItsRoundingIsNotOnALargeCurvesLine).
std::optional<CommonLine> common_line(const WorkingCurve& f, const WorkingCurve& g) {
  const double quick_tol = coincidence_tolerance_bound(f, g);
  if (!roughly_straight(f, quick_tol) || !roughly_straight(g, quick_tol)) return std::nullopt;
  const double tol = coincidence_tolerance(f, g);
  std::vector<Point2> all;
  for (const WorkingCurve* c : {&f, &g}) {
    for (std::size_t i = 0; i < c->x.size(); ++i) all.push_back({c->x[i], c->y[i]});
  }
  const auto before = [](Point2 a, Point2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; };
  std::sort(all.begin(), all.end(), before);
  Point2 origin = all.front(), far = all.front();
  double best = -1.0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      const Point2 v = all[j] - all[i];
      const double d = std::sqrt(v.x * v.x + v.y * v.y);  // working frame: no overflow
      if (d > best) {  // the first of equal pairs in sorted order: no dependence on input order
        best = d;
        origin = all[i];
        far = all[j];
      }
    }
  }
  const Point2 dir = far - origin;
  if (!(best > 0)) return std::nullopt;
  for (const WorkingCurve* c : {&f, &g}) {
    for (std::size_t i = 0; i < c->x.size(); ++i) {
      const Point2 v = {c->x[i] - origin.x, c->y[i] - origin.y};
      if (std::fabs(cross(dir, v)) / best > tol) return std::nullopt;
    }
  }
  return CommonLine{origin, dir, best};
}

/// The positions along the common line (u of f, v of g) and one monotone piece of each.
struct PiecePair {
  const std::vector<double>& u;
  const std::vector<double>& v;
  const MonotonePiece& pf;
  const MonotonePiece& pg;
};

/// Where the ranges of two pieces only touch (their shared range [w0, w1] no longer than
/// kTouch), with (ta, sa) and (tb, sb) the parameters at its ends: one contact in `out`,
/// unless an overlap or a contact already found is there (within kTouch of its middle). A
/// flat piece touches with all of its parameters (a curve within the line tolerance of a
/// point: Collinear.EndPointRootOfATinyCurveIsReported), and the other curve's parameters
/// are those of its two ends (its positions, rounded, may be one number, while its exact
/// points are not).
void add_touch(const WorkingCurve& f, const WorkingCurve& g, const PiecePair& p, double ta,
               double tb, double sa, double sb, CollinearOutcome& out) {
  const MonotonePiece &pf = p.pf, &pg = p.pg;
  if (flat(pf) && !flat(pg)) {
    ta = pf.t0;
    tb = pf.t1;
    sa = locate_on_curve(g, evaluate_dd(f, ta), invert(p.v, pg, pf.u0));
    sb = locate_on_curve(g, evaluate_dd(f, tb), invert(p.v, pg, pf.u1));
  } else if (flat(pg) && !flat(pf)) {
    sa = pg.t0;
    sb = pg.t1;
    ta = locate_on_curve(f, evaluate_dd(g, sa), invert(p.u, pf, pg.u0));
    tb = locate_on_curve(f, evaluate_dd(g, sb), invert(p.u, pf, pg.u1));
  } else if (flat(pf) && flat(pg)) {
    ta = pf.t0, tb = pf.t1, sa = pg.t0, sb = pg.t1;
  }
  const ParamInterval t_iv{std::min(ta, tb), std::max(ta, tb)};
  const ParamInterval s_iv{std::min(sa, sb), std::max(sa, sb)};
  const double tm = middle(t_iv.lo, t_iv.hi), sm = middle(s_iv.lo, s_iv.hi);
  bool known = false;
  for (const Overlap& o : out.overlaps) {
    known =
        known ||
        ((std::fabs(tm - o.t_interval.lo) <= kTouch || std::fabs(tm - o.t_interval.hi) <= kTouch) &&
         (std::fabs(sm - o.s_interval.lo) <= kTouch || std::fabs(sm - o.s_interval.hi) <= kTouch));
  }
  for (const CollinearContact& c : out.touches) {
    known =
        known || (std::fabs(tm - c.t_estimate) <= kTouch && std::fabs(sm - c.s_estimate) <= kTouch);
  }
  if (!known) out.touches.push_back({t_iv, s_iv, tm, sm});
}

/// What a monotone piece of f and one of g share: nothing when their ranges of positions
/// are more than kTouch apart; an overlap in `out` when they share more than kTouch;
/// otherwise a touch (add_touch). The parameters of the shared range's ends come from
/// bisection on the pieces (invert); each end is an end of one of the two pieces, where
/// that curve's parameter is exact, and the other parameter, from bisection on the rounded
/// positions, is pinned down by Newton's method on the exact point. When it is an end of
/// both, both parameters are exact: moving either would depend on which curve comes first
/// (Collinear.ATouchAtTwoEndsIsTheSameInBothOrders).
void add_shared_range(const WorkingCurve& f, const WorkingCurve& g, const PiecePair& p,
                      CollinearOutcome& out) {
  const MonotonePiece &pf = p.pf, &pg = p.pg;
  const double w0 = std::max(std::min(pf.u0, pf.u1), std::min(pg.u0, pg.u1));
  const double w1 = std::min(std::max(pf.u0, pf.u1), std::max(pg.u0, pg.u1));
  if (w1 < w0 - kTouch) return;
  double ta = invert(p.u, pf, w0), tb = invert(p.u, pf, w1);
  double sa = invert(p.v, pg, w0), sb = invert(p.v, pg, w1);
  const auto refine = [&](double w, double& t, double& s) {
    const bool from_f = w == pf.u0 || w == pf.u1, from_g = w == pg.u0 || w == pg.u1;
    if (from_f && from_g) return;
    if (from_f) {
      s = locate_on_curve(g, evaluate_dd(f, t), s);
    } else {
      t = locate_on_curve(f, evaluate_dd(g, s), t);
    }
  };
  refine(w0, ta, sa);
  refine(w1, tb, sb);
  if (w1 - w0 > kTouch) {
    Overlap o;
    o.t_interval = {std::min(ta, tb), std::max(ta, tb)};
    o.s_interval = {std::min(sa, sb), std::max(sa, sb)};
    o.reversed = (ta > tb) != (sa > sb);
    out.overlaps.push_back(o);
    return;
  }
  add_touch(f, g, p, ta, tb, sa, sb, out);
}

/// Drops each touch found before the overlap that ends there (its estimates within kTouch
/// of an end of the overlap's intervals in both t and s).
void drop_touches_at_overlap_ends(CollinearOutcome& out) {
  std::erase_if(out.touches, [&](const CollinearContact& c) {
    for (const Overlap& o : out.overlaps) {
      const bool t_end = std::fabs(c.t_estimate - o.t_interval.lo) <= kTouch ||
                         std::fabs(c.t_estimate - o.t_interval.hi) <= kTouch;
      const bool s_end = std::fabs(c.s_estimate - o.s_interval.lo) <= kTouch ||
                         std::fabs(c.s_estimate - o.s_interval.hi) <= kTouch;
      if (t_end && s_end) return true;
    }
    return false;
  });
}

}  // namespace

std::optional<CollinearOutcome> collinear_intersections(const WorkingCurve& f,
                                                        const WorkingCurve& g,
                                                        std::span<const ExactRoot> exact_roots) {
  const std::optional<CommonLine> line = common_line(f, g);
  if (!line) return std::nullopt;
  const double dd = dot(line->dir, line->dir);
  const std::vector<double> u = positions(f, line->origin, line->dir, dd);
  const std::vector<double> v = positions(g, line->origin, line->dir, dd);
  CollinearOutcome out;
  const std::vector<MonotonePiece> f_pieces = monotone_pieces(u), g_pieces = monotone_pieces(v);
  for (const MonotonePiece& pf : f_pieces) {
    for (const MonotonePiece& pg : g_pieces) add_shared_range(f, g, {u, v, pf, pg}, out);
  }
  drop_touches_at_overlap_ends(out);
  for (const ExactRoot& r : exact_roots) hold_exact_root(out, r);
  return out;
}

}  // namespace bezier::core
