#pragma once

#include <cmath>

namespace bezier::core {

/// A point (or vector) in the plane. Plain coordinates, passed by value.
struct Point2 {
  double x = 0.0;
  double y = 0.0;

  /// Exact comparison: equal coordinates bit for bit (+0 == -0, NaN != NaN).
  friend constexpr bool operator==(Point2, Point2) = default;
};

/// A point (or vector) in space.
struct Point3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;

  friend constexpr bool operator==(Point3, Point3) = default;
};

constexpr Point2 operator+(Point2 a, Point2 b) noexcept { return {a.x + b.x, a.y + b.y}; }
constexpr Point2 operator-(Point2 a, Point2 b) noexcept { return {a.x - b.x, a.y - b.y}; }
constexpr Point2 operator-(Point2 a) noexcept { return {-a.x, -a.y}; }
constexpr Point2 operator*(double s, Point2 a) noexcept { return {s * a.x, s * a.y}; }
constexpr Point2 operator*(Point2 a, double s) noexcept { return {a.x * s, a.y * s}; }
constexpr Point2 operator/(Point2 a, double s) noexcept { return {a.x / s, a.y / s}; }

constexpr Point3 operator+(Point3 a, Point3 b) noexcept {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
constexpr Point3 operator-(Point3 a, Point3 b) noexcept {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
constexpr Point3 operator-(Point3 a) noexcept { return {-a.x, -a.y, -a.z}; }
constexpr Point3 operator*(double s, Point3 a) noexcept { return {s * a.x, s * a.y, s * a.z}; }
constexpr Point3 operator*(Point3 a, double s) noexcept { return {a.x * s, a.y * s, a.z * s}; }
constexpr Point3 operator/(Point3 a, double s) noexcept { return {a.x / s, a.y / s, a.z / s}; }

/// a · b
constexpr double dot(Point2 a, Point2 b) noexcept { return a.x * b.x + a.y * b.y; }
constexpr double dot(Point3 a, Point3 b) noexcept { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// The z component of a × b: positive when b turns counter-clockwise from a.
constexpr double cross(Point2 a, Point2 b) noexcept { return a.x * b.y - a.y * b.x; }

/// a × b
constexpr Point3 cross(Point3 a, Point3 b) noexcept {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// (1 - t) a + t b, the de Casteljau step. Written in this form, not a + t (b - a),
/// because it returns a exactly at t = 0 and b exactly at t = 1, so a curve's end
/// points are reproduced bit for bit.
template <class P>
constexpr P lerp(P a, P b, double t) noexcept {
  return (1.0 - t) * a + t * b;
}

/// Largest absolute coordinate: the scale that geometric tolerances are relative to.
/// NaN coordinates are ignored by std::fmax.
inline double max_abs_coordinate(Point2 p) noexcept { return std::fmax(std::fabs(p.x), std::fabs(p.y)); }
inline double max_abs_coordinate(Point3 p) noexcept {
  return std::fmax(std::fabs(p.x), std::fmax(std::fabs(p.y), std::fabs(p.z)));
}

/// All coordinates finite (neither infinite nor NaN).
inline bool is_finite(double v) noexcept { return std::isfinite(v); }
inline bool is_finite(Point2 p) noexcept { return std::isfinite(p.x) && std::isfinite(p.y); }
inline bool is_finite(Point3 p) noexcept {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

/// Euclidean length, computed with hypot so it neither overflows nor underflows.
inline double length(Point2 v) noexcept { return std::hypot(v.x, v.y); }
inline double length(Point3 v) noexcept { return std::hypot(v.x, v.y, v.z); }

}  // namespace bezier::core
