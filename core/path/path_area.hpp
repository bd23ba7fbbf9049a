#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include "core/path/path.hpp"

namespace bezier::path {

/// The signed area a closed subpath encloses, by Green's theorem A = 1/2 ∮ (x dy - y dx)
/// over its segments, counter-clockwise positive (y up), winding numbers counted as the
/// theorem counts them. Computed as the area of the polygon of the segments' end points
/// (the shoelace formula relative to the first one, so translation changes only rounding)
/// plus each segment's area against its chord, core::enclosed_area: exact closed Bernstein
/// forms, no quadrature. Precondition: the subpath is closed; finite coordinates.
[[nodiscard]] double closed_subpath_area(const Path& path, const Subpath& subpath);

/// closed_subpath_area of the closed chain of curves `chain` (each starting where the one
/// before ends, the last ending where the first starts), given in order without a Path to
/// hold them: the same sums in the same order, so the same double.
[[nodiscard]] double closed_chain_area(std::span<const core::Curve* const> chain);

/// The sum of closed_subpath_area over the closed subpaths; nullopt when none is closed
/// (open subpaths enclose nothing).
[[nodiscard]] std::optional<double> closed_area(const Path& path);

/// The signed area enclosed by the piece of one subpath from segment i at t to segment j
/// at s (i < j in drawing order within the subpath, or i = j with t <= s), closed by the
/// chord back to its start: for a self-intersection (the two ends at one point) the area
/// of the loop. The same decomposition as closed_subpath_area: the polygon of the pieces'
/// end points plus each piece's own area against its chord.
[[nodiscard]] double piece_area(const Path& path, std::size_t i, double t, std::size_t j,
                                double s);

}  // namespace bezier::path
