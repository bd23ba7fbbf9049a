// libFuzzer target: region::boolean_operation on two small glyph-like regions, checked
// against the promises of core/region/boolean.hpp with an oracle that shares no code with
// the implementation.
//
// Operands: one to three closed contours of one to five segments of degree 1-3 each, their
// control points on a small integer grid (from a palette of eight points, so that contours
// share vertices and edges, or fresh), under either fill rule. b is built the same way, or
// is a copy of a, a's contours reversed, a moved by a grid vector, or a's first contour
// with b's own, so that shared boundaries, coincident edges, tangencies and containment
// come up often.
//
// Checks:
//  - status ok, work_cap_reached or unresolved; with ok:
//  - membership (promise 1): at points of a grid over the operands' box and points from the
//    input, clear of every boundary by more than the oracle's error, the result's winding
//    number is 1 where op(fill_a(w_a), fill_b(w_b)) holds and 0 elsewhere;
//  - clean (promise 3): consecutive segments of a contour meet bit for bit, contour areas
//    sum to the result's area;
//  - on a selector bit, the identities of the operations on the same operands:
//    area(a ∪ b) + area(a ∩ b) = area(a) + area(b), area(a xor b) = area(a ∪ b) - area(a ∩ b),
//    a minus a is empty, and simplify is idempotent (same area);
//  - on another, scaling both operands by 2^k scales the result's area by 4^k.
//
// The oracle: winding numbers of polylines through N + 1 uniform parameter values of every
// segment. A degree-n Bézier B differs from its chord interpolant at the same parameter by
// at most h^2 / 8 max|B''| <= h^2 / 8 n (n - 1) max_i |P_(i+2) - 2 P_(i+1) + P_i| (h = 1/N),
// so a point farther than that from the polyline has the curve's winding number (the
// straight homotopy between them never passes over it).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "core/curve/evaluate.hpp"
#include "core/region/boolean.hpp"
#include "core/region/fill_rule.hpp"
#include "core/region/region.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

using bezier::core::Curve;
using bezier::core::Point2;
using bezier::fuzz::check;
using bezier::region::BooleanOperation;
using bezier::region::BooleanResult;
using bezier::region::BooleanStatus;
using bezier::region::FillRule;
using bezier::region::Region;

/// Enough for every operand this target builds (a few thousand units each) with room for
/// the identities' extra operations.
constexpr std::int64_t kMaxWork = 4'000'000;
/// Chords per curved segment in the oracle.
constexpr int kChords = 48;

using Contour = std::vector<Curve>;
using Shape = std::vector<Contour>;

std::string describe(const Shape& shape) {
  std::string s;
  char buf[64];
  for (const Contour& contour : shape) {
    s += "  contour:";
    for (const Curve& c : contour) {
      s += " [";
      for (const Point2& p : c.points()) {
        std::snprintf(buf, sizeof buf, "(%g %g)", p.x, p.y);
        s += buf;
      }
      s += "]";
    }
    s += "\n";
  }
  return s;
}

/// A grid point: coordinates are integers in [-8, 8], or halves of them.
Point2 grid_point(FuzzedDataProvider& data) {
  const auto x = data.ConsumeIntegralInRange<int>(-16, 16);
  const auto y = data.ConsumeIntegralInRange<int>(-16, 16);
  const bool halves = data.ConsumeBool();
  return halves ? Point2{x / 2.0, y / 2.0} : Point2{static_cast<double>(x / 2), static_cast<double>(y / 2)};
}

Point2 pick_point(FuzzedDataProvider& data, const std::vector<Point2>& palette) {
  const auto k = data.ConsumeIntegral<std::uint8_t>();
  return k < 192 ? palette[k % palette.size()] : grid_point(data);
}

Contour make_contour(FuzzedDataProvider& data, const std::vector<Point2>& palette) {
  const int count = data.ConsumeIntegralInRange<int>(1, 5);
  const Point2 start = pick_point(data, palette);
  Contour contour;
  Point2 at = start;
  for (int k = 0; k < count; ++k) {
    const int degree = data.ConsumeIntegralInRange<int>(1, 3);
    std::vector<Point2> points{at};
    for (int i = 1; i < degree; ++i) points.push_back(pick_point(data, palette));
    at = k + 1 == count ? start : pick_point(data, palette);
    points.push_back(at);
    contour.emplace_back(std::move(points));
  }
  // A one-segment line back to its start has no area and no length; region_from_curves
  // takes it, but make the contour at least a lens.
  if (count == 1 && contour[0].degree() == 1) contour[0] = Curve({start, start + Point2{1, 0}, start});
  return contour;
}

Shape make_shape(FuzzedDataProvider& data, const std::vector<Point2>& palette) {
  Shape shape;
  const int contours = data.ConsumeIntegralInRange<int>(1, 3);
  for (int k = 0; k < contours; ++k) shape.push_back(make_contour(data, palette));
  return shape;
}

Shape reversed(const Shape& shape) {
  Shape out;
  for (const Contour& contour : shape) {
    Contour r;
    for (auto it = contour.rbegin(); it != contour.rend(); ++it) r.push_back(bezier::core::reversed(*it));
    out.push_back(std::move(r));
  }
  return out;
}

Shape mapped(const Shape& shape, double scale, Point2 shift) {
  Shape out;
  for (const Contour& contour : shape) {
    Contour m;
    for (const Curve& c : contour) {
      std::vector<Point2> points;
      for (const Point2& p : c.points()) points.push_back(Point2{p.x * scale + shift.x, p.y * scale + shift.y});
      m.emplace_back(std::move(points));
    }
    out.push_back(std::move(m));
  }
  return out;
}

Region region_of(const Shape& shape, FillRule rule) {
  std::vector<Curve> curves;
  for (const Contour& contour : shape) curves.insert(curves.end(), contour.begin(), contour.end());
  return bezier::region::region_from_curves(std::move(curves), rule);
}

/// Closed curve chains flattened for the oracle, with the largest distance between a chain
/// and its polyline at the same parameter.
struct Polylines {
  std::vector<std::vector<Point2>> lines;
  double error = 0.0;
};

Polylines flatten(const std::vector<std::vector<const Curve*>>& chains) {
  Polylines out;
  for (const auto& chain : chains) {
    std::vector<Point2> line;
    for (const Curve* c : chain) {
      const int n = c->degree();
      double second = 0.0;
      for (int i = 0; i + 2 <= n; ++i) {
        second = std::fmax(second, bezier::core::length((*c)[i + 2] - 2.0 * (*c)[i + 1] + (*c)[i]));
      }
      const int steps = n == 1 ? 1 : kChords;
      out.error = std::fmax(out.error, n * (n - 1) * second / (8.0 * steps * steps));
      for (int i = 0; i < steps; ++i) line.push_back(bezier::core::evaluate(*c, static_cast<double>(i) / steps));
    }
    out.lines.push_back(std::move(line));
  }
  return out;
}

Polylines flatten(const Shape& shape) {
  std::vector<std::vector<const Curve*>> chains;
  for (const Contour& contour : shape) {
    chains.emplace_back();
    for (const Curve& c : contour) chains.back().push_back(&c);
  }
  return flatten(chains);
}

Polylines flatten(const BooleanResult& result) {
  std::vector<std::vector<const Curve*>> chains;
  for (const auto& contour : result.contours) {
    chains.emplace_back();
    for (std::size_t k = contour.first_segment; k < contour.end_segment; ++k) {
      chains.back().push_back(&result.segments[k].curve);
    }
  }
  return flatten(chains);
}

struct Winding {
  long winding = 0;
  double distance = INFINITY;
};

Winding winding(const Polylines& polylines, Point2 p) {
  Winding out;
  for (const auto& line : polylines.lines) {
    const std::size_t n = line.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point2 a = line[i], b = line[(i + 1) % n];
      const Point2 ab = b - a, ap = p - a;
      const double len2 = bezier::core::dot(ab, ab);
      const double t = len2 > 0 ? std::fmax(0.0, std::fmin(1.0, bezier::core::dot(ap, ab) / len2)) : 0.0;
      out.distance = std::fmin(out.distance, bezier::core::length(ap - t * ab));
      if ((a.y <= p.y) != (b.y <= p.y)) {
        const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
        if (x > p.x) out.winding += b.y > a.y ? 1 : -1;
      }
    }
  }
  return out;
}

void check_clean(const BooleanResult& r) {
  double total = 0.0;
  for (const auto& contour : r.contours) {
    check(contour.first_segment < contour.end_segment && contour.end_segment <= r.segments.size(),
          "contour segment range");
    total += contour.area;
    for (std::size_t k = contour.first_segment; k < contour.end_segment; ++k) {
      const std::size_t next = k + 1 < contour.end_segment ? k + 1 : contour.first_segment;
      check(r.segments[k].curve.back() == r.segments[next].curve.front(), "contour joins exactly");
    }
  }
  check(std::fabs(total - r.area) <= 1e-12 * (1.0 + std::fabs(total)), "contour areas sum to the area");
}

/// The result's winding number is 1 exactly where the operation keeps the point, at every
/// point clear of all three boundaries.
void check_membership(BooleanOperation op, const Polylines& a, FillRule rule_a, const Polylines& b,
                      FillRule rule_b, const BooleanResult& r, const std::vector<Point2>& points,
                      double margin) {
  const Polylines result = flatten(r);
  for (const Point2 p : points) {
    const Winding wa = winding(a, p), wb = winding(b, p), wr = winding(result, p);
    if (wa.distance <= a.error + margin || wb.distance <= b.error + margin ||
        wr.distance <= result.error + margin) {
      continue;
    }
    const bool keep = bezier::region::keeps(op, bezier::region::fills(rule_a, wa.winding),
                                            bezier::region::fills(rule_b, wb.winding));
    check(wr.winding == (keep ? 1 : 0), [&] {
      char buf[160];
      std::snprintf(buf, sizeof buf, "at (%g, %g): result winding %ld, expected %d (w_a %ld, w_b %ld)", p.x,
                    p.y, wr.winding, keep ? 1 : 0, wa.winding, wb.winding);
      return std::string(buf);
    });
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider provider(data, size);
  const auto flags = provider.ConsumeIntegral<std::uint8_t>();
  const auto op = static_cast<BooleanOperation>(flags % 5);
  const FillRule rule_a = (flags & 8u) != 0 ? FillRule::evenodd : FillRule::nonzero;
  const FillRule rule_b = (flags & 16u) != 0 ? FillRule::evenodd : FillRule::nonzero;
  const bool identities = (flags & 32u) != 0;
  const bool scaling = (flags & 64u) != 0;
  std::vector<Point2> palette;
  for (int k = 0; k < 8; ++k) palette.push_back(grid_point(provider));

  const Shape a = make_shape(provider, palette);
  Shape b;
  switch (provider.ConsumeIntegralInRange<int>(0, 5)) {
    case 0: b = a; break;
    case 1: b = reversed(a); break;
    case 2: b = mapped(a, 1.0, grid_point(provider)); break;
    case 3:
      b = make_shape(provider, palette);
      b.insert(b.begin(), a.front());
      break;
    default: b = make_shape(provider, palette); break;
  }
  if (bezier::fuzz::print_inputs()) {
    std::fprintf(stderr, "op %d, fill a %d, fill b %d\na:\n%sb:\n%s", static_cast<int>(op),
                 static_cast<int>(rule_a), static_cast<int>(rule_b), describe(a).c_str(), describe(b).c_str());
  }
  const Region region_a = region_of(a, rule_a), region_b = region_of(b, rule_b);
  const BooleanResult r = bezier::region::boolean_operation(op, region_a, region_b, kMaxWork);
  if (r.status != BooleanStatus::ok) return 0;
  check_clean(r);

  // Sample points: a grid over the box of both operands (quarter-integer offsets, so the
  // points avoid the grid the control points lie on) and points from the input.
  std::vector<Point2> points;
  for (int i = 0; i < 17; ++i) {
    for (int j = 0; j < 17; ++j) points.push_back(Point2{-8.25 + i + 0.125 * j, -8.3 + j + 0.0625 * i});
  }
  while (provider.remaining_bytes() >= 4 && points.size() < 400) {
    const auto x = provider.ConsumeIntegral<std::uint16_t>(), y = provider.ConsumeIntegral<std::uint16_t>();
    points.push_back(Point2{-9.0 + 18.0 * x / 65535.0, -9.0 + 18.0 * y / 65535.0});
  }
  // The operation's vertex merging moves ends by at most a few ulps of the scale here (small
  // integer grid): 1e-6 is far above it and far below the grid's spacing.
  constexpr double kMargin = 1e-6;
  const Polylines flat_a = flatten(a), flat_b = flatten(b);
  check_membership(op, flat_a, rule_a, flat_b, rule_b, r, points, kMargin);

  if (identities) {
    const auto run = [&](BooleanOperation o, const Region& x, const Region& y) {
      return bezier::region::boolean_operation(o, x, y, kMaxWork);
    };
    const BooleanResult uni = run(BooleanOperation::union_, region_a, region_b);
    const BooleanResult inter = run(BooleanOperation::intersection, region_a, region_b);
    const BooleanResult xo = run(BooleanOperation::xor_, region_a, region_b);
    const BooleanResult sa = bezier::region::simplify(region_a, kMaxWork);
    const BooleanResult sb = bezier::region::simplify(region_b, kMaxWork);
    const BooleanResult a_minus_a = run(BooleanOperation::difference, region_a, region_a);
    const auto ok = [](const BooleanResult& x) { return x.status == BooleanStatus::ok; };
    // The areas are sums over the same pieces of the same curves, each found to the
    // intersection's accuracy: their differences are rounding and merge radii (1e-9 of
    // the scale 8, times the perimeters), far below this.
    constexpr double kAreaTolerance = 1e-6;
    if (ok(uni) && ok(inter) && ok(sa) && ok(sb)) {
      check(std::fabs(uni.area + inter.area - sa.area - sb.area) <= kAreaTolerance, [&] {
        char buf[160];
        std::snprintf(buf, sizeof buf, "area(a u b) %.17g + area(a n b) %.17g != area(a) %.17g + area(b) %.17g",
                      uni.area, inter.area, sa.area, sb.area);
        return std::string(buf);
      });
    }
    if (ok(uni) && ok(inter) && ok(xo)) {
      check(std::fabs(xo.area - (uni.area - inter.area)) <= kAreaTolerance, "area(a xor b) = area(a u b) - area(a n b)");
    }
    if (ok(a_minus_a)) check(a_minus_a.contours.empty(), "a minus a is empty");
    if (ok(sa)) {
      Region simple;
      simple.fill_rule = FillRule::nonzero;
      std::vector<Curve> curves;
      for (const auto& s : sa.segments) curves.push_back(s.curve);
      if (!curves.empty()) simple = bezier::region::region_from_curves(std::move(curves), FillRule::nonzero);
      const BooleanResult again = bezier::region::simplify(simple, kMaxWork);
      if (ok(again)) check(std::fabs(again.area - sa.area) <= kAreaTolerance, "simplify is idempotent");
    }
  }
  if (scaling) {
    const int k = provider.ConsumeIntegralInRange<int>(-20, 20);
    const double s = std::ldexp(1.0, k);
    const BooleanResult scaled = bezier::region::boolean_operation(
        op, region_of(mapped(a, s, {0, 0}), rule_a), region_of(mapped(b, s, {0, 0}), rule_b), kMaxWork);
    if (scaled.status == BooleanStatus::ok) {
      check(std::fabs(scaled.area - r.area * s * s) <= 1e-9 * s * s * (1.0 + std::fabs(r.area)),
            "scaling by 2^k scales the area by 4^k");
    }
  }
  return 0;
}
