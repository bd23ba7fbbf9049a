#pragma once

namespace bezier::region {

/// Which points a closed path fills, from their winding number w (SVG's fill-rule).
enum class FillRule {
  nonzero,  ///< w != 0
  evenodd,  ///< w odd
};

/// Whether a point of winding number `winding` is filled under `rule`.
[[nodiscard]] constexpr bool fills(int winding, FillRule rule) noexcept {
  return rule == FillRule::nonzero ? winding != 0 : (winding % 2) != 0;
}

}  // namespace bezier::region
