#pragma once

// Pieces written by hand for the clipping tests.

#include <vector>

#include "core/intersect/working_curve.hpp"

namespace bezier::test {

/// The piece with control points (x_i, y_i) and the given error bound.
[[nodiscard]] inline core::Piece piece_of(const std::vector<double>& x, const std::vector<double>& y,
                                          double error = 0.0) {
  core::Piece p;
  p.x = core::Coeffs(x);
  p.y = core::Coeffs(y);
  p.error = error;
  return p;
}

}  // namespace bezier::test
