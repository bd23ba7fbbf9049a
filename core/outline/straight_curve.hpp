#pragma once

#include <span>

#include "core/base/point.hpp"

namespace bezier::outline {

/// Whether the control points lie on one line, decided exactly: the sign of every
/// cross(P_i - P_0, P_k - P_0) (P_k a control point other than P_0) is zero in exact
/// arithmetic (a floating-point filter, then Shewchuk's expansions, core/numeric/expansion.hpp,
/// for the crosses the filter cannot decide). Then B(t) stays on that line, B' is parallel to
/// it wherever it is not zero, and the unit normal N is constant between the zeros of B': the
/// parallel curve of such a piece is the piece itself moved by d N (offset.hpp).
/// True for a curve that is one point. Conservative where exactness is out of reach: false
/// when a nonzero coordinate is below 2^-400 or above 2^400 in magnitude, or not finite (the
/// expansions' products could underflow or overflow; offset.hpp scales the curve first).
[[nodiscard]] bool control_points_collinear(std::span<const core::Point2> p);

}  // namespace bezier::outline
