#include "core/self_intersect/monotone_direction.hpp"

#include <cmath>
#include <limits>
#include <optional>

#include "core/numeric/bounded_projection.hpp"

namespace bezier::core {

namespace {

/// d . (p[i + 1] - p[i]) > 0 for certain, for every i.
template <std::size_t Extent>
bool increasing_along(Point2 d, std::span<const Point2, Extent> p) noexcept {
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    if (!bounded_projection(d, p[i + 1], p[i]).certainly_positive()) return false;
  }
  return true;
}

/// v / |v|, with |v| from the plain square root (only the direction matters: any d gives a
/// certified answer); nullopt when that length vanishes or overflows.
std::optional<Point2> direction_of(Point2 v) noexcept {
  const double length = std::sqrt(dot(v, v));
  if (!(length > 0.0 && length <= std::numeric_limits<double>::max())) return std::nullopt;
  return v / length;
}

/// certainly_monotone over a span of any extent (fixed for a cubic: the loops unroll).
template <std::size_t Extent>
bool monotone_along_a_direction(std::span<const Point2, Extent> p) noexcept {
  if (p.size() < 2) return false;
  if (increasing_along(p.back() - p.front(), p)) return true;
  const std::size_t n = p.size() - 1;
  if (n < 2) return false;  // a line: the chord is its only difference vector
  const auto first = direction_of(p[1] - p[0]), last = direction_of(p[n] - p[n - 1]);
  return first && last && increasing_along(*first + *last, p);
}

}  // namespace

bool certainly_monotone(std::span<const Point2> p) noexcept {
  return monotone_along_a_direction(p);
}

bool certainly_monotone(std::span<const Point2, 4> p) noexcept {
  return monotone_along_a_direction(p);
}

}  // namespace bezier::core
