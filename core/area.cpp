#include "core/area.hpp"

#include <cassert>
#include <vector>

#include "core/binomial.hpp"
#include "core/polar.hpp"

namespace bezier::core {

double enclosed_area(std::span<const Point2> points) {
  assert(!points.empty());
  const int n = static_cast<int>(points.size()) - 1;
  if (n < 2) return 0.0;  // a point or a segment closed by itself encloses nothing
  // C(n, i) and C(2n - 2, k) once: every weight is then one division (see the header).
  std::vector<double> cn(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) cn[static_cast<std::size_t>(i)] = binomial(n, i);
  std::vector<double> c2(static_cast<std::size_t>(2 * n - 1));
  for (int k = 0; k <= 2 * n - 2; ++k) c2[static_cast<std::size_t>(k)] = binomial(2 * n - 2, k);
  const Point2 origin = points[0];
  const double scale = 2.0 * (2 * n - 1);
  double area = 0.0;
  // i = 0 drops out: P_0 - P_0 = 0.
  for (int i = 1; i < n; ++i) {
    const Point2 pi = points[static_cast<std::size_t>(i)] - origin;
    double row = 0.0;
    for (int j = i + 1; j <= n; ++j) {
      const double weight = ((j - i) * cn[static_cast<std::size_t>(i)] * cn[static_cast<std::size_t>(j)]) /
                            (scale * c2[static_cast<std::size_t>(i + j - 1)]);
      row += weight * cross(pi, points[static_cast<std::size_t>(j)] - origin);
    }
    area += row;
  }
  return area;
}

double enclosed_area(const Curve& curve, double a, double b) {
  if (a == 0.0 && b == 1.0) return enclosed_area(curve.points());
  return enclosed_area(portion(curve, a, b).points());
}

double enclosed_area(const Curve& curve) { return enclosed_area(curve.points()); }

double signed_area(const Curve& curve, double a, double b) {
  // The closed path is the curve piece plus the chord B(b) -> B(a); the chord's own Green
  // integral is 1/2 cross(B(b), B(a)), so the piece's integral is the rest.
  const Curve piece = (a == 0.0 && b == 1.0) ? curve : portion(curve, a, b);
  return enclosed_area(piece.points()) + 0.5 * cross(piece.front(), piece.back());
}

double signed_area(const Curve& curve) { return signed_area(curve, 0.0, 1.0); }

bool is_closed(const Curve& curve) noexcept { return curve.front() == curve.back(); }

std::optional<double> closed_area(const Curve& curve) {
  if (!is_closed(curve)) return std::nullopt;
  return enclosed_area(curve.points());
}

}  // namespace bezier::core
