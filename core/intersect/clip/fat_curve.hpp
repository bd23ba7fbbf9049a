#pragma once

#include <optional>
#include <span>

#include "core/bernstein/degree.hpp"
#include "core/numeric/small_array.hpp"
#include "core/intersect/clip/fat_line.hpp"
#include "core/intersect/result.hpp"

namespace bezier::core {

/// The linear maps behind a fat curve of degree k for pieces of degree n, built once per
/// call (no static cache): R, the L2-best reduction to degree k, and E, the elevation back
/// to degree n. For n <= k no reduction is needed and the fat curve is the distance
/// function itself.
struct FatCurveOperator {
  int n = 0;
  int k = 0;  ///< min(requested k, n)
  /// Row-major entries of R, (k+1) x (n+1), and of E, (n+1) x (k+1): the compile-time
  /// tables of degree.hpp when they cover (n, k), else the owned matrices below.
  const double* reduce = nullptr;
  const double* elevate = nullptr;
  BernsteinMatrix owned_reduce;
  BernsteinMatrix owned_elevate;

  FatCurveOperator() = default;
  FatCurveOperator(const FatCurveOperator&) = delete;  // the pointers may point into owned_*
  FatCurveOperator& operator=(const FatCurveOperator&) = delete;
  FatCurveOperator(FatCurveOperator&&) noexcept = default;  // vectors keep their buffers
  FatCurveOperator& operator=(FatCurveOperator&&) noexcept = default;
  ~FatCurveOperator() = default;
};

[[nodiscard]] FatCurveOperator fat_curve_operator(int n, int k);

/// A fat curve of a scalar Bernstein polynomial D of degree n (Lou & Liu 2012, hybrid.hpp):
/// p = R a, the L2-best degree-k approximation, and delta with |D(t) - p(t)| <= delta for all
/// t in [0, 1]. delta = max_i |a_i - c_i| over the coefficients c = E p of p elevated back to
/// degree n (D - p has Bernstein coefficients a - c, and a Bernstein polynomial is bounded
/// by its largest coefficient); it is enlarged by the rounding of E p and of the
/// differences, so the bound holds for p exactly as stored.
struct FatCurve {
  Coeffs p;
  double delta = 0.0;
};

[[nodiscard]] FatCurve fat_curve(const FatCurveOperator& op, std::span<const double> a);

/// One hybrid clip: the part of the piece's domain where its distance function D can be
/// inside the fat line's band [lo, hi], i.e. where p(t) is within delta + (the distance
/// coefficients' error) of the band; roots of degree-k polynomials, closed form
/// (kept_interval). nullopt when the piece certainly misses the band.
[[nodiscard]] std::optional<ParamInterval> fat_curve_clip(const FatCurveOperator& op,
                                                          const DistanceCoefficients& d, double lo,
                                                          double hi);

}  // namespace bezier::core
