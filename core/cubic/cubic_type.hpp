#pragma once

#include <string_view>

#include "core/base/enum_names.hpp"

namespace bezier::core {

/// The type of a cubic Bézier segment on the closed interval t in [0,1]. The
/// first that applies, in this order:
///   point        all control points equal
///   line         all control points collinear
///   quadratic    P3 − 3 P2 + 3 P1 − P0 = 0 (a degree-elevated parabola)
///   cusp         B'(t) = 0 for some t in [0,1] (P0 = P1 is a cusp at t = 0)
///   loop_at_start, loop_at_end, loop
///                B(t1) = B(t2) with 0 <= t1 < t2 <= 1: loop_at_start when t1 = 0,
///                else loop_at_end when t2 = 1, else loop (a closed cubic, P0 = P3, has
///                t1 = 0 and t2 = 1 and is loop_at_start)
///   double_inflection, single_inflection, arch
///                2, 1 or 0 roots of B'(t) × B''(t) in [0,1] (cusps excluded)
enum class CubicType {
  point,
  line,
  quadratic,
  cusp,
  loop,
  loop_at_start,
  loop_at_end,
  double_inflection,
  single_inflection,
  arch,
};

/// The class of the unbounded cubic (t over all reals) in Loop & Blinn's classification
/// ("Resolution independent curve rendering using programmable graphics hardware",
/// SIGGRAPH 2005, §4), as Skia's SkClassifyCubic and Paper.js's Curve.classify report it:
/// by the discriminant of the inflection polynomial. `cusp` includes the cusp at infinity
/// (Skia's kCuspAtInfinity: d3 = 0, one finite inflection, e.g. y = x³), which Paper.js
/// reports as a serpentine.
enum class LoopBlinnClass {
  serpentine,
  cusp,
  loop,
  quadratic,
  line,
  point,
};

/// The API spelling: "point", "line", "quadratic", "cusp", "loop", "loop-at-start",
/// "loop-at-end", "double-inflection", "single-inflection", "arch".
inline constexpr EnumNames<CubicType::arch> kCubicTypeNames{
    "point", "line", "quadratic", "cusp", "loop", "loop-at-start", "loop-at-end",
    "double-inflection", "single-inflection", "arch"};

[[nodiscard]] constexpr std::string_view to_string(CubicType type) noexcept {
  return kCubicTypeNames(type);
}

/// "serpentine", "cusp", "loop", "quadratic", "line", "point".
inline constexpr EnumNames<LoopBlinnClass::point> kLoopBlinnClassNames{
    "serpentine", "cusp", "loop", "quadratic", "line", "point"};

[[nodiscard]] constexpr std::string_view to_string(LoopBlinnClass c) noexcept {
  return kLoopBlinnClassNames(c);
}

}  // namespace bezier::core
