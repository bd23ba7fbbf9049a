#pragma once

// Hand-chosen constants of the boolean operations (boolean.hpp and the files it builds on),
// each with its reason. All distances are relative to the operands' scale (the largest
// absolute control-point coordinate), so the operations behave the same at 1e-8 and at 1e8.

namespace bezier::region {

/// The parameter tolerance asked of the intersection searches (core::IntersectOptions):
/// the API's default, 1e-12.
inline constexpr double kIntersectionTolerance = 1e-12;

/// The smallest distance, relative to scale, within which two contact points are one vertex:
/// 2^-44 (about 256 ulps of the largest coordinate), the self-intersection search's own
/// distance tolerance (core/self_intersect). A contact whose parameter interval is wider adds
/// the distance that interval spans on its curve (arrangement.hpp).
inline constexpr double kVertexMergeRel = 0x1p-44;

/// How close, relative to scale, a ray may pass to a vertex or a curve may come to the ray's
/// origin before the crossing count is called unclear and another ray is tried: 2^-40, above
/// the rounding of the pieces' control points (de Casteljau at a few ulps of scale) and of
/// the snapped vertices (kVertexMergeRel), far below any feature of a region.
inline constexpr double kRayClearanceRel = 0x1p-40;

/// Deepest halving of a piece while counting its crossings with a ray: 2^-60 of the piece is
/// below the clearance for any piece of the coordinate range.
inline constexpr int kRayMaxDepth = 60;

/// Two edges leaving a vertex whose tangent angles differ by less than this (radians) are
/// ordered by curvature: 2^-20. Tangent contacts are located to about the square root of the
/// parameter tolerance, so the tangents of two curves that touch can differ by that much
/// after their common point is merged into one vertex.
inline constexpr double kTangentTieAngle = 0x1p-20;

}  // namespace bezier::region
