#pragma once

#include "core/intersect/clip/clip.hpp"

namespace bezier::core {

/// The subdivision method's exclusion test on two pieces.
struct Separation {
  bool separated = false;  ///< the exact pieces certainly do not meet
  bool noisy = false;      ///< not separated, and the error margins dominated a fat-line test
};

/// Bounding boxes disjoint, or either piece entirely outside the other's fat line (an
/// oriented bounding box; without it, curves that run close together, as near a tangency,
/// keep O(1/sqrt(width)) boxes alive per level of halving). Every test includes the
/// pieces' error bounds.
[[nodiscard]] Separation separation(const Piece& f, const Piece& g);

}  // namespace bezier::core
