#include "core/path/elliptical_arc.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bezier::path {

namespace {

using core::Point2;

/// v / |v| for v != 0, scaled first so that no square overflows or underflows.
Point2 unit(Point2 v) {
  const double scale = std::max(std::abs(v.x), std::abs(v.y));
  const Point2 w = v / scale;
  return w / std::hypot(w.x, w.y);
}

/// The linear part of the affine map from the unit circle to the ellipse, R(φ) diag(rx, ry):
/// it carries differences of unit-circle points to differences of ellipse points.
struct EllipseFrame {
  double cos_phi = 1.0;
  double sin_phi = 0.0;
  double rx = 1.0;
  double ry = 1.0;

  [[nodiscard]] Point2 map(Point2 p) const {
    const double x = rx * p.x;
    const double y = ry * p.y;
    return {cos_phi * x - sin_phi * y, sin_phi * x + cos_phi * y};
  }
};

/// R(-φ) v.
Point2 rotated_back(Point2 v, double cos_phi, double sin_phi) {
  return {cos_phi * v.x + sin_phi * v.y, -sin_phi * v.x + cos_phi * v.y};
}

/// The widest angle of one cubic: a quarter turn (with slack, so that a quarter turn given
/// as the double nearest π/2 stays one piece). Narrower pieces than the tolerance needs
/// keep the cubics' control polygons close to their curves.
constexpr double kMaxPieceAngle = std::numbers::pi / 2.0 + 1e-9;

/// The arc in centre form (see the header), as the images of the unit circle's frame at the
/// start point: u1 = m ê + s q ê⊥ is the start on the unit circle and u1⊥ its tangent, so a
/// point of the circle γ radians further is e(γ) = cos γ u1 + sin γ u1⊥, carried to the
/// ellipse by the frame with A(ê) = `along` and A(ê⊥) = `across`. The sweep is the angle
/// from u1 to u2 in [-π, π] (before the sweep flag picks its turn).
struct CentreForm {
  EllipseFrame frame;
  Point2 along;   ///< A(ê): the image of the unit vector along the chord (ê).
  Point2 across;  ///< A(ê⊥)
  double m = 0.0;
  double sq = 0.0;  ///< s q
  double sweep_angle = 0.0;

  /// A(u1) and A(u1⊥), the start's radius and tangent on the ellipse, rotated by γ:
  /// A(e(γ)) and A(e'(γ)), each as a combination of `along` and `across` (no angle of the
  /// circle is formed, so nothing rounds against the ellipse's absolute direction).
  [[nodiscard]] Point2 tangent(double gamma) const {
    const double c = std::cos(gamma), s = std::sin(gamma);
    return (m * c - sq * s) * across - (sq * c + m * s) * along;
  }
  /// A(e(γ) - e(0)) = A((cos γ - 1) u1 + sin γ u1⊥), with cos γ - 1 = -2 sin²(γ/2) (no
  /// cancellation for small γ).
  [[nodiscard]] Point2 chord(double gamma) const {
    const double h = std::sin(gamma / 2.0), s = std::sin(gamma);
    const double back = -2.0 * h * h;
    return (back * m - sq * s) * along + (back * sq + m * s) * across;
  }
};

CentreForm centre_form(const EllipticalArc& arc, double rx, double ry, double cos_phi,
                       double sin_phi) {
  // The half chord in the ellipse's axes, (x', y') = R(-φ) (from - to) / 2, halved first so
  // that the difference cannot overflow (it may underflow to zero for end points a few
  // subnormals apart: its direction comes from the chord scaled to magnitude 1 instead).
  const Point2 half{arc.from.x / 2.0 - arc.to.x / 2.0, arc.from.y / 2.0 - arc.to.y / 2.0};
  const Point2 h = rotated_back(half, cos_phi, sin_phi);
  // ê, the direction of d = (x' / rx, y' / ry), from a vector parallel to it: the chord's
  // direction in the ellipse's axes with x scaled by ry / rx (or y by rx / ry), so that
  // nothing overflows and a nonzero chord never gives a zero vector.
  Point2 chord = arc.from - arc.to;
  if (!core::is_finite(chord)) chord = half;
  const Point2 c = rotated_back(unit(chord), cos_phi, sin_phi);
  const Point2 e = unit(rx >= ry ? Point2{c.x * (ry / rx), c.y} : Point2{c.x, c.y * (rx / ry)});
  const Point2 e_perp{-e.y, e.x};
  // m in long double: x' / rx overflows a double for radii far below the chord (a subnormal
  // radius), while the scaled radii rx m, ry m are about the chord's size.
  const long double m_wide = std::hypot(static_cast<long double>(h.x) / rx, static_cast<long double>(h.y) / ry);
  double m = static_cast<double>(m_wide);
  if (m_wide > 1.0L) {  // radii too small: scaled up to reach (B.2.5, Λ = m² > 1)
    rx = static_cast<double>(rx * m_wide);
    ry = static_cast<double>(ry * m_wide);
    m = 1.0;
  }
  const double q = std::sqrt(std::max(0.0, (1.0 - m) * (1.0 + m)));
  const double s = arc.large_arc != arc.sweep ? 1.0 : -1.0;
  CentreForm out;
  out.frame = EllipseFrame{cos_phi, sin_phi, rx, ry};
  out.along = out.frame.map(e);
  out.across = out.frame.map(e_perp);
  out.m = m;
  out.sq = s * q;
  // The angle from u1 to u2 = -m ê + s q ê⊥: cross(u1, u2) = 2 s m q and
  // dot(u1, u2) = q² - m², so it is s times twice the angle of (q, m). Taken from m and q
  // directly, it keeps its relative precision when the chord is tiny against the radii (m
  // near 0), where u1 and u2 agree in nearly every bit and their cross product would be
  // rounding noise.
  out.sweep_angle = s * 2.0 * std::atan2(m, q);
  return out;
}

/// The number n of pieces of an arc of `sweep` radians (> 0) whose cubics are within
/// `relative` times the radius of the circle (circular_arc_cubic_error) and at most
/// kMaxPieceAngle each, with n - 1 pieces not (or n = 1); nullopt when that is more than
/// max_pieces. ε(δ) = (2/27) (δ/4)⁶ (1 + O(δ⁴)) for small δ: the first guess from it is
/// close, and the count is then corrected.
std::optional<std::size_t> piece_count(double sweep, double relative, std::size_t max_pieces) {
  const double guess =
      std::min(kMaxPieceAngle, 4.0 * std::pow(13.5 * std::min(relative, 1.0), 1.0 / 6.0));
  const double first_count = std::ceil(sweep / guess);
  if (!(first_count <= static_cast<double>(max_pieces))) return std::nullopt;
  const auto fits = [&](std::size_t pieces) {
    const double piece = sweep / static_cast<double>(pieces);
    return piece <= kMaxPieceAngle && circular_arc_cubic_error(piece) <= relative;
  };
  auto n = std::max<std::size_t>(1, static_cast<std::size_t>(first_count));
  while (!fits(n)) ++n;
  while (n > 1 && fits(n - 1)) --n;
  if (n > max_pieces) return std::nullopt;
  return n;
}

/// The n cubics of the arc from the start through `sweep_angle` on the frame's unit circle,
/// each the circular-arc cubic (k = 4/3 tan(δ/4)) mapped by the frame, appended to
/// `segments`: the first starts at arc.from and the last ends at arc.to bit for bit. Every
/// point is built from the start point, as arc.from + A(e(γ) - e(0)), and the handles as
/// A(k e'(γ)) (CentreForm): no point goes through the centre, which for radii far larger
/// than the chord is far from the arc (its coordinates would round away the arc's). False,
/// with nothing appended, when a control point is not finite.
bool append_cubics(const EllipticalArc& arc, const CentreForm& centred, double sweep_angle,
                   std::size_t n, std::vector<core::Curve>& segments) {
  const double delta = sweep_angle / static_cast<double>(n);
  const double k = 4.0 / 3.0 * std::tan(delta / 4.0);
  // γ of joint j, one formula for the cubic that ends there and the one that starts there,
  // so that they share the joint bit for bit.
  const auto gamma = [&](std::size_t j) {
    return sweep_angle * (static_cast<double>(j) / static_cast<double>(n));
  };
  segments.reserve(n);
  Point2 start = arc.from;
  for (std::size_t j = 0; j < n; ++j) {
    const Point2 end = j + 1 == n ? arc.to : arc.from + centred.chord(gamma(j + 1));
    const Point2 p1 = start + k * centred.tangent(gamma(j));
    const Point2 p2 = end - k * centred.tangent(gamma(j + 1));
    if (!core::is_finite(p1) || !core::is_finite(p2) || !core::is_finite(end)) {
      segments.clear();
      return false;
    }
    segments.emplace_back(std::vector<Point2>{start, p1, p2, end});
    start = end;
  }
  return true;
}

}  // namespace

double circular_arc_cubic_error(double angle) {
  const double h = angle / 4.0;
  const double s = std::sin(h);
  const double c = std::cos(h);
  const double s3 = s * s * s;
  // √(1 + x) - 1 written as x / (√(1 + x) + 1): no cancellation for small x.
  const double x = (4.0 / 27.0) * (s3 * s3) / (c * c);
  return x / (std::sqrt(1.0 + x) + 1.0);
}

ArcSegments arc_to_cubics(const EllipticalArc& arc, std::optional<double> tolerance,
                          std::size_t max_pieces) {
  ArcSegments out;
  if (arc.from == arc.to) return out;
  const double rx = std::abs(arc.rx);
  const double ry = std::abs(arc.ry);
  // φ modulo 360 degrees.
  const double phi = std::fmod(arc.x_axis_rotation_degrees, 360.0) * (std::numbers::pi / 180.0);
  const double cos_phi = std::cos(phi);
  const double sin_phi = std::sin(phi);
  const auto line = [&](double within) {
    if (max_pieces < 1) {
      out.status = ArcStatus::too_many_pieces;
      return out;
    }
    out.segments.emplace_back(std::vector<Point2>{arc.from, arc.to});
    out.tolerance = within;
    return out;
  };
  if (rx == 0.0 || ry == 0.0) return line(0.0);  // a zero radius is a line (B.2.5)

  const CentreForm centred = centre_form(arc, rx, ry, cos_phi, sin_phi);
  const EllipseFrame& frame = centred.frame;
  double sweep_angle = centred.sweep_angle;
  const double radius = std::max(frame.rx, frame.ry);
  if (!std::isfinite(frame.rx) || !std::isfinite(frame.ry)) {
    out.status = ArcStatus::out_of_range;  // an ellipse reaching beyond the double range
    return out;
  }
  const double asked = tolerance.value_or(kDefaultArcRelativeTolerance * radius);
  // m zero in doubles (the half chord below the least subnormal of the radii) leaves Δθ = 0
  // for the small arc, which is then the chord to within its sagitta, radius · m² / 2.
  const bool chord_only = sweep_angle == 0.0 && !arc.large_arc;
  if (arc.sweep && sweep_angle <= 0.0 && !chord_only) sweep_angle += 2.0 * std::numbers::pi;
  if (!arc.sweep && sweep_angle >= 0.0 && !chord_only) sweep_angle -= 2.0 * std::numbers::pi;
  // The coordinates the cubics' points are computed in: the start point plus chords and
  // handles of the ellipse, none longer than radius · min(|Δθ|, 2) (a chord of the unit
  // circle is at most 2 and at most the angle it spans), or, where that is less, the
  // ellipse's own extent |C|∞ + radius (the start is within it, and every chord and handle
  // within a few radii).
  const Point2 centre = Point2{arc.from.x / 2.0 + arc.to.x / 2.0, arc.from.y / 2.0 + arc.to.y / 2.0} -
                        centred.sq * centred.across;
  const double magnitude =
      std::min(core::max_abs_coordinate(centre) + radius,
               std::max(core::max_abs_coordinate(arc.from), core::max_abs_coordinate(arc.to)) +
                   radius * std::min(std::abs(sweep_angle), 2.0));
  const double used = std::max(asked, kArcToleranceFloor * magnitude);
  if (chord_only) return line(used);
  out.tolerance = used;
  // The approximation's share of the tolerance, relative to the larger radius.
  const double relative = out.tolerance / 2.0 / radius;
  const std::optional<std::size_t> n = piece_count(std::abs(sweep_angle), relative, max_pieces);
  if (!n) {
    out.status = ArcStatus::too_many_pieces;
    out.tolerance = 0.0;
    return out;
  }
  if (!append_cubics(arc, centred, sweep_angle, *n, out.segments)) {
    out.status = ArcStatus::out_of_range;
    out.tolerance = 0.0;
  }
  return out;
}

}  // namespace bezier::path
