#include "core/intersect/clip/bezier_clip.hpp"

#include "core/bernstein/bernstein1d.hpp"

namespace bezier::core {

Clip bezier_clip(const Piece& x, const Piece& other, PointLineDirection direction) {
  const FatLine line = fat_line(other, x, direction);
  const DistanceCoefficients d = distance_coefficients(line, x);
  return {bernstein::hull_clip(d.a, line.d_min - d.error, line.d_max + d.error), is_noisy(line, d)};
}

}  // namespace bezier::core
