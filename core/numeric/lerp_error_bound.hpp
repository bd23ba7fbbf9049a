#pragma once

// The rounding error of n levels of linear interpolation: the bound every de Casteljau
// evaluation and every portion (blossom) of a polynomial in Bernstein form computed in
// doubles carries.

#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {

/// A bound on |computed - exact| for a value computed from inputs c_i by `levels` levels of
/// lerp(a, b, t) = (1 - t) a + t b in doubles, each level's t in [0, 1] (any t per level,
/// so de Casteljau's B(t) and a blossom b(a, ..., a, b, ..., b) alike), the exact value
/// being the same recurrence in exact arithmetic on the same c_i, with max|c_i| <=
/// `magnitude`:
///
///     3.02 levels u magnitude + 2^-1000.
///
/// Derivation (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed.: the model
/// fl(x op y) = (x op y)(1 + d), |d| <= u, §2.2; gamma_k = k u / (1 - k u) and
/// (1 + gamma_j)(1 + gamma_k) <= 1 + gamma_(j+k), Lemma 3.3). One lerp of computed values
/// a^, b^ rounds 1 - t, the two products and the sum, so it returns
/// (1 - t) a^ (1 + th_3) + t b^ (1 + th_2) with |th_k| <= gamma_k: its error against the
/// exact lerp of the exact a, b is at most (1 - t) |a^ - a| + t |b^ - b| + gamma_3 max(|a^|,
/// |b^|), since (1 - t) + t = 1. Let e_k and m_k be the largest error and the largest
/// |value| on level k: e_(k+1) <= e_k + gamma_3 m_k and m_(k+1) <= (1 + gamma_3) m_k, with
/// e_0 = 0 and m_0 <= magnitude, so after n levels
///
///     e_n <= ((1 + gamma_3)^n - 1) magnitude <= gamma_(3n) magnitude.
///
/// gamma_(3n) <= 3.02 n u while 3 n u <= 1 - 3 / 3.02 (n below 2^43): the rest of the 0.02 n u
/// covers the rounding of the bound's own two products. Underflow: a product that lands
/// among the subnormals errs by up to 2^-1075 in absolute terms, outside the model above
/// (the sum of two subnormals is exact); two per lerp, carried on with weights summing to at
/// most 1 + gamma_3, so n levels add less than n 2^-1073, which 2^-1000 covers for any n
/// the kernel meets. It also keeps the bound positive when magnitude is 0 or subnormal.
///
/// Precondition: levels >= 0, magnitude >= 0 and finite.
[[nodiscard]] constexpr double lerp_levels_error_bound(int levels, double magnitude) noexcept {
  return 3.02 * levels * kUnitRoundoff * magnitude + 0x1p-1000;
}

}  // namespace bezier::core
