#include "core/self_intersect/refine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/self_intersect/tuning.hpp"

namespace bezier::core {

namespace {

using self_intersect_tuning::kConvergedStep;

/// The jet from coordinate rows x, y (overwritten), count = n + 1 entries each. Rows of
/// plain doubles rather than Point2 so that the inline buffers need no initialisation.
CurveJet jet_in(double* x, double* y, std::size_t count, double t) {
  const std::size_t n = count - 1;
  const double dn = static_cast<double>(n);
  const double s = 1.0 - t;
  CurveJet jet{{x[0], y[0]}, {}, {}};
  if (n == 0) return jet;
  // Reduce to three entries (two for n = 1), then read the derivatives off the last rows.
  // (1 - t) a + t b as in lerp(), so the point agrees with evaluate()'s plain row.
  for (std::size_t level = n; level > 2; --level) {
    for (std::size_t i = 0; i < level; ++i) {
      x[i] = s * x[i] + t * x[i + 1];
      y[i] = s * y[i] + t * y[i + 1];
    }
  }
  if (n >= 2) {
    const double k = dn * (dn - 1.0);
    jet.d2 = {k * ((x[2] - x[1]) - (x[1] - x[0])), k * ((y[2] - y[1]) - (y[1] - y[0]))};
    x[0] = s * x[0] + t * x[1];
    y[0] = s * y[0] + t * y[1];
    x[1] = s * x[1] + t * x[2];
    y[1] = s * y[1] + t * y[2];
  }
  jet.d1 = {dn * (x[1] - x[0]), dn * (y[1] - y[0])};
  jet.point = {s * x[0] + t * x[1], s * y[0] + t * y[1]};
  return jet;
}

/// What every iteration of both refinements starts from: the jets at u and v, F = B(v) -
/// B(u) and |F|.
struct PairJets {
  CurveJet at_u;
  CurveJet at_v;
  Point2 f;
  double residual;
};

[[gnu::always_inline]] inline PairJets pair_jets(std::span<const Point2> points, double u, double v) {
  const CurveJet ju = curve_jet(points, u);
  const CurveJet jv = curve_jet(points, v);
  const Point2 f = jv.point - ju.point;
  return {ju, jv, f, norm(f)};
}

/// The best iterate before the first: any residual beats it.
PairRefinement no_iterate_yet() {
  PairRefinement best;
  best.residual = std::numeric_limits<double>::infinity();
  return best;
}

/// Both refinements return, when they do not converge, the iterate with the smallest |F|
/// (the later one on a tie).
void keep_if_best(PairRefinement& best, double u, double v, double residual, int iteration) {
  if (residual <= best.residual) best = {u, v, residual, false, iteration};
}

bool inside(double u, double v, const ParameterBox& box) {
  return box.u.contains(u) && box.v.contains(v);
}

}  // namespace

CurveJet curve_jet(std::span<const Point2> points, double t) {
  constexpr std::size_t kInline = 32;
  const std::size_t count = points.size();
  if (count == 4) {
    // Cubics written out (the closed-form fast path's budget is a few hundred
    // nanoseconds); the same lerp and difference sequence as jet_in.
    const double s = 1.0 - t;
    const Point2 a = s * points[0] + t * points[1], b = s * points[1] + t * points[2],
                 c = s * points[2] + t * points[3];
    const Point2 d = s * a + t * b, e = s * b + t * c;
    return {s * d + t * e, 3.0 * (e - d), 6.0 * ((c - b) - (b - a))};
  }
  if (count <= kInline) {
    double x[kInline], y[kInline];
    for (std::size_t i = 0; i < count; ++i) {
      x[i] = points[i].x;
      y[i] = points[i].y;
    }
    return jet_in(x, y, count, t);
  }
  std::vector<double> x(count), y(count);
  for (std::size_t i = 0; i < count; ++i) {
    x[i] = points[i].x;
    y[i] = points[i].y;
  }
  return jet_in(x.data(), y.data(), count, t);
}

PairRefinement refine_double_point(std::span<const Point2> points, double u0, double v0,
                                   ParameterBox box, double rounding, int max_iterations) {
  PairRefinement best = no_iterate_yet();
  double u = u0, v = v0;
  for (int it = 0; it <= max_iterations; ++it) {
    const auto [ju, jv, f, residual] = pair_jets(points, u, v);
    keep_if_best(best, u, v, residual, it);
    if (residual == 0.0) return {u, v, 0.0, true, it};
    // -B'(u) du + B'(v) dv = -F, by Cramer's rule.
    const Point2 a = -ju.d1;
    const double det = cross(a, jv.d1);
    if (!(std::isfinite(det)) || det == 0.0) return best;
    const double du = cross(-f, jv.d1) / det;
    const double dv = cross(a, -f) / det;
    if (!(std::isfinite(du) && std::isfinite(dv))) return best;
    u += du;
    v += dv;
    if (!inside(u, v, box)) return best;
    const double floor =
        rounding * std::numbers::sqrt2 * std::max(norm(ju.d1), norm(jv.d1)) / std::fabs(det);
    const double small = std::max(kConvergedStep, 4.0 * floor);
    // A step at the noise floor leaves an error of order step^2 (or of the noise): done.
    // The residual reported is the one before the step, an upper bound up to rounding.
    if (std::fabs(du) <= small && std::fabs(dv) <= small) return {u, v, residual, true, it + 1};
  }
  return best;
}

double double_point_uncertainty(std::span<const Point2> points, double u, double v,
                                double rounding) {
  const Point2 tu = curve_jet(points, u).d1;
  const Point2 tv = curve_jet(points, v).d1;
  const double det = std::fabs(cross(tu, tv));
  if (det == 0.0) return std::numeric_limits<double>::infinity();
  return rounding * std::numbers::sqrt2 * std::max(norm(tu), norm(tv)) / det;
}

bool is_resolved_double_point(std::span<const Point2> points, double u, double v, double rounding,
                              bool closed) {
  return double_point_uncertainty(points, u, v, rounding) <
         self_intersect_tuning::kResolvedFraction * parameter_separation(u, v, closed);
}

PairRefinement refine_self_contact(std::span<const Point2> points, double u0, double v0,
                                   ParameterBox box, int max_iterations) {
  PairRefinement best = no_iterate_yet();
  double u = std::clamp(u0, box.u.lo, box.u.hi), v = std::clamp(v0, box.v.lo, box.v.hi);
  bool done = false;
  for (int it = 0; it <= max_iterations; ++it) {
    const auto [ju, jv, f, residual] = pair_jets(points, u, v);
    keep_if_best(best, u, v, residual, it);
    if (done || residual == 0.0) {
      best.converged = true;
      best.iterations = it;
      return best;
    }
    // G = (F·B'(v), cross(B'(u), B'(v))) and its Jacobian (see the header).
    const double g1 = dot(f, jv.d1);
    const double g2 = cross(ju.d1, jv.d1);
    const double j11 = -dot(ju.d1, jv.d1);
    const double j12 = dot(jv.d1, jv.d1) + dot(f, jv.d2);
    const double j21 = cross(ju.d2, jv.d1);
    const double j22 = cross(ju.d1, jv.d2);
    const double det = j11 * j22 - j12 * j21;
    if (!(std::isfinite(det)) || det == 0.0) return best;
    const double du = (-g1 * j22 + g2 * j12) / det;
    const double dv = (-g2 * j11 + g1 * j21) / det;
    if (!(std::isfinite(du) && std::isfinite(dv))) return best;
    const double nu = std::clamp(u + du, box.u.lo, box.u.hi);
    const double nv = std::clamp(v + dv, box.v.lo, box.v.hi);
    const bool tiny = std::fabs(nu - u) <= kConvergedStep && std::fabs(nv - v) <= kConvergedStep;
    u = nu;
    v = nv;
    done = tiny;
  }
  return best;
}

}  // namespace bezier::core
