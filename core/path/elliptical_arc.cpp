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

/// The affine map from the unit circle to the ellipse: C + R(φ) diag(rx, ry) p.
struct EllipseFrame {
  Point2 centre;
  double cos_phi = 1.0;
  double sin_phi = 0.0;
  double rx = 1.0;
  double ry = 1.0;

  [[nodiscard]] Point2 map(Point2 p) const {
    const double x = rx * p.x;
    const double y = ry * p.y;
    return {centre.x + (cos_phi * x - sin_phi * y), centre.y + (sin_phi * x + cos_phi * y)};
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

Point2 on_circle(double angle) { return {std::cos(angle), std::sin(angle)}; }

/// The arc in centre form (see the header): the ellipse's frame, the angle θ1 of the start
/// point on its unit circle and the angle from u1 to u2 in (-π, π] (before the sweep flag
/// picks its turn; 0 when u1 and u2 are equal in doubles).
struct CentreForm {
  EllipseFrame frame;
  double theta1 = 0.0;
  double sweep_angle = 0.0;
};

/// The endpoint to centre parametrisation (B.2.4, written in the ellipse's unit
/// coordinates) of an arc whose end points differ, with radii rx, ry > 0 (absolute values)
/// and rotation φ given by its cosine and sine; radii too small to reach are scaled up
/// (B.2.5, Λ = m² > 1), so the frame's radii may exceed rx and ry, or be infinite for an
/// ellipse beyond the double range.
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
  const Point2 mid{arc.from.x / 2.0 + arc.to.x / 2.0, arc.from.y / 2.0 + arc.to.y / 2.0};
  CentreForm out;
  out.frame = EllipseFrame{mid, cos_phi, sin_phi, rx, ry};
  out.frame.centre = out.frame.map(-s * q * e_perp);
  const Point2 u1 = m * e + s * q * e_perp;
  const Point2 u2 = -m * e + s * q * e_perp;
  out.theta1 = std::atan2(u1.y, u1.x);
  out.sweep_angle = std::atan2(cross(u1, u2), dot(u1, u2));
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

/// The n cubics of the arc from θ1 through `sweep_angle` on the frame's unit circle, each
/// the circular-arc cubic (k = 4/3 tan(δ/4)) mapped by the frame, appended to out.segments:
/// the first starts at arc.from and the last ends at arc.to bit for bit. False, with
/// nothing appended, when a control point is not finite.
bool append_cubics(const EllipticalArc& arc, const EllipseFrame& frame, double theta1,
                   double sweep_angle, std::size_t n, std::vector<core::Curve>& segments) {
  const double delta = sweep_angle / static_cast<double>(n);
  const double k = 4.0 / 3.0 * std::tan(delta / 4.0);
  // The angle of joint j, one formula for the cubic that ends there and the one that
  // starts there, so that they share the joint bit for bit.
  const auto angle = [&](std::size_t j) {
    return theta1 + sweep_angle * (static_cast<double>(j) / static_cast<double>(n));
  };
  segments.reserve(n);
  Point2 start = arc.from;
  for (std::size_t j = 0; j < n; ++j) {
    const Point2 a = on_circle(angle(j));
    const Point2 b = on_circle(angle(j + 1));
    const Point2 p1 = frame.map(a + k * Point2{-a.y, a.x});
    const Point2 p2 = frame.map(b - k * Point2{-b.y, b.x});
    const Point2 end = j + 1 == n ? arc.to : frame.map(b);
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
  const double magnitude = std::max(std::abs(frame.centre.x), std::abs(frame.centre.y)) + radius;
  const double asked = tolerance.value_or(kDefaultArcRelativeTolerance * radius);
  const double used = std::max(asked, kArcToleranceFloor * magnitude);
  if (!std::isfinite(magnitude) || !std::isfinite(frame.rx) || !std::isfinite(frame.ry)) {
    out.status = ArcStatus::out_of_range;  // an ellipse reaching beyond the double range
    return out;
  }
  // u1 and u2 equal in doubles: the chord subtends less than an ulp of angle (m below about
  // 1e-16), and the small arc is the chord to within its sagitta, about radius · m² / 2.
  if (sweep_angle == 0.0 && !arc.large_arc) return line(used);
  if (arc.sweep && sweep_angle <= 0.0) sweep_angle += 2.0 * std::numbers::pi;
  if (!arc.sweep && sweep_angle >= 0.0) sweep_angle -= 2.0 * std::numbers::pi;
  out.tolerance = used;
  // The approximation's share of the tolerance, relative to the larger radius.
  const double relative = out.tolerance / 2.0 / radius;
  const std::optional<std::size_t> n = piece_count(std::abs(sweep_angle), relative, max_pieces);
  if (!n) {
    out.status = ArcStatus::too_many_pieces;
    out.tolerance = 0.0;
    return out;
  }
  if (!append_cubics(arc, frame, centred.theta1, sweep_angle, *n, out.segments)) {
    out.status = ArcStatus::out_of_range;
    out.tolerance = 0.0;
  }
  return out;
}

}  // namespace bezier::path
