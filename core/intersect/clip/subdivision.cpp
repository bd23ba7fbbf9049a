#include "core/intersect/clip/subdivision.hpp"

namespace bezier::core {

namespace {

struct Side {
  bool outside = false;
  bool noisy = false;
};

/// Whether the distances of `x` all lie outside the fat line of `g` (with every margin).
Side outside_fat_line(const Piece& x, const Piece& g) {
  const FatLine line = fat_line(g, x);
  const DistanceCoefficients d = distance_coefficients(line, x);
  const double lo = line.d_min - d.error, hi = line.d_max + d.error;
  bool all_below = true, all_above = true;
  for (const double v : d.a) {
    all_below = all_below && v < lo;
    all_above = all_above && v > hi;
  }
  return {all_below || all_above, is_noisy(line, d)};
}

}  // namespace

Separation separation(const Piece& f, const Piece& g) {
  if (bounding_boxes_disjoint(f, g)) return {true, false};
  const Side a = outside_fat_line(f, g);
  if (a.outside) return {true, false};
  const Side b = outside_fat_line(g, f);
  if (b.outside) return {true, false};
  return {false, a.noisy && b.noisy};
}

}  // namespace bezier::core
