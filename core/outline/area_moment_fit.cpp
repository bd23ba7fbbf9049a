#include "core/outline/area_moment_fit.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/multiversion.hpp"
#include "core/numeric/quadratic_roots.hpp"

namespace bezier::outline {

namespace {

// Handle lengths in chords: a step of 1e-12 moves the cubic by far less than any tolerance
// accepted; the zeros of q' only separate the roots, and need less.
constexpr double kRootResolution = 1e-12;
constexpr double kTurnResolution = 1e-6;
constexpr double kTouch = 1e-3;
constexpr int kArcNewtonSteps = 12;

/// A polynomial of degree <= 4 in monomial form, c[i] the coefficient of x^i.
struct Quartic {
  std::array<double, 5> c{};

  [[nodiscard]] double at(double x) const {
    return c[0] + x * (c[1] + x * (c[2] + x * (c[3] + x * c[4])));
  }
  [[nodiscard]] Quartic derivative() const {
    return {{c[1], 2.0 * c[2], 3.0 * c[3], 4.0 * c[4], 0.0}};
  }
};

/// The root of p in [lo, hi] where p(lo) and p(hi) have opposite signs and p is monotone:
/// Newton steps from the secant's root, each replaced by the bisection when it leaves the
/// bracket, which shrinks with every evaluated sign, until a step is below `resolution`.
double bracketed_root(const Quartic& p, const Quartic& dp, double lo, double hi, double p_lo,
                      double p_hi, double resolution) {
  double x = lo + (hi - lo) * (p_lo / (p_lo - p_hi));
  if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
  for (int i = 0; i < 64; ++i) {
    const double v = p.at(x);
    if (v == 0.0) return x;
    if ((v < 0.0) == (p_lo < 0.0)) {
      lo = x;
    } else {
      hi = x;
    }
    const double slope = dp.at(x);
    double next = slope != 0.0 ? x - v / slope : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - x) <= resolution || hi - lo <= resolution) return next;
    x = next;
  }
  return x;
}

/// Up to four points of [lo, hi], ascending.
struct Points {
  std::array<double, 4> at{};
  std::size_t count = 0;
  void add(double x) {
    if (count < at.size() && (count == 0 || at[count - 1] < x)) at[count++] = x;
  }
};

/// The roots of p in [lo, hi] given the zeros of p' there (`turns`, ascending): p is
/// monotone between them, so each stretch holds at most one root, bracketed by a change of
/// sign. With `touches`, also the zeros of p' where p comes within kTouch (of its largest
/// coefficient in size) of zero without crossing it.
Points monotone_roots(const Quartic& p, const Points& turns, double lo, double hi,
                      double resolution, Points* touches) {
  const Quartic dp = p.derivative();
  double size = 0.0;
  for (const double v : p.c) size = std::max(size, std::fabs(v));
  Points roots;
  double left = lo, p_left = p.at(lo);
  if (p_left == 0.0) roots.add(lo);
  for (std::size_t i = 0; i <= turns.count; ++i) {
    const double right = i < turns.count ? turns.at[i] : hi;
    const double p_right = p.at(right);
    if (p_right == 0.0) {
      roots.add(right);
    } else if (p_left != 0.0 && (p_left < 0.0) != (p_right < 0.0)) {
      roots.add(bracketed_root(p, dp, left, right, p_left, p_right, resolution));
    } else if (touches != nullptr && i < turns.count && std::fabs(p_right) <= kTouch * size) {
      touches->add(right);
    }
    left = right;
    p_left = p_right;
  }
  return roots;
}

/// The roots in (lo, hi) of c0 + c1 x + c2 x^2, ascending.
Points quadratic_roots_in(double c0, double c1, double c2, double lo, double hi) {
  Points roots;
  const double size = std::max({std::fabs(c0), std::fabs(c1), std::fabs(c2)});
  if (std::fabs(c2) <= 1e-14 * size) {
    if (c1 != 0.0) {
      const double x = -c0 / c1;
      if (x > lo && x < hi) roots.add(x);
    }
    return roots;
  }
  const double disc = c1 * c1 - 4.0 * c2 * c0;
  if (disc < 0.0) return roots;
  const core::RootPair r = core::quadratic_roots(c2, c1, c0, disc);
  if (r.lo > lo && r.lo < hi) roots.add(r.lo);
  if (r.hi > lo && r.hi < hi) roots.add(r.hi);
  return roots;
}


/// The quartic q(a) = D^2 (M(a, b(a)) - moment) of area_moment_fit.hpp and the map a -> b.
struct AreaMomentSystem {
  Quartic q;
  double n0 = 0.0, n1 = 0.0, e0 = 0.0, e1 = 0.0;  // N = n0 + n1 a, D = e0 + e1 a
  bool valid = false;

  AreaMomentSystem(core::Point2 t0, core::Point2 t3, double area, double moment) {
    const double c0 = t0.x, s0 = t0.y, c3 = t3.x, s3 = t3.y;
    const double k = s0 * c3 - c0 * s3;
    // M(a, b) = Σ m_pq a^p b^q (area_moment_fit.hpp).
    const double m10 = 17.0 / 140.0 * s0, m01 = -5.0 / 28.0 * s3;
    const double m20 = 3.0 / 56.0 * c0 * s0, m02 = 3.0 / 56.0 * c3 * s3;
    const double m11 = 9.0 / 280.0 * c0 * s3 - 33.0 / 280.0 * s0 * c3;
    const double m21 = -9.0 / 280.0 * c0 * k, m12 = 9.0 / 280.0 * c3 * k;
    n0 = -20.0 / 3.0 * area;
    n1 = 2.0 * s0;
    e0 = 2.0 * s3;
    e1 = k;
    // D^2 (M - moment) = (m10 a + m20 a^2 - moment) D^2 + (m01 + m11 a + m21 a^2) N D
    //                    + (m02 + m12 a) N^2.
    const std::array<double, 3> dd{e0 * e0, 2.0 * e0 * e1, e1 * e1};
    const std::array<double, 3> nd{n0 * e0, n0 * e1 + n1 * e0, n1 * e1};
    const std::array<double, 3> nn{n0 * n0, 2.0 * n0 * n1, n1 * n1};
    const std::array<double, 3> first{-moment, m10, m20}, second{m01, m11, m21};
    const std::array<double, 2> third{m02, m12};
    for (std::size_t i = 0; i < 3; ++i) {
      for (std::size_t j = 0; j < 3; ++j) {
        q.c[i + j] += first[i] * dd[j] + second[i] * nd[j];
        if (i < 2) q.c[i + j] += third[i] * nn[j];
      }
    }
    double largest = 0.0;
    for (const double v : q.c) largest = std::max(largest, std::fabs(v));
    valid = largest > 0.0 && std::isfinite(largest);
  }

  /// The pair for a, when D(a) is clear of zero and both handles are in [0, kMaxHandle].
  [[nodiscard]] bool pair(double a, HandleLengths& out) const {
    if (!(a >= 0.0 && a <= kMaxHandle)) return false;
    const double den = e0 + e1 * a;
    if (!(std::fabs(den) > 1e-9 * (std::fabs(e0) + std::fabs(e1) * kMaxHandle))) return false;
    const double b = (n0 + n1 * a) / den;
    if (!(b >= 0.0 && b <= kMaxHandle)) return false;
    out = {a, b};
    return true;
  }
};

}  // namespace

BEZIER_FMA_CLONES HandleCandidates area_moment_handles(core::Point2 t0, core::Point2 t3,
                                                       double area, double moment) {
  HandleCandidates result;
  const AreaMomentSystem system(t0, t3, area, moment);
  if (!system.valid) return result;
  // The zeros of q'' (closed form), then of q' and of q between them.
  const Quartic& q = system.q;
  const Quartic q1 = q.derivative(), q2 = q1.derivative();
  const Points bends = quadratic_roots_in(q2.c[0], q2.c[1], q2.c[2], 0.0, kMaxHandle);
  const Points turns = monotone_roots(q1, bends, 0.0, kMaxHandle, kTurnResolution, nullptr);
  Points touches;
  const Points exact = monotone_roots(q, turns, 0.0, kMaxHandle, kRootResolution, &touches);
  auto add = [&](double a) {
    HandleLengths pair;
    if (result.count < result.pairs.size() && system.pair(a, pair)) result.pairs[result.count++] = pair;
  };
  for (std::size_t i = 0; i < exact.count; ++i) add(exact.at[i]);
  for (std::size_t i = 0; i < touches.count; ++i) add(touches.at[i]);
  return result;
}

namespace {

/// The start of arc_started_handles' Newton steps: both handles of the circular arc through
/// the ends with these tangents, turning by φ, are 1 / (3 cos^2(φ / 4)) chords:
/// cos^2(φ / 4) = (1 + cos(φ / 2)) / 2, cos(φ / 2) = sqrt((1 + cos φ) / 2), cos φ = t0 · t3.
double arc_handle(core::Point2 t0, core::Point2 t3) {
  const double half = std::sqrt(std::max(0.0, 0.5 * (1.0 + core::dot(t0, t3))));
  return 2.0 / (3.0 * (1.0 + half));
}

/// Where a Newton walk of arc_started_handles stands.
enum class Walk { stepping, found, failed };

/// One Newton step of arc_started_handles from a on the system's quartic q (dq its
/// derivative): found (out set) once a step is within kRootResolution, failed where the slope
/// vanishes, the step leaves [0, kMaxHandle] or the pair is refused.
Walk arc_newton_step(const AreaMomentSystem& system, const Quartic& dq, double& a,
                     HandleLengths& out) {
  const double slope = dq.at(a);
  if (!(slope != 0.0)) return Walk::failed;
  const double step = system.q.at(a) / slope;
  a -= step;
  if (!(a >= 0.0 && a <= kMaxHandle)) return Walk::failed;
  if (std::fabs(step) <= kRootResolution) return system.pair(a, out) ? Walk::found : Walk::failed;
  return Walk::stepping;
}

}  // namespace

BEZIER_FMA_CLONES bool arc_started_handles(core::Point2 t0, core::Point2 t3, double area,
                                           double moment, HandleLengths& out) {
  const AreaMomentSystem system(t0, t3, area, moment);
  if (!system.valid) return false;
  double a = arc_handle(t0, t3);
  const Quartic dq = system.q.derivative();
  for (int i = 0; i < kArcNewtonSteps; ++i) {
    const Walk walk = arc_newton_step(system, dq, a, out);
    if (walk != Walk::stepping) return walk == Walk::found;
  }
  return false;
}

BEZIER_FMA_CLONES std::array<bool, 2> arc_started_handles_of_two(
    const std::array<core::Point2, 2>& t0, const std::array<core::Point2, 2>& t3,
    const std::array<double, 2>& area, const std::array<double, 2>& moment,
    std::array<HandleLengths, 2>& out) {
  const std::array<AreaMomentSystem, 2> systems{
      AreaMomentSystem(t0[0], t3[0], area[0], moment[0]),
      AreaMomentSystem(t0[1], t3[1], area[1], moment[1])};
  const std::array<Quartic, 2> dq{systems[0].q.derivative(), systems[1].q.derivative()};
  std::array<double, 2> a{arc_handle(t0[0], t3[0]), arc_handle(t0[1], t3[1])};
  std::array<Walk, 2> walk{systems[0].valid ? Walk::stepping : Walk::failed,
                           systems[1].valid ? Walk::stepping : Walk::failed};
  for (int i = 0; i < kArcNewtonSteps; ++i) {
    if (walk[0] != Walk::stepping && walk[1] != Walk::stepping) break;
    for (std::size_t k = 0; k < 2; ++k) {
      if (walk[k] == Walk::stepping) walk[k] = arc_newton_step(systems[k], dq[k], a[k], out[k]);
    }
  }
  return {walk[0] == Walk::found, walk[1] == Walk::found};
}

}  // namespace bezier::outline
