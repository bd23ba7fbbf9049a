#include "core/curve/area.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

#include "core/numeric/binomial.hpp"
#include "core/numeric/power_of_two.hpp"
#include "core/curve/subdivide.hpp"

namespace bezier::core {

namespace {

/// The weight of cross(P_i - P_0, P_j - P_0) in enclosed_area() for degree n, 0 < i < j <= n,
/// given C(n, i), C(n, j) and C(2n - 2, i + j - 1): one division (see the header).
double area_weight(int n, int i, int j, double cn_i, double cn_j, double c2_ij) {
  const double scale = 2.0 * (2 * n - 1);
  return ((j - i) * cn_i * cn_j) / (scale * c2_ij);
}

/// Degrees whose weights are computed once (on first use) and then looked up.
constexpr int kTabledDegree = 12;

/// weights(n)[i * (n + 1) + j] = area_weight(n, i, j, ...) for n <= kTabledDegree: the same
/// doubles as computing them on the spot.
const double* tabled_weights(int n) {
  static const std::vector<std::vector<double>> tables = [] {
    std::vector<std::vector<double>> all(kTabledDegree + 1);
    for (int m = 2; m <= kTabledDegree; ++m) {
      std::vector<double>& w = all[static_cast<std::size_t>(m)];
      w.assign(static_cast<std::size_t>((m + 1) * (m + 1)), 0.0);
      for (int i = 1; i < m; ++i) {
        for (int j = i + 1; j <= m; ++j) {
          w[static_cast<std::size_t>(i * (m + 1) + j)] = area_weight(
              m, i, j, binomial(m, i), binomial(m, j), binomial(2 * m - 2, i + j - 1));
        }
      }
    }
    return all;
  }();
  return tables[static_cast<std::size_t>(n)].data();
}

/// enclosed_area_as_given for a cubic: the same weights (the table's), products and sums in
/// the same order, so the same double; written out, without the general loops.
inline double cubic_enclosed_area_as_given(std::span<const Point2, 4> points) {
  static const double* const weight = tabled_weights(3);
  const Point2 origin = points[0];
  const Point2 p1 = points[1] - origin, p2 = points[2] - origin, p3 = points[3] - origin;
  double row1 = 0.0;
  row1 += weight[1 * 4 + 2] * cross(p1, p2);
  row1 += weight[1 * 4 + 3] * cross(p1, p3);
  double row2 = 0.0;
  row2 += weight[2 * 4 + 3] * cross(p2, p3);
  double area = 0.0;
  area += row1;
  area += row2;
  return area;
}

/// The double sum of enclosed_area() on the coordinates as given.
double enclosed_area_as_given(std::span<const Point2> points) {
  const int n = static_cast<int>(points.size()) - 1;
  if (n < 2) return 0.0;  // a point or a segment closed by itself encloses nothing
  if (n == 3) return cubic_enclosed_area_as_given(points.first<4>());
  // The weights from the table for the usual degrees; beyond, C(n, i) and C(2n - 2, k) once
  // and each weight from them.
  std::vector<double> computed;
  const double* weight = nullptr;
  if (n <= kTabledDegree) {
    weight = tabled_weights(n);
  } else {
    std::vector<double> cn(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) cn[static_cast<std::size_t>(i)] = binomial(n, i);
    std::vector<double> c2(static_cast<std::size_t>(2 * n - 1));
    for (int k = 0; k <= 2 * n - 2; ++k) c2[static_cast<std::size_t>(k)] = binomial(2 * n - 2, k);
    computed.assign(static_cast<std::size_t>((n + 1) * (n + 1)), 0.0);
    for (int i = 1; i < n; ++i) {
      for (int j = i + 1; j <= n; ++j) {
        computed[static_cast<std::size_t>(i * (n + 1) + j)] =
            area_weight(n, i, j, cn[static_cast<std::size_t>(i)], cn[static_cast<std::size_t>(j)],
                        c2[static_cast<std::size_t>(i + j - 1)]);
      }
    }
    weight = computed.data();
  }
  const Point2 origin = points[0];
  double area = 0.0;
  // i = 0 drops out: P_0 - P_0 = 0.
  for (int i = 1; i < n; ++i) {
    const Point2 pi = points[static_cast<std::size_t>(i)] - origin;
    double row = 0.0;
    for (int j = i + 1; j <= n; ++j) {
      row += weight[i * (n + 1) + j] * cross(pi, points[static_cast<std::size_t>(j)] - origin);
    }
    area += row;
  }
  return area;
}

/// B on [a, b] reparametrised to [0, 1]: subdivide() at b keeps the left half (B on
/// [0, b]), then subdivide() of that at a / b keeps the right half (B on [a, b]); for
/// b = 0 (then a < 0), the left half at a reversed. Two O(n^2) compensated triangles (each new
/// control point within about one rounding) instead of portion()'s n + 1 blossoms (O(n^3)). The one
/// rounding in a / b moves the start of the piece along the curve by about an ulp of a, which
/// changes a loop's area only to second order (at a double point d/da of the enclosed area is 1/2
/// cross(B(b) - B(a), B'(a)) = 0).
Curve piece(const Curve& curve, double a, double b) {
  // A reversed interval is the forward one reversed: no extrapolation at a / b > 1.
  if (a > b) return reversed(piece(curve, b, a));
  if (b == 0.0) return reversed(subdivide(curve, a).left);
  return subdivide(subdivide(curve, b).left, a / b).right;
}

}  // namespace

double enclosed_area(std::span<const Point2> points) {
  assert(!points.empty());
  // Differences and their cross products overflow beyond about 2^510 (underflow below
  // 2^-510) even when the area itself is representable: scale such input by a power of two
  // (exact) and the area back by its square; an area beyond the double range is then +-inf.
  // A cubic's four points with a fixed extent (the loop unrolls), the same maximum.
  const auto largest_of = [](auto fixed_points) {
    double largest = 0.0;
    for (const Point2 p : fixed_points) {
      largest = std::max(largest, std::max(std::fabs(p.x), std::fabs(p.y)));
    }
    return largest;
  };
  const bool cubic = points.size() == 4;
  const double largest = cubic ? largest_of(points.first<4>()) : largest_of(points);
  if (largest == 0.0 || (0x1p-400 <= largest && largest <= 0x1p400)) {
    return cubic ? cubic_enclosed_area_as_given(points.first<4>()) : enclosed_area_as_given(points);
  }
  const int k = -exponent_of(largest);
  return std::ldexp(enclosed_area_as_given(scaled_by_power_of_two(points, k)), -2 * k);
}

double enclosed_area(const Curve& curve, double a, double b) {
  if (a == 0.0 && b == 1.0) return enclosed_area(curve.points());
  return enclosed_area(piece(curve, a, b).points());
}

double enclosed_area(const Curve& curve) {
  return enclosed_area(curve.points());
}

double signed_area(const Curve& curve, double a, double b) {
  // The closed path is the curve piece plus the chord B(b) -> B(a); the chord's own Green
  // integral is 1/2 cross(B(b), B(a)), so the piece's integral is the rest.
  if (a == 0.0 && b == 1.0) {
    return enclosed_area(curve.points()) + 0.5 * cross(curve.front(), curve.back());
  }
  const Curve p = piece(curve, a, b);
  return enclosed_area(p.points()) + 0.5 * cross(p.front(), p.back());
}

double signed_area(const Curve& curve) {
  return signed_area(curve, 0.0, 1.0);
}

bool is_closed(const Curve& curve) noexcept {
  return curve.front() == curve.back();
}

std::optional<double> closed_area(const Curve& curve) {
  if (!is_closed(curve)) return std::nullopt;
  return enclosed_area(curve.points());
}

}  // namespace bezier::core
