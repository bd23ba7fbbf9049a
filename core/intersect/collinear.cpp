#include "core/intersect/collinear.hpp"

#include <algorithm>
#include <cmath>

#include "core/bernstein_roots.hpp"
#include "core/intersect/bernstein1d.hpp"
#include "core/intersect/overlap.hpp"

namespace bezier::core {

namespace {

/// Ranges closer than this (in units of the line's parameter, about 1 over the common
/// extent) touch rather than overlap.
constexpr double kTouch = 0x1p-40;

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

std::vector<MonotonePiece> monotone_pieces(const std::vector<double>& u) {
  const std::size_t n = u.size() - 1;
  std::vector<double> breaks = {0.0};
  if (n >= 2) {
    std::vector<double> du(n);
    for (std::size_t i = 0; i < n; ++i) du[i] = u[i + 1] - u[i];
    for (const double r : bernstein_roots(du).roots) {
      if (r > breaks.back() + kTouch && r < 1.0 - kTouch) breaks.push_back(r);
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

/// The parameter in [p.t0, p.t1] where u = w, on a monotone piece (bisection; the ends
/// themselves when w is at or beyond their values).
double invert(const std::vector<double>& u, const MonotonePiece& p, double w) {
  const bool increasing = p.u1 >= p.u0;
  if (increasing ? w <= p.u0 : w >= p.u0) return p.t0;
  if (increasing ? w >= p.u1 : w <= p.u1) return p.t1;
  double a = p.t0, b = p.t1;
  for (int i = 0; i < 200; ++i) {
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

}  // namespace

std::optional<CollinearOutcome> collinear_intersections(const WorkingCurve& f,
                                                        const WorkingCurve& g) {
  const double quick_tol = overlap_tolerance(std::max(f.degree, g.degree));
  if (!roughly_straight(f, quick_tol) || !roughly_straight(g, quick_tol)) return std::nullopt;
  // The line through f's first control point and the control point farthest from it.
  const Point2 origin = {f.x[0], f.y[0]};
  Point2 dir = {0.0, 0.0};
  double best = -1.0;
  for (const WorkingCurve* c : {&f, &g}) {
    for (std::size_t i = 0; i < c->x.size(); ++i) {
      const Point2 v = {c->x[i] - origin.x, c->y[i] - origin.y};
      const double d = std::sqrt(v.x * v.x + v.y * v.y);  // working frame: no overflow
      if (d > best) {
        best = d;
        dir = v;
      }
    }
  }
  if (!(best > 0)) return std::nullopt;
  const double tol = overlap_tolerance(std::max(f.degree, g.degree));
  for (const WorkingCurve* c : {&f, &g}) {
    for (std::size_t i = 0; i < c->x.size(); ++i) {
      const Point2 v = {c->x[i] - origin.x, c->y[i] - origin.y};
      if (std::fabs(cross(dir, v)) / best > tol) return std::nullopt;
    }
  }
  const double dd = dot(dir, dir);
  const std::vector<double> u = positions(f, origin, dir, dd), v = positions(g, origin, dir, dd);
  CollinearOutcome out;
  for (const MonotonePiece& pf : monotone_pieces(u)) {
    for (const MonotonePiece& pg : monotone_pieces(v)) {
      const double w0 = std::max(std::min(pf.u0, pf.u1), std::min(pg.u0, pg.u1));
      const double w1 = std::min(std::max(pf.u0, pf.u1), std::max(pg.u0, pg.u1));
      if (w1 < w0 - kTouch) continue;
      double ta = invert(u, pf, w0), tb = invert(u, pf, w1);
      double sa = invert(v, pg, w0), sb = invert(v, pg, w1);
      // Each end of the shared range is an end of one of the two pieces, where that
      // curve's parameter is exact; the other parameter, from bisection on the rounded
      // positions, is pinned down by Newton's method on the exact point.
      const auto refine = [&](double w, double& t, double& s) {
        const bool from_f = w == pf.u0 || w == pf.u1;
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
        continue;
      }
      // The ranges only touch: one point, unless an overlap already ends there.
      const double tm = ta / 2 + tb / 2, sm = sa / 2 + sb / 2;
      bool known = false;
      for (const Overlap& o : out.overlaps) {
        known = known || ((std::fabs(tm - o.t_interval.lo) <= kTouch ||
                           std::fabs(tm - o.t_interval.hi) <= kTouch) &&
                          (std::fabs(sm - o.s_interval.lo) <= kTouch ||
                           std::fabs(sm - o.s_interval.hi) <= kTouch));
      }
      for (const CollinearContact& c : out.touches) {
        known = known ||
                (std::fabs(tm - c.t_estimate) <= kTouch && std::fabs(sm - c.s_estimate) <= kTouch);
      }
      if (!known)
        out.touches.push_back(
            {{std::min(ta, tb), std::max(ta, tb)}, {std::min(sa, sb), std::max(sa, sb)}, tm, sm});
    }
  }
  // A touch found before the overlap that ends there.
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
  return out;
}

}  // namespace bezier::core
