#include "core/intersect/clip/hybrid.hpp"

namespace bezier::core {

Clip hybrid_clip(const Piece& x, const Piece& other, const FatCurveOperator& op,
                 PointLineDirection direction) {
  const FatLine line = fat_line(other, x, direction);
  const DistanceCoefficients d = distance_coefficients(line, x);
  return {fat_curve_clip(op, d, line.d_min, line.d_max), is_noisy(line, d)};
}

}  // namespace bezier::core
