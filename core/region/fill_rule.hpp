#pragma once

#include <string_view>

#include "core/base/enum_names.hpp"

namespace bezier::region {

/// Which points a closed path fills, by their winding number w (SVG 2 §13.4.2 "Fill
/// properties", the `fill-rule` property): `nonzero` fills w != 0, `evenodd` fills odd w.
enum class FillRule { nonzero, evenodd };

/// "nonzero", "evenodd".
inline constexpr core::EnumNames<FillRule::evenodd> kFillRuleNames{"nonzero", "evenodd"};

[[nodiscard]] constexpr std::string_view to_string(FillRule rule) noexcept {
  return kFillRuleNames(rule);
}

/// Whether a point of winding number `winding` is filled under `rule`.
[[nodiscard]] constexpr bool fills(FillRule rule, long winding) noexcept {
  return rule == FillRule::nonzero ? winding != 0 : (winding % 2) != 0;
}

}  // namespace bezier::region
