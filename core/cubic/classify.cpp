#include "core/cubic/classify.hpp"

#include <algorithm>
#include <cassert>

#include "core/cubic/canonical_form.hpp"
#include "core/cubic/predicates.hpp"
#include "core/numeric/quadratic_roots.hpp"

namespace bezier::core {

namespace {

double clamp_unit(double t) noexcept {
  // Also turns -0 into +0: the parameters are reported in [0, 1] with +0.
  return t <= 0.0 ? 0.0 : std::min(t, 1.0);
}

LoopBlinnClass loop_blinn_class(const CubicSigns& s) noexcept {
  if (s.d1 == 0 && s.d2 == 0 && s.d3 == 0) return LoopBlinnClass::line;
  if (s.d2 == 0 && s.d3 == 0) return LoopBlinnClass::quadratic;
  // d3 = 0 with d2 != 0: I is linear, one finite inflection, and the cusp is at t = ∞
  // (Loop–Blinn's discriminant d1² (3 d2² − 4 d1 d3) vanishes with their d1, our d3).
  if (s.d3 == 0) return LoopBlinnClass::cusp;
  if (s.disc > 0) return LoopBlinnClass::serpentine;
  return s.disc < 0 ? LoopBlinnClass::loop : LoopBlinnClass::cusp;
}

// The roots of I(t) = d1 + d2 t + d3 t² in [0,1] when disc > 0, selected by exact signs and
// placed by the rounded roots (exactly 0 or 1 when I(0) or I(1) is exactly zero).
Inflections inflections_on_unit_interval(const CubicPredicates& pred) {
  const CubicSigns& s = pred.sign;
  Inflections out;
  const auto add = [&out](double t) { out.t[static_cast<std::size_t>(out.count++)] = t; };
  if (s.d3 == 0) {
    // Linear: one root −d1 / d2, inside iff I(0) and I(1) do not share a strict sign.
    if (s.d1 * s.i1 > 0) return out;
    add(s.d1 == 0 ? 0.0 : s.i1 == 0 ? 1.0 : clamp_unit(-pred.d1 / pred.d2));
    return out;
  }
  // g = sgn(d3) I opens upwards: negative strictly between its roots r1 < r2, positive
  // outside. Both roots lie in [0,1] iff g(0) >= 0, g(1) >= 0 and the vertex lies in [0,1];
  // otherwise one does iff g(0), g(1) differ in strict sign or one of them is zero.
  const int g0 = s.d3 * s.d1, g1 = s.d3 * s.i1;
  const bool vertex_inside = s.d2 * s.d3 <= 0 && s.d2_plus_2d3 * s.d3 >= 0;
  const auto roots = [&pred] { return quadratic_roots(pred.d3, pred.d2, pred.d1, pred.disc); };
  if (g0 >= 0 && g1 >= 0 && vertex_inside) {
    const RootPair r = roots();
    add(g0 == 0 ? 0.0 : clamp_unit(r.lo));
    add(g1 == 0 ? 1.0 : clamp_unit(r.hi));
    if (out.t[1] < out.t[0]) out.t[1] = out.t[0];  // keep the order through rounding
  } else if (g0 == 0) {
    add(0.0);
  } else if (g1 == 0) {
    add(1.0);
  } else if (g0 * g1 < 0) {
    // g(0) < 0: 0 lies between the roots, so r2 is in (0, 1); g(0) > 0: r1 is.
    const RootPair r = roots();
    add(clamp_unit(g0 < 0 ? r.hi : r.lo));
  }
  return out;
}

}  // namespace

CubicClassification classify(std::span<const Point2, 4> p) {
  CubicClassification out;
  if (p[0] == p[1] && p[1] == p[2] && p[2] == p[3]) return out;  // point

  const CubicPredicates pred = cubic_predicates(p);
  const CubicSigns& s = pred.sign;
  out.exact = pred.exact;
  out.loop_blinn = loop_blinn_class(s);
  out.canonical_point = canonical_point(pred);
  if (out.loop_blinn == LoopBlinnClass::line) {
    out.type = CubicType::line;
    return out;
  }
  if (out.loop_blinn == LoopBlinnClass::quadratic) {
    out.type = CubicType::quadratic;
    return out;
  }

  if (s.disc == 0) {
    // d3 != 0 here (d3 = 0 would give disc = d2² > 0). The double root of I is the cusp.
    const bool inside = s.d2 * s.d3 <= 0 && s.d2_plus_2d3 * s.d3 >= 0;
    if (!inside) {
      out.type = CubicType::arch;  // cusp outside [0,1]; I has no other root
      return out;
    }
    out.type = CubicType::cusp;
    out.cusp = s.d2 == 0 ? 0.0 : s.d2_plus_2d3 == 0 ? 1.0 : clamp_unit(-pred.d2 / (2.0 * pred.d3));
    return out;
  }

  if (s.disc < 0) {
    if (!double_point_on_segment(s)) {
      out.type = CubicType::arch;  // the loop lies (partly) outside [0,1]; no inflections
      return out;
    }
    const std::optional<CubicDoublePoint> dp = cubic_double_point(p, pred);
    assert(dp.has_value() && dp->on_segment);
    out.type = s.l0 == 0   ? CubicType::loop_at_start
               : s.l1 == 0 ? CubicType::loop_at_end
                           : CubicType::loop;
    out.self_intersection = dp;
    return out;
  }

  out.inflections = inflections_on_unit_interval(pred);
  out.type = out.inflections.count == 2   ? CubicType::double_inflection
             : out.inflections.count == 1 ? CubicType::single_inflection
                                          : CubicType::arch;
  return out;
}

CubicClassification classify(const Curve& cubic) {
  assert(cubic.degree() == 3);
  return classify(std::span<const Point2, 4>(cubic.points().data(), 4));
}

}  // namespace bezier::core
