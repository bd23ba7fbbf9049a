#pragma once

#include "core/intersect/clip/clip.hpp"

namespace bezier::core {

/// Bézier clip (Sederberg & Nishita 1990, §3): x against the fat line of `other`, with x's
/// distance function bounded by the convex hull of its control polygon (bernstein::hull_clip).
[[nodiscard]] Clip bezier_clip(const Piece& x, const Piece& other, PointLineDirection direction);

}  // namespace bezier::core
