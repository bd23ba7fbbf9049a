#include "core/intersect/compensated_point.hpp"

#include <array>

#include "core/numeric/error_free.hpp"
#include "core/numeric/fixed_extent.hpp"
#include "core/numeric/tuning.hpp"
#include "core/base/multiversion.hpp"

namespace bezier::core {

namespace {

/// Degrees evaluated in stack rows (numeric_tuning::kInlineEntries); higher ones take the
/// double-double path.
constexpr std::size_t kMaxDegree = numeric_tuning::kInlineEntries - 1;

/// One compensated de Casteljau step: from the entries (b0, e0) and (b1, e1) of a level
/// (plain de Casteljau values b and their carried errors e), with 1 - t = r_hi + r_lo, the
/// entry of the next level.
struct Entry {
  double b, e;
};
inline Entry step(Entry a, Entry c, double t, double r_hi, double r_lo) noexcept {
  const TwoTerm<double> p1 = two_product(r_hi, a.b);
  const TwoTerm<double> p2 = two_product(t, c.b);
  const TwoTerm<double> s = two_sum(p1.hi, p2.hi);
  return {s.hi, r_hi * a.e + t * c.e + ((p1.lo + p2.lo) + (s.lo + r_lo * a.b))};
}

/// One coordinate's level of E entries.
template <std::size_t E>
using Level = std::array<Entry, E>;

template <std::size_t E>
Level<E> first_level(const Coeffs& hi, const Coeffs& lo, std::size_t n) noexcept {
  Level<E> out;
  for (std::size_t i = 0; i <= n; ++i) out[i] = {hi[i], lo[i]};
  return out;
}

/// The levels below x and y for E = n + 1 entries fixed at compile time, each into a fresh
/// array (levels computed in place in one buffer made GCC's vectoriser reload overlapping
/// pairs of entries just stored, which stalls store forwarding).
template <std::size_t E>
void descend(const Level<E>& x, const Level<E>& y, double dn, double t, TwoTerm<double> r,
             CompensatedPoint& out) noexcept {
  if constexpr (E == 2) out.tangent = {dn * (x[1].b - x[0].b), dn * (y[1].b - y[0].b)};
  Level<E - 1> nx, ny;
  for (std::size_t k = 0; k + 1 < E; ++k) {
    nx[k] = step(x[k], x[k + 1], t, r.hi, r.lo);
    ny[k] = step(y[k], y[k + 1], t, r.hi, r.lo);
  }
  if constexpr (E == 2) {
    const TwoTerm<double> px = two_sum(nx[0].b, nx[0].e), py = two_sum(ny[0].b, ny[0].e);
    out.x = {px.hi, px.lo};
    out.y = {py.hi, py.lo};
  } else {
    descend(nx, ny, dn, t, r, out);
  }
}

/// The same in place in buffers of kMaxDegree + 1 entries, for degrees 4 to kMaxDegree.
CompensatedPoint compensated_in_place(const WorkingCurve& f, std::size_t n, double t) noexcept {
  Level<kMaxDegree + 1> x = first_level<kMaxDegree + 1>(f.x, f.x_lo, n);
  Level<kMaxDegree + 1> y = first_level<kMaxDegree + 1>(f.y, f.y_lo, n);
  const TwoTerm<double> r = two_sum(1.0, -t);  // r.hi is the 1 - t of bernstein::lerp
  CompensatedPoint out;
  for (std::size_t count = n; count > 0; --count) {
    if (count == 1) {
      const double dn = static_cast<double>(n);
      out.tangent = {dn * (x[1].b - x[0].b), dn * (y[1].b - y[0].b)};
    }
    for (std::size_t k = 0; k < count; ++k) {
      x[k] = step(x[k], x[k + 1], t, r.hi, r.lo);
      y[k] = step(y[k], y[k + 1], t, r.hi, r.lo);
    }
  }
  const TwoTerm<double> px = two_sum(x[0].b, x[0].e), py = two_sum(y[0].b, y[0].e);
  out.x = {px.hi, px.lo};
  out.y = {py.hi, py.lo};
  return out;
}

}  // namespace

BEZIER_FMA_CLONES CompensatedPoint evaluate_compensated(const WorkingCurve& f, double t) {
  const std::size_t n = f.x.size() - 1;
  if (n > kMaxDegree) {
    const PointDD p = evaluate_dd(f, t);
    return {p.x, p.y, evaluate_with_tangent(f, t).tangent};
  }
  return with_fixed_extent(n + 1, [&](auto e) {
    constexpr std::size_t E = decltype(e)::value;
    if constexpr (E == std::dynamic_extent) {
      return compensated_in_place(f, n, t);
    } else {
      CompensatedPoint out;
      descend(first_level<E>(f.x, f.x_lo, n), first_level<E>(f.y, f.y_lo, n),
              static_cast<double>(n), t, two_sum(1.0, -t), out);
      return out;
    }
  });
}

}  // namespace bezier::core
