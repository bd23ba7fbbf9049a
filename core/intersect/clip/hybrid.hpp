#pragma once

#include "core/intersect/clip/clip.hpp"
#include "core/intersect/clip/fat_curve.hpp"

namespace bezier::core {

/// Hybrid clip (after Q. Lou and L. Liu, "Curve intersection using hybrid clipping",
/// Computers & Graphics 36(5), 2012, 309-320): x against the fat line of `other`, with x's
/// distance function bounded by its fat curve of degree op.k (fat_curve_clip).
[[nodiscard]] Clip hybrid_clip(const Piece& x, const Piece& other, const FatCurveOperator& op,
                               PointLineDirection direction);

}  // namespace bezier::core
