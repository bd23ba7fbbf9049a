#pragma once

#include <vector>

#include "core/base/curve.hpp"
#include "core/numeric/small_array.hpp"
#include "core/numeric/double_double.hpp"

namespace bezier::core {

/// The frame the search works in: p -> (p - origin) * 2^exponent, so that the largest
/// working coordinate is about 1. Translating or scaling both inputs by a power of two moves
/// the frame with them, so the search sees the same numbers (answers do not change under
/// translation and uniform scaling). The exponent spans the whole double range
/// (about -1024 for coordinates next to the largest double, up to 1074 for subnormal ones),
/// more than one double can scale by, so it is kept as an integer.
struct WorkingFrame {
  Point2 origin;
  int exponent = 0;
};

/// The frame of a pair of curves: origin at the centre of their common bounding box,
/// rounded to 12 significant bits (so that coordinates on a coarser grid subtract exactly),
/// exponent -e with 2^e >= the largest centred coordinate.
[[nodiscard]] WorkingFrame working_frame(const Curve& f, const Curve& g);

/// A curve in the working frame, held exactly: coordinate = hi + lo, where hi is the
/// rounded centred coordinate and lo its rounding error (TwoSum), so the double-double
/// pieces and residuals lose nothing to the change of frame. (Scaling by a power of two is
/// exact unless it underflows; coordinates below 2^-1000 of the curves' size are flushed,
/// which is far below any tolerance here.)
struct WorkingCurve {
  int degree = 0;
  Coeffs x, y;               ///< hi parts
  Coeffs x_lo, y_lo;         ///< lo parts
  double magnitude = 0.0;    ///< max |hi| over all coordinates (<= about 1)
  double frame_error = 0.0;  ///< max |lo|: how far hi is from the exact working curve
  bool is_point = false;     ///< every control point is the same point, exactly
};

[[nodiscard]] WorkingCurve to_working(const Curve& curve, WorkingFrame frame);

/// A piece of a working curve, f restricted to [a, b], in a local frame (the working frame
/// shifted by `center`): every exact control point of f|[a,b] - center lies within `error`
/// of (x_i, y_i) in each coordinate. The error bound covers the frame's rounding, the
/// arithmetic of the portion and the rounding to the local frame, so every test that adds
/// it to its margins is conservative.
struct Piece {
  Coeffs x, y;
  double error = 0.0;
  [[nodiscard]] int degree() const noexcept { return static_cast<int>(x.size()) - 1; }
};

/// f on [a, b] in doubles, in the working frame itself (center 0). Error bound:
/// frame_error + lerp_levels_error_bound(n, magnitude) (about 3.02 n u magnitude).
/// Precondition: 0 <= a <= b <= 1.
[[nodiscard]] Piece fast_piece(const WorkingCurve& f, double a, double b);
/// The same into an existing piece (no temporaries: the search refills its two pieces at
/// every step).
void fast_piece_into(const WorkingCurve& f, double a, double b, Piece& out);

/// f on [a, b] computed in double-doubles and then rounded into the frame centred at
/// `center`: error bound u |local coordinate| + (12 n + 4) u^2 magnitude, so a small piece
/// keeps its shape to the last bits of its own size, not of the curve's. Used near
/// tangencies, where the fast pieces' rounding hides whether the curves touch.
[[nodiscard]] Piece compensated_piece(const WorkingCurve& f, double a, double b, Point2 center);

/// f(t) in double-doubles (de Casteljau), for Newton residuals; t in [0, 1].
struct PointDD {
  dd::Real x, y;
};
[[nodiscard]] PointDD evaluate_dd(const WorkingCurve& f, double t);

/// f(t) and f'(t) in doubles (de Casteljau on the hi parts; the derivative from the last
/// level: n (b_1 - b_0)).
struct PointAndTangent {
  Point2 point;
  Point2 tangent;
};
[[nodiscard]] PointAndTangent evaluate_with_tangent(const WorkingCurve& f, double t);

/// f''(t) in doubles (zero for degree < 2).
[[nodiscard]] Point2 second_derivative(const WorkingCurve& f, double t);

/// A working-frame point back in input coordinates.
[[nodiscard]] Point2 from_working(Point2 p, WorkingFrame frame) noexcept;

}  // namespace bezier::core
