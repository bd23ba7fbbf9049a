#include "core/intersect/compensated_point.hpp"

#include "core/error_free.hpp"
#include "core/intersect/fixed_extent.hpp"
#include "core/multiversion.hpp"

namespace bezier::core {

namespace {

/// Degrees evaluated in stack rows (SmallArray's inline size); higher ones take the
/// double-double path.
constexpr std::size_t kMaxDegree = 23;

/// One coordinate's rows of E entries: plain de Casteljau values b and their carried errors e.
template <std::size_t E>
struct Rows {
  double b[E];
  double e[E];
};

/// One level of the compensated de Casteljau on `count` + 1 entries, with 1 - t = r_hi + r_lo.
template <std::size_t E>
inline void level(Rows<E>& row, std::size_t count, double t, double r_hi, double r_lo) noexcept {
  for (std::size_t k = 0; k < count; ++k) {
    const TwoTerm<double> p1 = two_product(r_hi, row.b[k]);
    const TwoTerm<double> p2 = two_product(t, row.b[k + 1]);
    const TwoTerm<double> s = two_sum(p1.hi, p2.hi);
    row.e[k] = r_hi * row.e[k] + t * row.e[k + 1] + ((p1.lo + p2.lo) + (s.lo + r_lo * row.b[k]));
    row.b[k] = s.hi;
  }
}

/// evaluate_compensated on rows of E >= n + 1 entries: E = n + 1 fixed at compile time for
/// degrees 1 to 3 (with_fixed_extent; the levels unroll), kMaxDegree + 1 otherwise.
template <std::size_t E>
CompensatedPoint compensated_rows(const WorkingCurve& f, std::size_t n, double t) noexcept {
  Rows<E> x, y;
  for (std::size_t i = 0; i <= n; ++i) {
    x.b[i] = f.x[i];
    x.e[i] = f.x_lo[i];
    y.b[i] = f.y[i];
    y.e[i] = f.y_lo[i];
  }
  const TwoTerm<double> r = two_sum(1.0, -t);  // r.hi is the 1 - t of bernstein::lerp
  CompensatedPoint out;
  for (std::size_t count = n; count > 0; --count) {
    if (count == 1) {
      const double dn = static_cast<double>(n);
      out.tangent = {dn * (x.b[1] - x.b[0]), dn * (y.b[1] - y.b[0])};
    }
    level(x, count, t, r.hi, r.lo);
    level(y, count, t, r.hi, r.lo);
  }
  const TwoTerm<double> px = two_sum(x.b[0], x.e[0]), py = two_sum(y.b[0], y.e[0]);
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
    constexpr std::size_t kRow = E == std::dynamic_extent ? kMaxDegree + 1 : E;
    return compensated_rows<kRow>(f, E == std::dynamic_extent ? n : E - 1, t);
  });
}

}  // namespace bezier::core
