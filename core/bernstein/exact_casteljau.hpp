#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/numeric/expansion.hpp"

namespace bezier::core {

// De Casteljau's rounds in exact arithmetic, for the few decisions a rounded value cannot
// settle: whether a polynomial in Bernstein form keeps one sign on a short stretch, and its
// exact value at a parameter. Each round is p + t (q - p) on expansions
// (core/numeric/expansion.hpp): a difference, a product by the double t and a sum, all
// exact. The cost is that of expansions (allocations, components that grow with each
// round), so these are for rare calls, never for a hot loop.
//
// Exactness needs every product's rounding error above the subnormal range: with l(x) the
// exponent of the least significant set bit of x, after k rounds at parameters t_j every
// component's least significant bit is at least min_i l(c_i) + sum_j l(t_j), which must
// stay >= -1074. Both functions check this (and that every coefficient is finite and at most
// 2^1000 in magnitude, so that no sum overflows) and give nullopt when it does not hold:
// the caller keeps its rounded answer then.

/// p(t) exactly, for the polynomial with Bernstein coefficients c on [0, 1] and t in [0, 1].
/// Precondition: c non-empty.
[[nodiscard]] std::optional<Expansion> exact_value(std::span<const double> c, double t);

/// The Bernstein coefficients of the same polynomial on [a, b] (0 <= a <= b <= 1), exactly:
/// coefficient i is the blossom value b(a^(n-i), b^i). Precondition: c non-empty.
[[nodiscard]] std::optional<std::vector<Expansion>> exact_portion(std::span<const double> c, double a,
                                                                  double b);

/// The largest double at most e's exact value, and the smallest at least it.
[[nodiscard]] double rounded_down(const Expansion& e);
[[nodiscard]] double rounded_up(const Expansion& e);

}  // namespace bezier::core
