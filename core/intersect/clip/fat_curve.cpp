#include "core/intersect/clip/fat_curve.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/intersect/clip/band_solve.hpp"
#include "core/bernstein/bernstein1d.hpp"
#include "core/numeric/min_max.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {

FatCurveOperator fat_curve_operator(int n, int k) {
  assert(n >= 0 && k >= 1);
  FatCurveOperator op;
  op.n = n;
  op.k = std::min(k, n);
  if (op.k < n) {
    op.reduce = l2_reduction_table(n, op.k);
    op.elevate = elevation_table(op.k, n);
    if (op.reduce == nullptr) {
      op.owned_reduce = l2_reduction_matrix(n, op.k);
      op.reduce = op.owned_reduce.entries.data();
    }
    if (op.elevate == nullptr) {
      op.owned_elevate = elevation_matrix(op.k, n);
      op.elevate = op.owned_elevate.entries.data();
    }
  }
  return op;
}

FatCurve fat_curve(const FatCurveOperator& op, std::span<const double> a) {
  assert(static_cast<int>(a.size()) == op.n + 1);
  FatCurve out;
  if (op.k >= op.n) {
    out.p = Coeffs(a);
    return out;
  }
  const int k = op.k, n = op.n;
  out.p.resize(static_cast<std::size_t>(k + 1));
  for (int i = 0; i <= k; ++i) {
    double sum = 0.0;
    const double* row = op.reduce + i * (n + 1);
    for (int j = 0; j <= n; ++j) sum += row[j] * a[static_cast<std::size_t>(j)];
    out.p[static_cast<std::size_t>(i)] = sum;
  }
  double delta = 0.0;
  for (int i = 0; i <= n; ++i) {
    double c = 0.0;
    const double* row = op.elevate + i * (k + 1);
    for (int j = 0; j <= k; ++j) c += row[j] * out.p[static_cast<std::size_t>(j)];
    delta = max2(delta, std::fabs(a[static_cast<std::size_t>(i)] - c));
  }
  // E's entries carry one rounding each and the sum k + 1 more; the rows of E are convex
  // combinations, so |fl(E p) - E p| <= (k + 3) u max|p|; the difference rounds once more.
  const double u = kUnitRoundoff;
  out.delta = delta * (1 + 2 * u) + (k + 5) * u * bernstein::max_abs(out.p) + 0x1p-1000;
  return out;
}

std::optional<ParamInterval> fat_curve_clip(const FatCurveOperator& op,
                                            const DistanceCoefficients& d, double lo, double hi) {
  // Degree <= k: the fat curve is the distance function itself (delta = 0), no copy.
  if (op.k >= op.n) return kept_interval(d.a, lo - d.error, hi + d.error);
  const FatCurve fc = fat_curve(op, d.a);
  const double widen = fc.delta + d.error;
  return kept_interval(fc.p, lo - widen, hi + widen);
}

}  // namespace bezier::core
