#include "core/intersect/band_solve.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/intersect/bernstein1d.hpp"

namespace bezier::core {

namespace {

constexpr double kU = bernstein::kU;
/// Widening of the closed-form interval before it is certified: well above the error of a
/// polished simple root (a few ulps), small enough to keep quadratic convergence (a clip can
/// still shrink an interval by a factor 2^31).
constexpr double kRootPad = 0x1p-32;

double horner(double c0, double c1, double c2, double c3, double t) noexcept {
  return ((c3 * t + c2) * t + c1) * t + c0;
}

double polish(double c0, double c1, double c2, double c3, double t) noexcept {
  for (int i = 0; i < 3; ++i) {
    const double f = horner(c0, c1, c2, c3, t);
    const double df = (3 * c3 * t + 2 * c2) * t + c1;
    if (!(df != 0.0)) break;
    const double next = t - f / df;
    if (!std::isfinite(next)) break;
    t = next;
  }
  return t;
}

/// Roots of c0 + c1 t + c2 t^2 (c2 != 0), cancellation-free.
int quadratic(double c0, double c1, double c2, double out[2]) noexcept {
  const double disc = c1 * c1 - 4 * c2 * c0;
  if (disc < 0) {
    // Keep a nearly double root: rounding may have pushed the discriminant below zero.
    if (disc > -16 * kU * (c1 * c1 + std::fabs(4 * c2 * c0))) {
      out[0] = -c1 / (2 * c2);
      return 1;
    }
    return 0;
  }
  const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
  if (q == 0.0) {
    out[0] = 0.0;
    return 1;
  }
  out[0] = q / c2;
  out[1] = c0 / q;
  return 2;
}

/// Roots of t^3 + a t^2 + b t + c (Viète for three real roots, Cardano for one).
int monic_cubic(double a, double b, double c, double out[3]) noexcept {
  const double shift = -a / 3;
  const double p = b - a * a / 3;
  const double q = (2 * a * a * a) / 27 - (a * b) / 3 + c;
  const double disc = q * q / 4 + p * p * p / 27;
  if (p == 0.0 && q == 0.0) {
    out[0] = shift;
    return 1;
  }
  if (disc > 0) {
    const double big = std::cbrt(std::fabs(q) / 2 + std::sqrt(disc));
    const double A = q > 0 ? -big : big;
    const double x = A - p / (3 * A);
    out[0] = x + shift;
    return 1;
  }
  const double r = std::sqrt(-p / 3);
  const double cos_arg = std::clamp((3 * q) / (2 * p) * std::sqrt(-3 / p), -1.0, 1.0);
  const double phi = std::acos(cos_arg) / 3;
  for (int k = 0; k < 3; ++k) out[k] = 2 * r * std::cos(phi - 2 * std::numbers::pi * k / 3) + shift;
  return 3;
}

/// Insertion sort of a few values (std::sort trips GCC 12's -Warray-bounds on tiny arrays).
void sort_small(double* v, int count) noexcept {
  for (int i = 1; i < count; ++i) {
    for (int j = i; j > 0 && v[j] < v[j - 1]; --j) std::swap(v[j], v[j - 1]);
  }
}

bool certainly_outside(std::span<const double> q, double lo, double hi, double e) noexcept {
  bool all_below = true, all_above = true;
  for (const double v : q) {
    all_below = all_below && v < lo - e;
    all_above = all_above && v > hi + e;
  }
  return all_below || all_above;
}

}  // namespace

CubicRoots real_roots_up_to_cubic(double c0, double c1, double c2, double c3, double lo, double hi) {
  CubicRoots out;
  const double scale = std::fmax(std::fmax(std::fabs(c0), std::fabs(c1)), std::fmax(std::fabs(c2), std::fabs(c3)));
  if (scale == 0.0) return out;
  double raw[3];
  int count = 0;
  if (std::fabs(c3) > 0x1p-40 * scale) {
    count = monic_cubic(c2 / c3, c1 / c3, c0 / c3, raw);
  } else if (std::fabs(c2) > 0x1p-40 * scale) {
    count = quadratic(c0, c1, c2, raw);
  } else if (c1 != 0.0) {
    raw[0] = -c0 / c1;
    count = 1;
  }
  for (int i = 0; i < count; ++i) {
    const double t = polish(c0, c1, c2, c3, raw[i]);
    if (lo <= t && t <= hi) out.t[out.count++] = t;
  }
  sort_small(out.t, out.count);
  return out;
}

std::optional<ParamInterval> kept_interval_by_hulls(std::span<const double> p, double lo, double hi) {
  const int k = static_cast<int>(p.size()) - 1;
  const double e = 3.02 * k * kU * bernstein::max_abs(p) + 0x1p-1000;
  ParamInterval range{0.0, 1.0};
  for (int iteration = 0; iteration < 8; ++iteration) {
    const Coeffs q = iteration == 0 ? Coeffs(p) : bernstein::portion<double>(p, range.lo, range.hi);
    const double margin = iteration == 0 ? 0.0 : e;
    const auto clip = bernstein::hull_clip(q, lo - margin, hi + margin);
    if (!clip) return std::nullopt;
    const double w = range.hi - range.lo;
    ParamInterval next = range;
    if (clip->lo > 0.0) next.lo = std::fmax(range.lo, range.lo + w * clip->lo - 4 * kU);
    if (clip->hi < 1.0) next.hi = std::fmin(range.hi, range.lo + w * clip->hi + 4 * kU);
    const bool shrank_enough = next.hi - next.lo < 0.8 * w;
    range = next;
    if (!shrank_enough) break;
  }
  return range;
}

std::optional<ParamInterval> kept_interval(std::span<const double> p, double lo, double hi) {
  const auto [min_it, max_it] = std::minmax_element(p.begin(), p.end());
  if (*max_it < lo || *min_it > hi) return std::nullopt;
  if (lo <= *min_it && *max_it <= hi) return ParamInterval{0.0, 1.0};
  const int k = static_cast<int>(p.size()) - 1;
  if (k < 1 || k > 3) return kept_interval_by_hulls(p, lo, hi);
  // Power basis: p(t) = c0 + c1 t + c2 t^2 + c3 t^3.
  double c[4] = {p[0], 0.0, 0.0, 0.0};
  if (k == 1) {
    c[1] = p[1] - p[0];
  } else if (k == 2) {
    c[1] = 2 * (p[1] - p[0]);
    c[2] = p[0] - 2 * p[1] + p[2];
  } else {
    c[1] = 3 * (p[1] - p[0]);
    c[2] = 3 * (p[0] - 2 * p[1] + p[2]);
    c[3] = (p[3] - p[0]) + 3 * (p[1] - p[2]);
  }
  double breaks[8];
  int nb = 0;
  breaks[nb++] = 0.0;
  for (const double level : {lo, hi}) {
    const CubicRoots r = real_roots_up_to_cubic(c[0] - level, c[1], c[2], c[3], -0x1p-20, 1 + 0x1p-20);
    for (int i = 0; i < r.count; ++i) breaks[nb++] = std::clamp(r.t[i], 0.0, 1.0);
  }
  breaks[nb++] = 1.0;
  sort_small(breaks, nb);
  double alpha = 2.0, beta = -1.0;
  for (int i = 0; i + 1 < nb; ++i) {
    const double mid = breaks[i] / 2 + breaks[i + 1] / 2;
    const double v = bernstein::evaluate(p, mid);
    if (lo <= v && v <= hi) {
      alpha = std::fmin(alpha, breaks[i]);
      beta = std::fmax(beta, breaks[i + 1]);
    }
  }
  if (beta < alpha) return kept_interval_by_hulls(p, lo, hi);
  alpha = alpha - kRootPad > 0 ? alpha - kRootPad : 0.0;
  beta = beta + kRootPad < 1 ? beta + kRootPad : 1.0;
  const double e = 3.02 * k * kU * bernstein::max_abs(p) + 0x1p-1000;
  if (alpha > 0.0 && !certainly_outside(bernstein::portion<double>(p, 0.0, alpha), lo, hi, e)) {
    return kept_interval_by_hulls(p, lo, hi);
  }
  if (beta < 1.0 && !certainly_outside(bernstein::portion<double>(p, beta, 1.0), lo, hi, e)) {
    return kept_interval_by_hulls(p, lo, hi);
  }
  return ParamInterval{alpha, beta};
}

}  // namespace bezier::core
