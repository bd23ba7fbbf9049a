#include "core/intersect/clip/clip.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/base/rect.hpp"
#include "core/numeric/min_max.hpp"
#include "core/numeric/fixed_extent.hpp"
#include "core/base/multiversion.hpp"
#include "core/numeric/unit_roundoff.hpp"
#include "core/intersect/tuning.hpp"

namespace bezier::core {

namespace {

/// The control box of a piece's coordinates x, y (E entries, with_fixed_extent), widened by
/// its error bound.
template <std::size_t E>
Rect extent_of(std::span<const double, E> x, std::span<const double, E> y,
               double error) noexcept {
  Rect box{{x[0], y[0]}, {x[0], y[0]}};
  for (std::size_t i = 1; i < x.size(); ++i) box = box.including({x[i], y[i]});
  return box.grown(error);
}

template <std::size_t E>
Rect extent(const Piece& p) noexcept {
  const std::size_t size = p.x.size();
  return extent_of(fixed_span<E>(p.x.data(), size), fixed_span<E>(p.y.data(), size), p.error);
}

bool disjoint(const Rect& a, const Rect& b) noexcept { return !a.intersects(b); }

/// The least and the largest of the E values a (std::minmax_element's, without the
/// iterators: the same comparisons on the same values).
template <std::size_t E>
std::pair<double, double> value_range(std::span<const double, E> a) noexcept {
  const auto [lo, hi] = std::minmax_element(a.begin(), a.end());
  return {*lo, *hi};
}

}  // namespace

bool is_noisy(const FatLine& line, const DistanceCoefficients& d) noexcept {
  const std::size_t size = d.a.size();
  const auto [lo, hi] = with_fixed_extent(
      size, [&](auto e) { return value_range(fixed_span<decltype(e)::value>(d.a.data(), size)); });
  const double noise = line.margin + d.error;
  const double signal = (line.d_max - line.d_min - 2 * line.margin) + (hi - lo);
  return intersect_tuning::kNoiseRatio * noise > signal;
}

BEZIER_FMA_CLONES bool bounding_boxes_disjoint(const Piece& f, const Piece& g) noexcept {
  // One dispatch for both pieces when their degrees agree (every step of two cubics).
  if (f.x.size() == g.x.size()) {
    return with_fixed_extent(f.x.size(), [&](auto e) {
      return disjoint(extent<decltype(e)::value>(f), extent<decltype(e)::value>(g));
    });
  }
  return disjoint(extent<std::dynamic_extent>(f), extent<std::dynamic_extent>(g));
}

ParamInterval map_to_domain(ParamInterval domain, ParamInterval local) noexcept {
  const double w = domain.hi - domain.lo;
  ParamInterval out = domain;
  if (local.lo > 0.0) out.lo = max2(domain.lo, domain.lo + w * local.lo - 4 * kUnitRoundoff);
  if (local.hi < 1.0) out.hi = min2(domain.hi, domain.lo + w * local.hi + 4 * kUnitRoundoff);
  if (out.hi < out.lo) out.hi = out.lo;
  return out;
}

}  // namespace bezier::core
