#include "core/path/joint_separation.hpp"

#include <cmath>
#include <optional>
#include <span>

#include "core/numeric/bounded_projection.hpp"
#include "core/path/tuning.hpp"

namespace bezier::path {

namespace {

using core::Point2;

/// |v|: the plain square root of v . v where that sum is a normal double far from
/// overflow (then within about an ulp of hypot: a square that underflows loses at most
/// 2^-1074 against a sum of at least 2^-960), else hypot. Only the direction of d matters to
/// the certificate (separates takes any d as exact); the length keeps the two unit vectors
/// of the directions below comparable.
double length_of(Point2 v) noexcept {
  const double squared = v.x * v.x + v.y * v.y;
  if (0x1p-960 <= squared && squared <= 0x1p960) return std::sqrt(squared);
  return std::hypot(v.x, v.y);
}

/// v / |v|, or nullopt when that is not a finite nonzero vector.
std::optional<Point2> unit(Point2 v) noexcept {
  const double length = length_of(v);
  if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
  return v / length;
}

/// d . (p - joint) has the sign `sign` (+1 or -1) for certain and by the margin, or p is the
/// joint itself (an exact zero, allowed where `zero_allowed`).
bool on_side(Point2 d, Point2 p, Point2 joint, double sign, bool zero_allowed) noexcept {
  const core::BoundedProjection x = core::bounded_projection(d, p, joint);
  // Written so that NaN or an infinite bound fails. The joint itself never passes (its
  // projection is 0 or NaN, its bound positive), so it is looked at only on failure.
  if (sign * x.value - x.error > path_tuning::kSeparationMargin * x.size) return true;
  return zero_allowed && p == joint;
}

/// The conditions of the header for one direction d, on the control points of `before`
/// (ending at the joint) and of `after` (starting there). Written over spans of any extent:
/// with the sizes fixed (two cubics, the common case) the loops unroll; the tests and their
/// order are the same either way.
template <std::size_t Before, std::size_t After>
bool separates(Point2 d, std::span<const Point2, Before> before,
               std::span<const Point2, After> after) noexcept {
  const Point2 joint = after.front();
  const std::size_t n = before.size() - 1, m = after.size() - 1;
  for (std::size_t i = 0; i < n; ++i) {
    if (!on_side(d, before[i], joint, 1.0, i > 0)) return false;
  }
  for (std::size_t j = 1; j <= m; ++j) {
    if (!on_side(d, after[j], joint, -1.0, j < m)) return false;
  }
  return true;
}

/// The difference of the two end tangents' unit vectors (see the header), times the product
/// of the two lengths: v |w| - w |v| = |v| |w| (v / |v| - w / |w|), the same direction
/// without the two divisions, whose latency the test would otherwise wait on (separates
/// takes any d as exact). A product that overflows makes d infinite or NaN, which separates
/// never certifies.
template <std::size_t Before, std::size_t After>
std::optional<Point2> tangent_direction(std::span<const Point2, Before> before,
                                        std::span<const Point2, After> after) noexcept {
  const Point2 joint = after.front();
  std::optional<Point2> v, w;
  for (std::size_t i = before.size() - 1; i-- > 0 && !v;) {
    if (before[i] != joint) v = before[i] - joint;
  }
  for (std::size_t j = 1; j < after.size() && !w; ++j) {
    if (after[j] != joint) w = after[j] - joint;
  }
  if (!v || !w) return std::nullopt;
  const double v_length = length_of(*v), w_length = length_of(*w);
  if (!(v_length > 0.0) || !(w_length > 0.0)) return std::nullopt;
  return *v * w_length - *w * v_length;
}

/// The difference of the control polygons' mean directions from the joint (see the header).
template <std::size_t Before, std::size_t After>
std::optional<Point2> mean_direction(std::span<const Point2, Before> before,
                                     std::span<const Point2, After> after) noexcept {
  const Point2 joint = after.front();
  Point2 v_sum{}, w_sum{};
  for (std::size_t i = 0; i + 1 < before.size(); ++i) {
    if (before[i] == joint) continue;
    const auto u = unit(before[i] - joint);
    if (!u) return std::nullopt;
    v_sum = v_sum + *u;
  }
  for (std::size_t j = 1; j < after.size(); ++j) {
    if (after[j] == joint) continue;
    const auto u = unit(after[j] - joint);
    if (!u) return std::nullopt;
    w_sum = w_sum + *u;
  }
  const auto v = unit(v_sum);
  const auto w = unit(w_sum);
  if (!v || !w) return std::nullopt;
  return *v - *w;
}

/// meet_only_at_joint on control points known to share the joint.
template <std::size_t Before, std::size_t After>
bool separated_at_joint(std::span<const Point2, Before> before,
                        std::span<const Point2, After> after) noexcept {
  if (const auto d = tangent_direction(before, after); d && separates(*d, before, after)) return true;
  const auto d = mean_direction(before, after);
  return d && separates(*d, before, after);
}

}  // namespace

bool meet_only_at_joint(const core::Curve& before_curve, const core::Curve& after_curve) noexcept {
  const std::span<const Point2> before = before_curve.points(), after = after_curve.points();
  if (before.size() < 2 || after.size() < 2 || before.back() != after.front()) return false;
  // Cubics and lines, the usual segments, with fixed extents; other degrees as they come.
  const auto with_after = [&](auto fixed_before) {
    if (after.size() == 4) return separated_at_joint(fixed_before, after.first<4>());
    if (after.size() == 2) return separated_at_joint(fixed_before, after.first<2>());
    return separated_at_joint(fixed_before, after);
  };
  if (before.size() == 4) return with_after(before.first<4>());
  if (before.size() == 2) return with_after(before.first<2>());
  return with_after(before);
}

}  // namespace bezier::path
