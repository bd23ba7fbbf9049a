#pragma once

#include "core/base/curve.hpp"

namespace bezier::path {

/// Whether two segments that share a joint certainly meet nowhere else: `before` ends where
/// `after` starts (before.back() == after.front(), bit for bit), and true is an answer only
/// when B(t) = C(s) holds for (t, s) = (1, 0) alone, where B is `before` and C is `after`.
/// False means "not shown" (the caller then searches the pair); it is also the answer when
/// the ends differ or either segment is a single point.
///
/// Why it is exact. Let J be the joint, v_i = P_i - J (i < n) for the control points of B
/// and w_j = Q_j - J (j > 0) for those of C. Suppose a direction d has
///   d . v_0 > 0,  d . v_i >= 0 (0 < i < n),  d . w_m < 0,  d . w_j <= 0 (0 < j < m).
/// Then d . (B(t) - J) = sum_{i < n} b_{i,n}(t) d . v_i (the weights sum to 1 and the
/// term of P_n = J is zero): at t = 0 it is d . v_0 > 0, and for 0 < t < 1 every Bernstein
/// weight is positive, so the sum is positive. Likewise d . (C(s) - J) < 0 for 0 < s <= 1.
/// A common point B(t) = C(s) has both projections equal, so t = 1 and s = 0: the joint is
/// the only common point, and neither segment passes through J anywhere else. Each sign is
/// certified by bounded_projection's error bound; a control point equal to J (bit for bit)
/// adds an exact zero and is skipped.
///
/// The margin. Each nonzero projection must also exceed path_tuning::kSeparationMargin (tuning.hpp) times its
/// size (|d.x v.x| + |d.y v.y|): the segments then leave J in angular sectors at least about
/// that many radians apart, so near the joint their distance grows in proportion to the
/// distance from J, and they stay apart by far more than the two-curve search's
/// coincidence tolerance (core/intersect/overlap.hpp) except within a few thousand ulps of
/// J. There the search's only contact is the joint (an exact root, since the ends are equal
/// bit for bit), which path searches drop as a joint, not an intersection. So with the margin
/// a true answer also means: the two-curve search of the pair has nothing to add.
///
/// The directions tried: the difference of the unit vectors along the last nonzero v and
/// the first nonzero w (the end tangents: when the joint is smooth, d is the tangent, and
/// the line through J across it separates the two segments); then the difference of the
/// normalised sums of the unit vectors along every nonzero v and every nonzero w (the two
/// control polygons' mean directions from J), for segments that turn more.
/// Cost: O(n + m) for each direction, no allocation.
[[nodiscard]] bool meet_only_at_joint(const core::Curve& before, const core::Curve& after) noexcept;

}  // namespace bezier::path
