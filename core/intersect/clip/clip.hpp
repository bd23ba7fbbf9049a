#pragma once

#include <optional>

#include "core/intersect/clip/fat_line.hpp"
#include "core/intersect/result.hpp"
#include "core/intersect/working_curve.hpp"

namespace bezier::core {

/// The outcome of clipping one piece against the other piece's fat line.
struct Clip {
  /// The part of the clipped piece's domain [0, 1] that may still hold an intersection;
  /// nullopt when the pieces certainly do not meet.
  std::optional<ParamInterval> kept;
  /// True when the error margins are a large part of what the clip saw (more than a quarter
  /// of the band width plus the spread of the distances): the pieces are too small for
  /// their rounding, and compensated pieces (or nothing) can tell more.
  bool noisy = false;
  /// False when the test had nothing to say (kept = [0, 1] by default, noisy meaningless).
  bool informative = true;
};

/// Axis-aligned bounding boxes of the control points, each widened by its piece's error
/// bound, are disjoint: the exact pieces cannot meet.
[[nodiscard]] bool bounding_boxes_disjoint(const Piece& f, const Piece& g) noexcept;

/// Whether the margins dominate a clip (see Clip::noisy).
[[nodiscard]] bool is_noisy(const FatLine& line, const DistanceCoefficients& d) noexcept;

/// The global parameter interval of a local interval of a piece on `domain`: the affine map
/// rounded outward by 4 u (its rounding error is below 3 u for parameters in [0, 1]) and
/// clamped to the domain; an end of the local interval at 0 or 1 maps to the domain's end
/// exactly.
[[nodiscard]] ParamInterval map_to_domain(ParamInterval domain, ParamInterval local) noexcept;

}  // namespace bezier::core
