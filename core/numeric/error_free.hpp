#pragma once

#include <cmath>

#include "core/base/point.hpp"

namespace bezier::core {

/// An unevaluated sum hi + lo: the result of an error-free transformation.
template <class T>
struct TwoTerm {
  T hi;
  T lo;
};

/// a + b = hi + lo exactly, with hi = fl(a + b) (Knuth's TwoSum, TAOCP vol. 2, §4.2.2;
/// branch-free, any order of magnitudes). Exact unless a + b overflows. Relies on strict
/// IEEE evaluation: no -ffast-math, no contraction of a - b into a fused operation.
[[nodiscard]] constexpr TwoTerm<double> two_sum(double a, double b) noexcept {
  const double s = a + b;
  const double b_virtual = s - a;
  return {s, (a - (s - b_virtual)) + (b - b_virtual)};
}

/// a b = hi + lo exactly, with hi = fl(a b): the fused multiply-add gives the rounding
/// error of the product in one rounding (exact unless the product over- or underflows).
/// (Dekker's split-based TwoProduct avoids the libm call on x86-64 builds without -mfma,
/// but is no faster: glibc dispatches fma to the hardware instruction.)
[[nodiscard]] inline TwoTerm<double> two_product(double a, double b) noexcept {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

/// The same transformations coordinate by coordinate.
[[nodiscard]] inline TwoTerm<Point2> two_sum(Point2 a, Point2 b) noexcept {
  const auto x = two_sum(a.x, b.x), y = two_sum(a.y, b.y);
  return {{x.hi, y.hi}, {x.lo, y.lo}};
}
[[nodiscard]] inline TwoTerm<Point3> two_sum(Point3 a, Point3 b) noexcept {
  const auto x = two_sum(a.x, b.x), y = two_sum(a.y, b.y), z = two_sum(a.z, b.z);
  return {{x.hi, y.hi, z.hi}, {x.lo, y.lo, z.lo}};
}
[[nodiscard]] inline TwoTerm<Point2> two_product(double s, Point2 a) noexcept {
  const auto x = two_product(s, a.x), y = two_product(s, a.y);
  return {{x.hi, y.hi}, {x.lo, y.lo}};
}
[[nodiscard]] inline TwoTerm<Point3> two_product(double s, Point3 a) noexcept {
  const auto x = two_product(s, a.x), y = two_product(s, a.y), z = two_product(s, a.z);
  return {{x.hi, y.hi, z.hi}, {x.lo, y.lo, z.lo}};
}

}  // namespace bezier::core
