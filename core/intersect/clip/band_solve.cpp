#include "core/intersect/clip/band_solve.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/bernstein/bernstein1d.hpp"
#include "core/numeric/lerp_error_bound.hpp"
#include "core/numeric/min_max.hpp"
#include "core/numeric/fixed_extent.hpp"
#include "core/base/multiversion.hpp"
#include "core/numeric/unit_roundoff.hpp"
#include "core/intersect/tuning.hpp"

namespace bezier::core {

using namespace intersect_tuning;

namespace {

double horner(double c0, double c1, double c2, double c3, double t) noexcept {
  return ((c3 * t + c2) * t + c1) * t + c0;
}

double polish(double c0, double c1, double c2, double c3, double t, int iterations) noexcept {
  for (int i = 0; i < iterations; ++i) {
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
    if (disc > -16 * kUnitRoundoff * (c1 * c1 + std::fabs(4 * c2 * c0))) {
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

CubicRoots real_roots_up_to_cubic(double c0, double c1, double c2, double c3, double lo,
                                  double hi) {
  CubicRoots out;
  const double scale = max2(max2(std::fabs(c0), std::fabs(c1)),
                                       max2(std::fabs(c2), std::fabs(c3)));
  if (scale == 0.0) return out;
  double raw[3];
  int count = 0;
  if (std::fabs(c3) > kLeadingCoefficient * scale) {
    count = monic_cubic(c2 / c3, c1 / c3, c0 / c3, raw);
  } else if (std::fabs(c2) > kLeadingCoefficient * scale) {
    count = quadratic(c0, c1, c2, raw);
  } else if (c1 != 0.0) {
    raw[0] = -c0 / c1;
    count = 1;
  }
  for (int i = 0; i < count; ++i) {
    // The cancellation-free quadratic formula is accurate as it is; the trigonometric and
    // Cardano forms lose a few digits to the normalisation, which Newton's method restores.
    const double t = polish(c0, c1, c2, c3, raw[i], c3 != 0.0 ? 2 : 0);
    if (lo <= t && t <= hi) out.t[out.count++] = t;
  }
  sort_small(out.t, out.count);
  return out;
}

namespace {

/// Room for the E coefficients of a portion: on the stack when E is fixed.
template <std::size_t E>
struct CoefficientBuffer {
  explicit CoefficientBuffer(std::size_t /*size*/) noexcept {}
  double* data() noexcept { return values.data(); }
  std::array<double, E> values;
};
template <>
struct CoefficientBuffer<std::dynamic_extent> {
  explicit CoefficientBuffer(std::size_t size)
      : values(size, SmallArray<double>::Uninitialized{}) {}
  double* data() noexcept { return values.data(); }
  SmallArray<double> values;
};

template <std::size_t E>
std::optional<ParamInterval> kept_interval_by_hulls_of(std::span<const double, E> p, double lo,
                                                       double hi) {
  const int k = static_cast<int>(p.size()) - 1;
  const double e = lerp_levels_error_bound(k, bernstein::max_abs(p));
  CoefficientBuffer<E> piece(p.size());
  ParamInterval range{0.0, 1.0};
  for (int pass = 0; pass < kBandClipPasses; ++pass) {
    // The first pass clips p itself (exact coefficients, no margin).
    std::optional<ParamInterval> clip;
    if (pass == 0) {
      clip = bernstein::hull_clip_of(p, lo, hi);
    } else {
      bernstein::portion_into(std::span<const double>(p), range.lo, range.hi, piece.data());
      clip = bernstein::hull_clip_of(std::span<const double, E>(piece.data(), p.size()), lo - e,
                                     hi + e);
    }
    if (!clip) return std::nullopt;
    const double w = range.hi - range.lo;
    ParamInterval next = range;
    if (clip->lo > 0.0) next.lo = max2(range.lo, range.lo + w * clip->lo - 4 * kUnitRoundoff);
    if (clip->hi < 1.0) next.hi = min2(range.hi, range.lo + w * clip->hi + 4 * kUnitRoundoff);
    const bool shrank_enough = next.hi - next.lo < kBandClipKeptFraction * w;
    range = next;
    if (!shrank_enough) break;
  }
  return range;
}

}  // namespace

std::optional<ParamInterval> kept_interval_by_hulls(std::span<const double> p, double lo,
                                                    double hi) {
  return kept_interval_by_hulls_of<std::dynamic_extent>(p, lo, hi);
}

namespace {

/// p on [0, a] (left) and on [b, 1] (right) for degree k <= 3, by one de Casteljau pass each:
/// the left piece is the first entry of every level, the right piece the last.
struct Ends {
  double left[4];
  double right[4];
};

// The helpers of kept_interval take p as a span of E = k + 1 coefficients, E fixed at
// compile time (kept_interval dispatches on the degree): their loops then unroll.

template <std::size_t E>
Ends end_pieces(std::span<const double, E> p, double a, double b) noexcept {
  const int k = static_cast<int>(p.size()) - 1;
  Ends out{};
  double row[4];
  for (int i = 0; i <= k; ++i) row[i] = p[i];
  out.left[0] = row[0];
  for (int level = k; level > 0; --level) {
    for (int i = 0; i < level; ++i) row[i] = bernstein::lerp(row[i], row[i + 1], a);
    out.left[k - level + 1] = row[0];
  }
  for (int i = 0; i <= k; ++i) row[i] = p[i];
  out.right[k] = row[k];
  for (int level = k; level > 0; --level) {
    for (int i = 0; i < level; ++i) row[i] = bernstein::lerp(row[i], row[i + 1], b);
    out.right[level - 1] = row[level - 1];
  }
  return out;
}

/// de Casteljau value of a degree-k <= 3 polynomial.
template <std::size_t E>
double value(std::span<const double, E> p, double t) noexcept {
  if constexpr (E != std::dynamic_extent && E >= 2) {
    const std::array<double, 2> last = bernstein::last_casteljau_level(p, t);
    return bernstein::lerp(last[0], last[1], t);
  } else {
    const int k = static_cast<int>(p.size()) - 1;
    double row[4] = {};  // (GCC cannot see that p is never empty for a dynamic E)
    for (int i = 0; i <= k; ++i) row[i] = p[i];
    for (int level = k; level > 0; --level) {
      for (int i = 0; i < level; ++i) row[i] = bernstein::lerp(row[i], row[i + 1], t);
    }
    return row[0];
  }
}

/// Where the monotone p (power coefficients c) crosses level[0] and level[1] in [0, 1], for
/// the lanes marked wanted (the others keep their start). Halley's method, whose order is 3:
/// started where the control polygon crosses the level, which on the first, large pieces
/// can be 0.2 off, two steps reach the 2^-32 pad where Newton's method often needs four, so
/// that a certificate rarely fails and sends the clip to the hull iteration. The two lanes
/// are independent
/// chains and every step's outcome is a select, not a branch: they overlap in the pipeline.
template <std::size_t E>
std::array<double, 2> monotone_roots(std::span<const double, E> p, const double* c, bool increasing,
                                     const double level[2], const bool wanted[2]) noexcept {
  const int k = static_cast<int>(p.size()) - 1;
  std::array<double, 2> t{};
  bool active[2];
  for (int lane = 0; lane < 2; ++lane) {
    // p_j <= level is monotone in j, so the polygon crosses the level on the segment where
    // it changes, found by counting.
    const double v = level[lane];
    int at_most = 0;
    for (int j = 0; j <= k; ++j) at_most += p[static_cast<std::size_t>(j)] <= v ? 1 : 0;
    const bool crosses = at_most > 0 && at_most <= k;
    const int i = !crosses ? 0 : (increasing ? at_most - 1 : k - at_most);
    const double a = p[static_cast<std::size_t>(i)], b = p[static_cast<std::size_t>(i) + 1];
    t[lane] = crosses ? (i + (v - a) / (b - a)) / k : 0.5;
    active[lane] = wanted[lane];
  }
  for (int iteration = 0; iteration < kHalleySteps; ++iteration) {
    for (int lane = 0; lane < 2; ++lane) {
      const double x = t[lane], x2 = x * x;
      // Estrin's halves: a shorter dependency chain than Horner's.
      const double f = ((c[0] - level[lane]) + c[1] * x) + (c[2] + c[3] * x) * x2;
      const double df = (c[1] + 2 * c[2] * x) + 3 * c[3] * x2;
      const double ddf = 2 * c[2] + 6 * c[3] * x;
      const double denominator = 2 * df * df - f * ddf;
      const double next = x - 2 * f * df / denominator;
      const bool step = active[lane] && denominator != 0.0 && next >= 0.0 && next <= 1.0;
      const bool converged = std::fabs(next - x) <= kHalleyConverged;
      t[lane] = step ? next : x;
      active[lane] = step && !converged;
    }
  }
  return t;
}

/// kept_interval for p of E coefficients: E fixed at compile time for degrees 1 to 3 (the
/// loops unroll and the branches on the degree fold; the arithmetic is the same), dynamic
/// for the rest, which only take the quick exits and the hull iteration.
template <std::size_t E>
std::optional<ParamInterval> kept_interval_of(std::span<const double, E> p, double lo, double hi) {
  const int k = static_cast<int>(p.size()) - 1;
  double p_min = p[0], p_max = p[0];
  for (const double v : p) {
    p_min = v < p_min ? v : p_min;
    p_max = v > p_max ? v : p_max;
  }
  if (p_max < lo || p_min > hi) return std::nullopt;
  if (lo <= p_min && p_max <= hi) return ParamInterval{0.0, 1.0};
  if (k < 1 || k > 3) return kept_interval_by_hulls_of(p, lo, hi);
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
  const double e = lerp_levels_error_bound(k, bernstein::max_abs(p));
  // Monotone p (monotone Bernstein coefficients, so p' has constant sign): the set is one
  // interval between the crossings of lo and hi, and a single value outside each end
  // certifies it. This is the common case once the pieces are small.
  bool increasing = true, decreasing = true;
  for (int i = 0; i < k; ++i) {
    increasing = increasing && p[static_cast<std::size_t>(i)] <= p[static_cast<std::size_t>(i) + 1];
    decreasing = decreasing && p[static_cast<std::size_t>(i)] >= p[static_cast<std::size_t>(i) + 1];
  }
  if (increasing || decreasing) {
    // Lane 0 is where p enters the band (from below if increasing, from above if
    // decreasing), lane 1 where it leaves it; an end of [0, 1] already inside needs no root.
    const std::size_t last = static_cast<std::size_t>(k);
    const double level[2] = {increasing ? lo : hi, increasing ? hi : lo};
    const bool inside[2] = {increasing ? p[0] >= lo : p[0] <= hi,
                            increasing ? p[last] <= hi : p[last] >= lo};
    const bool wanted[2] = {!inside[0], !inside[1]};
    const std::array<double, 2> root = monotone_roots(p, c, increasing, level, wanted);
    const double alpha = inside[0] ? 0.0 : max2(0.0, root[0] - kRootPad);
    const double beta = inside[1] ? 1.0 : min2(1.0, root[1] + kRootPad);
    // One value beyond each end certifies it: a monotone p outside the band there stays
    // outside up to the end of [0, 1].
    const double at_alpha = value(p, alpha), at_beta = value(p, beta);
    const bool alpha_certified =
        alpha == 0.0 || (increasing ? at_alpha < lo - e : at_alpha > hi + e);
    const bool beta_certified = beta == 1.0 || (increasing ? at_beta > hi + e : at_beta < lo - e);
    if (alpha_certified && beta_certified && alpha <= beta) return ParamInterval{alpha, beta};
  }
  // Not monotone, degree 3 (common on the first, large pieces): the hull iteration. The
  // exact set from the cubic's monotone stretches (Newton's method per stretch, a
  // certificate per stretch, the hull iteration when one fails) is tighter, but its
  // branches cost more than the few extra steps the looser bound takes; near a root, where the
  // convergence order counts, the distance function is monotone and takes the path above.
  if (k == 3) return kept_interval_by_hulls_of(p, lo, hi);
  // Not monotone, degree <= 2: the roots of p = lo and p = hi in closed form; segments between
  // them are kept when p at their midpoint (Horner: only a guess, certified below) is in the
  // band.
  double breaks[8];
  int nb = 0;
  breaks[nb++] = 0.0;
  for (const double level : {lo, hi}) {
    const CubicRoots r =
        real_roots_up_to_cubic(c[0] - level, c[1], c[2], c[3], -kRootWindow, 1 + kRootWindow);
    for (int i = 0; i < r.count; ++i)
      breaks[nb++] = r.t[i] < 0.0 ? 0.0 : (r.t[i] > 1.0 ? 1.0 : r.t[i]);
  }
  breaks[nb++] = 1.0;
  sort_small(breaks, nb);
  double alpha = 2.0, beta = -1.0;
  for (int i = 0; i + 1 < nb; ++i) {
    const double mid = breaks[i] / 2 + breaks[i + 1] / 2;
    const double v = horner(c[0], c[1], c[2], c[3], mid);
    if (lo <= v && v <= hi) {
      alpha = alpha < breaks[i] ? alpha : breaks[i];
      beta = beta > breaks[i + 1] ? beta : breaks[i + 1];
    }
  }
  if (beta < alpha) return kept_interval_by_hulls_of(p, lo, hi);
  alpha = alpha - kRootPad > 0 ? alpha - kRootPad : 0.0;
  beta = beta + kRootPad < 1 ? beta + kRootPad : 1.0;
  const Ends ends = end_pieces(p, alpha, beta);
  const std::span<const double> left(ends.left, static_cast<std::size_t>(k + 1));
  const std::span<const double> right(ends.right, static_cast<std::size_t>(k + 1));
  if ((alpha > 0.0 && !certainly_outside(left, lo, hi, e)) ||
      (beta < 1.0 && !certainly_outside(right, lo, hi, e))) {
    return kept_interval_by_hulls_of(p, lo, hi);
  }
  return ParamInterval{alpha, beta};
}

}  // namespace

BEZIER_FMA_CLONES std::optional<ParamInterval> kept_interval(std::span<const double> p, double lo,
                                                             double hi) {
  return with_fixed_extent(p.size(), [&](auto e) {
    return kept_interval_of(fixed_span<decltype(e)::value>(p.data(), p.size()), lo, hi);
  });
}

}  // namespace bezier::core
