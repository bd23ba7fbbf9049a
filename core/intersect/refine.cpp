#include "core/intersect/refine.hpp"

#include <algorithm>
#include <cmath>

#include "core/numeric/min_max.hpp"
#include "core/intersect/compensated_point.hpp"
#include "core/intersect/kind.hpp"
#include "core/intersect/tuning.hpp"

namespace bezier::core {

namespace {

using namespace intersect_tuning;

Point2 residual(const WorkingCurve& f, const WorkingCurve& g, double t, double s) {
  const PointDD a = evaluate_dd(f, t), b = evaluate_dd(g, s);
  return {dd::to_double(dd::sub(a.x, b.x)), dd::to_double(dd::sub(a.y, b.y))};
}

double clamp_to(ParamInterval iv, double x) noexcept {
  return std::clamp(x, iv.lo, iv.hi);
}

struct Newton {
  double t = 0.0, s = 0.0;
  int iterations = 0;
  bool converged = false;
  /// f' and g' at the last iterate Newton's method started a step from (within the last
  /// step, at most 2^-40 when converged, of (t, s)).
  Point2 df{}, dg{};
  /// f(t) and g(s) at the final (t, s), by the tangents from that iterate's points.
  Point2 f_point{}, g_point{};
};

/// p + v h rounded once, p in double-double: the point a step h along the tangent v.
Point2 moved(const CompensatedPoint& p, Point2 v, double h) noexcept {
  return {dd::to_double(dd::add(p.x, dd::Real{v.x * h, 0.0})),
          dd::to_double(dd::add(p.y, dd::Real{v.y * h, 0.0}))};
}

/// Newton on f(t) - g(s) = 0 (or Gauss-Newton on one free parameter).
Newton transversal(const WorkingCurve& f, const WorkingCurve& g, const Contact& c, bool t_free,
                   bool s_free) {
  Newton n;
  n.t = c.t.lo + (c.t.hi - c.t.lo) / 2;
  n.s = c.s.lo + (c.s.hi - c.s.lo) / 2;
  if (t_free) n.t = c.t.lo;
  if (s_free) n.s = c.s.lo;
  double last_step = INFINITY;
  for (int i = 0; i < kTransversalIterations; ++i) {
    const CompensatedPoint a = evaluate_compensated(f, n.t), b = evaluate_compensated(g, n.s);
    const Point2 r = {dd::to_double(dd::sub(a.x, b.x)), dd::to_double(dd::sub(a.y, b.y))};
    const Point2 df = a.tangent, dg = b.tangent;
    n.df = df;
    n.dg = dg;
    ++n.iterations;
    double dt = 0.0, ds = 0.0;
    if (t_free) {
      const double gg = dot(dg, dg);
      if (!(gg > 0)) break;
      ds = dot(r, dg) / gg;  // g(s + ds) ~ g(s) + g' ds = P
    } else if (s_free) {
      const double ff = dot(df, df);
      if (!(ff > 0)) break;
      dt = -dot(r, df) / ff;
    } else {
      // f' dt - g' ds = -r by Cramer's rule; det [f', -g'] = -(f' x g').
      const double det = cross(df, dg);
      if (!(det != 0.0)) break;
      dt = -cross(r, dg) / det;
      ds = cross(df, r) / det;
    }
    if (!(std::isfinite(dt) && std::isfinite(ds))) break;
    const double t_before = n.t, s_before = n.s;
    n.t = clamp_to(c.t, n.t + dt);
    n.s = clamp_to(c.s, n.s + ds);
    n.f_point = moved(a, df, n.t - t_before);
    n.g_point = moved(b, dg, n.s - s_before);
    const double step = max2(std::fabs(dt), std::fabs(ds));
    if (step <= kConverged || (step <= kEarlyConverged && sine_between(df, dg) > kSeparatedSine)) {
      n.converged = true;
      break;
    }
    // Stagnation (at the floor of the residual's accuracy, or a clamped step): stop.
    if (step >= last_step && i > kStagnationAfter) break;
    last_step = step;
  }
  return n;
}

/// Newton on cross(f', g') = 0, (f - g) · f' = 0.
Newton tangency(const WorkingCurve& f, const WorkingCurve& g, const Contact& c, double t0,
                double s0) {
  Newton n;
  n.t = t0;
  n.s = s0;
  for (int i = 0; i < kTangencyIterations; ++i) {
    const PointAndTangent ft = evaluate_with_tangent(f, n.t), gt = evaluate_with_tangent(g, n.s);
    const Point2 r = residual(f, g, n.t, n.s);
    const Point2 ddf = second_derivative(f, n.t), ddg = second_derivative(g, n.s);
    const Point2 df = ft.tangent, dg = gt.tangent;
    ++n.iterations;
    const double F1 = cross(df, dg), F2 = dot(r, df);
    const double a11 = cross(ddf, dg), a12 = cross(df, ddg);
    const double a21 = dot(df, df) + dot(r, ddf), a22 = -dot(dg, df);
    const double det = a11 * a22 - a12 * a21;
    if (!(det != 0.0) || !std::isfinite(det)) break;
    const double dt = -(F1 * a22 - a12 * F2) / det;
    const double ds = -(a11 * F2 - a21 * F1) / det;
    if (!(std::isfinite(dt) && std::isfinite(ds))) break;
    n.t = clamp_to(c.t, n.t + dt);
    n.s = clamp_to(c.s, n.s + ds);
    if (max2(std::fabs(dt), std::fabs(ds)) <= kConverged) {
      n.converged = true;
      break;
    }
  }
  return n;
}

}  // namespace

Refinement refine_contact(const WorkingCurve& f, const WorkingCurve& g, const Contact& contact,
                          bool t_free, bool s_free, double tangent_sine) {
  if (contact.exact) {
    Refinement exact;
    exact.t = contact.exact_root.t;
    exact.s = contact.exact_root.s;
    return exact;
  }
  const Newton n = transversal(f, g, contact, t_free, s_free);
  Refinement out;
  out.t = n.t;
  out.s = n.s;
  out.iterations = n.iterations;
  if (t_free || s_free) return out;
  // Converged: the last step moved (t, s) by at most 2^-40, which changes the angle by far
  // less than the threshold's precision.
  if (n.converged && sine_between(n.df, n.dg) > tangent_sine) {
    out.f_at_t = PointAndTangent{n.f_point, n.df};
    out.g_at_s = PointAndTangent{n.g_point, n.dg};
    return out;
  }
  const Newton tn = tangency(f, g, contact, n.t, n.s);
  out.iterations += tn.iterations;
  if (tn.converged) {
    out.t = tn.t;
    out.s = tn.s;
    out.tangency_system = true;
  }
  return out;
}

}  // namespace bezier::core
