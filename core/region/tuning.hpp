#pragma once

#include <cstdint>

// The tuning constants of the winding number (winding.hpp), each with the reason for its
// value. None of them changes what is certified: they bound the work.

namespace bezier::region::region_tuning {

/// The deepest subdivision of a segment near a target: pieces of parameter width 2^-96.
/// The double-double pieces carry a rounding error of about depth n 2^-102 of the
/// coordinates' scale (winding.cpp), so below this depth a piece is no larger than its own
/// error and subdividing it decides nothing more; a target still undecided there is within
/// about 2^-80 of the scale of the band's edge, and is reported on the boundary.
inline constexpr int kMaxDepth = 96;

/// Work units (core/intersect/work_cost.hpp: about one coordinate update of de Casteljau's
/// algorithm in doubles) of the box test of one segment against one target: a few
/// comparisons, about one update.
inline constexpr std::int64_t kBoxTestCost = 1;

}  // namespace bezier::region::region_tuning
