#pragma once

#include <array>
#include <cassert>
#include <cmath>
#include <optional>
#include <span>

#include "core/base/interval.hpp"
#include "core/numeric/double_double.hpp"
#include "core/numeric/min_max.hpp"
#include "core/numeric/small_array.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core::bernstein {

/// (1 - t) a + t b in doubles, the de Casteljau step. For t in [0,1] its rounding error is
/// at most 3.01 u max(|a|, |b|): 1 - t, the two products and the sum each round once.
[[nodiscard]] inline double lerp(double a, double b, double t) noexcept {
  return (1.0 - t) * a + t * b;
}
[[nodiscard]] inline dd::Real lerp(dd::Real a, dd::Real b, double t) noexcept {
  return dd::lerp(a, b, t);
}

/// The two entries of level n - 1 of de Casteljau's triangle at t, for E = n + 1 >= 2
/// coefficients, E fixed at compile time: p(t) is lerp of them, p'(t) n times their
/// difference. Each level goes into a fresh array. (Levels computed in place in one buffer
/// made GCC's vectoriser reload overlapping pairs of entries just stored one by one, which
/// stalls store forwarding; a fifth of the Krawczyk test's time.) Forced inline, so that
/// the whole triangle stays in registers of the caller (which may ask for scalar code,
/// BEZIER_SCALAR_ROUNDS below).
template <std::size_t E>
[[nodiscard, gnu::always_inline]] inline std::array<double, 2> last_casteljau_level(
    std::span<const double, E> c, double t) noexcept {
  static_assert(E >= 2 && E != std::dynamic_extent);
  if constexpr (E == 2) {
    return {c[0], c[1]};
  } else {
    std::array<double, E - 1> next;
    for (std::size_t i = 0; i + 1 < E; ++i) next[i] = lerp(c[i], c[i + 1], t);
    return last_casteljau_level(std::span<const double, E - 1>(next), t);
  }
}

// The fixed-size de Casteljau rounds below are chains of scalar lerps; GCC's straight-line
// vectoriser pairs them through the stack (a pair stored, then an overlapping pair loaded),
// which stalls store forwarding at every level. Code unrolled for a size fixed at compile
// time stays scalar.
#if defined(__GNUC__) && !defined(__clang__)
#define BEZIER_SCALAR_ROUNDS __attribute__((optimize("no-tree-slp-vectorize", "no-tree-loop-vectorize")))
#else
#define BEZIER_SCALAR_ROUNDS
#endif

namespace detail {

/// portion_into's blossom values for n = 1, 2, 3 in straight-line code (the same values as
/// the rounds of portion_rounds).
template <class T>
[[gnu::always_inline]] inline void portion_low_degree(const T* c, std::size_t n, double a, double b,
                                                      T* out) {
  if (n == 1) {
    out[0] = bernstein::lerp(c[0], c[1], a);
    out[1] = bernstein::lerp(c[0], c[1], b);
  } else if (n == 2) {
    const T a0 = bernstein::lerp(c[0], c[1], a), a1 = bernstein::lerp(c[1], c[2], a);
    const T b0 = bernstein::lerp(c[0], c[1], b), b1 = bernstein::lerp(c[1], c[2], b);
    out[0] = bernstein::lerp(a0, a1, a);
    out[1] = bernstein::lerp(a0, a1, b);
    out[2] = bernstein::lerp(b0, b1, b);
  } else {
    const T a10 = bernstein::lerp(c[0], c[1], a), a11 = bernstein::lerp(c[1], c[2], a),
            a12 = bernstein::lerp(c[2], c[3], a);
    const T a20 = bernstein::lerp(a10, a11, a), a21 = bernstein::lerp(a11, a12, a);
    const T b10 = bernstein::lerp(c[0], c[1], b), b11 = bernstein::lerp(c[1], c[2], b),
            b12 = bernstein::lerp(c[2], c[3], b);
    const T b20 = bernstein::lerp(b10, b11, b), b21 = bernstein::lerp(b11, b12, b);
    out[0] = bernstein::lerp(a20, a21, a);
    out[1] = bernstein::lerp(a20, a21, b);
    out[2] = bernstein::lerp(b20, b21, a);
    out[3] = bernstein::lerp(b20, b21, b);
  }
}

/// portion_into's triangle of rounds for any n, in the buffers row and work (n + 1 entries
/// each). Inlined into its callers so that, where n is a compile-time constant, the loops
/// unroll.
template <class T>
[[gnu::always_inline]] inline void portion_rounds(const T* c, std::size_t n, double a, double b,
                                                  T* row, T* work, T* out) {
  for (std::size_t k = 0; k <= n; ++k) row[k] = c[k];
  // Pass 1: rounds with a. After j rounds, row[0..n-j] is the level-j polygon; result
  // i = n - j <= n/2 is finished from it with i rounds of b.
  for (std::size_t j = 0;; ++j) {
    const std::size_t i = n - j;
    if (2 * i <= n) {
      for (std::size_t k = 0; k <= i; ++k) work[k] = row[k];
      for (std::size_t level = i; level > 0; --level) {
        for (std::size_t k = 0; k < level; ++k) work[k] = bernstein::lerp(work[k], work[k + 1], b);
      }
      out[i] = work[0];
    }
    if (j == n) break;
    for (std::size_t k = 0; k + j < n; ++k) row[k] = bernstein::lerp(row[k], row[k + 1], a);
  }
  // Pass 2: rounds with b; result i > n/2 is finished from level i with n - i rounds of a.
  for (std::size_t k = 0; k <= n; ++k) row[k] = c[k];
  for (std::size_t j = 1; j <= n; ++j) {
    for (std::size_t k = 0; k + j <= n; ++k) row[k] = bernstein::lerp(row[k], row[k + 1], b);
    if (2 * j > n) {
      const std::size_t m = n - j;  // rounds of a still to apply, polygon of m + 1 values
      for (std::size_t k = 0; k <= m; ++k) work[k] = row[k];
      for (std::size_t level = m; level > 0; --level) {
        for (std::size_t k = 0; k < level; ++k) work[k] = bernstein::lerp(work[k], work[k + 1], a);
      }
      out[j] = work[0];
    }
  }
}

}  // namespace detail

/// The coefficients of the same polynomial restricted to [a, b] and reparametrised to
/// [0, 1]: coefficient i is the blossom value b(a^(n-i), b^i) (Ramshaw 1987), computed from
/// the triangle of de Casteljau rounds with a (for i <= n/2, finished with i rounds of b)
/// and with b (for i > n/2, finished with n - i rounds of a). The parameters enter exactly,
/// so the piece is exactly the polynomial on [a, b] up to the rounding of the arithmetic:
/// each coefficient goes through n steps, so for a, b in [0, 1] its error is at most
/// 3.01 n u max|c| in doubles, 10 n u^2 max|c| in double-doubles. Degrees 1 to 3 run as
/// straight-line code (the same values).
/// Written into out[0..n], which must not alias c (callers refill a piece in place).
template <class T>
void portion_into(std::span<const T> c, double a, double b, T* out) {
  const std::size_t n = c.size() - 1;
  if (1 <= n && n <= 3) {
    detail::portion_low_degree(c.data(), n, a, b, out);
    return;
  }
  SmallArray<T> row(n + 1, typename SmallArray<T>::Uninitialized{});
  SmallArray<T> work(n + 1, typename SmallArray<T>::Uninitialized{});
  detail::portion_rounds(c.data(), n, a, b, row.data(), work.data(), out);
}

/// portion_into for E = n + 1 >= 1 coefficients fixed at compile time: the same values,
/// the rounds unrolled for the size and kept scalar (BEZIER_SCALAR_ROUNDS).
template <std::size_t E, class T>
BEZIER_SCALAR_ROUNDS void portion_into_fixed(const T* c, double a, double b, T* out) {
  static_assert(E >= 1 && E != std::dynamic_extent);
  if constexpr (2 <= E && E <= 4) {
    detail::portion_low_degree(c, E - 1, a, b, out);
  } else {
    std::array<T, E> row, work;
    detail::portion_rounds(c, E - 1, a, b, row.data(), work.data(), out);
  }
}

/// portion_into as a new array.
template <class T>
[[nodiscard]] SmallArray<T> portion(std::span<const T> c, double a, double b) {
  SmallArray<T> out(c.size(), typename SmallArray<T>::Uninitialized{});
  portion_into(c, a, b, out.data());
  return out;
}

/// p(t) by de Casteljau.
[[nodiscard]] inline double evaluate(std::span<const double> c, double t) {
  SmallArray<double> row(c);  // inline storage up to degree 23
  for (std::size_t level = c.size() - 1; level > 0; --level) {
    for (std::size_t k = 0; k < level; ++k) row[k] = bernstein::lerp(row[k], row[k + 1], t);
  }
  return row[0];
}

/// Largest |c_i|.
[[nodiscard]] inline double max_abs(std::span<const double> c) noexcept {
  double m = 0.0;
  for (const double v : c) m = max2(m, std::fabs(v));
  return m;
}

/// A conservative hull of {t in [0,1] : the control polygon's convex hull K meets the band
/// lo <= y <= hi}, for the points (i/n, c_i). Its left end is 0 when c_0 is in the band.
/// When c_0 is below it, the left end lies at the level lo: from a point of K in the band
/// above lo, the segment to (0, c_0), inside K, leads further left within the band. It is
/// the left end of K on that level, on the edge of K's upper chain that rises through lo,
/// whose left end is below lo and right end at or above it; every segment between two
/// control points lies in K, so the minimum over the segments (i < j, c_i < lo <= c_j) of
/// their crossings of lo is exact. Mirrored for c_0 above the band (level hi, segments
/// falling through it) and for the right end (c_n). The crossing abscissae are computed with
/// a few roundings; the result is widened by 8 u on each side and clamped to [0, 1]. Empty
/// (nullopt) exactly when every c_i < lo or every c_i > hi. This is the clip of Sederberg &
/// Nishita (1990), without building the hull: only the segments and the level each end
/// needs are tested, not every segment against both levels. For E
/// coefficients, E fixed at compile time for the low degrees (fixed_extent.hpp: the loops
/// unroll) or dynamic.
template <std::size_t E>
[[nodiscard]] std::optional<ParamInterval> hull_clip_of(std::span<const double, E> c, double lo,
                                                        double hi) {
  const std::size_t n = c.size() - 1;
  // Bitwise operators: selects, not branches the data decides.
  bool any_below = false, any_above = false, any_inside = false;
  for (const double v : c) {
    const bool below = v < lo;
    const bool above = v > hi;
    any_below |= below;
    any_above |= above;
    any_inside |= !(below | above);
  }
  if (!any_inside && !(any_below && any_above)) return std::nullopt;
  if (!any_below && !any_above) return ParamInterval{0.0, 1.0};
  if (n == 0) return ParamInterval{0.0, 1.0};
  const double inv_n = 1.0 / static_cast<double>(n);
  // Where segment i < j crosses `level` (its ends on either side of it or at it).
  const auto crossing = [&](std::size_t i, std::size_t j, double level) {
    const double xi = static_cast<double>(i) * inv_n, dx = static_cast<double>(j - i) * inv_n;
    return xi + dx * ((level - c[i]) / (c[j] - c[i]));
  };
  double t_min = 0.0, t_max = 1.0;
  if (c[0] < lo || c[0] > hi) {
    // sign (c - level) < 0: on c_0's side of the level.
    const double level = c[0] < lo ? lo : hi, sign = c[0] < lo ? 1.0 : -1.0;
    t_min = 2.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double side_i = sign * (c[i] - level);
      for (std::size_t j = i + 1; j <= n; ++j) {
        const double side_j = sign * (c[j] - level);
        if ((side_i < 0) & (side_j >= 0)) t_min = min2(t_min, crossing(i, j, level));
      }
    }
  }
  if (c[n] < lo || c[n] > hi) {
    const double level = c[n] < lo ? lo : hi, sign = c[n] < lo ? 1.0 : -1.0;
    t_max = -1.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double side_i = sign * (c[i] - level);
      for (std::size_t j = i + 1; j <= n; ++j) {
        const double side_j = sign * (c[j] - level);
        if ((side_j < 0) & (side_i >= 0)) t_max = max2(t_max, crossing(i, j, level));
      }
    }
  }
  const double pad = 8 * kUnitRoundoff;
  return ParamInterval{max2(0.0, t_min - pad), min2(1.0, t_max + pad)};
}

[[nodiscard]] inline std::optional<ParamInterval> hull_clip(std::span<const double> c, double lo,
                                                            double hi) {
  return hull_clip_of<std::dynamic_extent>(c, lo, hi);
}

}  // namespace bezier::core::bernstein
