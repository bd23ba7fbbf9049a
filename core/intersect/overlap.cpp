#include "core/intersect/overlap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "core/numeric/binomial.hpp"
#include "core/bernstein/degree.hpp"
#include "core/bernstein/bernstein1d.hpp"
#include "core/numeric/min_max.hpp"
#include "core/intersect/common_arc.hpp"
#include "core/intersect/gauss_newton.hpp"
#include "core/bernstein/monomial.hpp"
#include "core/numeric/power_of_two.hpp"
#include "core/numeric/unit_roundoff.hpp"
#include "core/intersect/tuning.hpp"

namespace bezier::core {

using namespace intersect_tuning;

namespace {

/// How far the monomial coefficient a_k of a curve may be from that of a curve whose
/// control points are within overlap_tolerance(degree) of its own: C(n, k) 2^k times that
/// distance (a_k is C(n, k) times a k-th forward difference), plus the rounding of the
/// conversion and of the working frame (as in true_degree).
double coefficient_error(const WorkingCurve& c, int k, int degree) {
  const double points = overlap_tolerance(degree) + 64 * kUnitRoundoff * c.magnitude + c.frame_error;
  return binomial(c.degree, k) * power_of_two(k) * points;
}

struct Residual {
  double x, y;
};

Residual residual(const WorkingCurve& f, double t, PointDD p) {
  const PointDD q = evaluate_dd(f, t);
  return {dd::to_double(dd::sub(q.x, p.x)), dd::to_double(dd::sub(q.y, p.y))};
}

std::vector<double> elevated(const std::vector<double>& c, int to) {
  if (static_cast<int>(c.size()) - 1 == to) return c;
  return elevate_degree(std::span<const double>(c), to);
}

std::vector<double> piece(std::span<const double> c, double a, double b) {
  const Coeffs p = bernstein::portion<double>(c, a, b);
  return {p.begin(), p.end()};
}

/// A region holding a curve's control polygon, widened by a margin: the bounding box of
/// its (hi) control points and the band between the lines parallel to its chord through
/// the extreme control points (the fat line). Both hold the convex hull, so both hold every
/// piece's control points, up to rounding.
class HullRegion {
 public:
  HullRegion(const WorkingCurve& c, double margin) noexcept {
    x_lo_ = x_hi_ = c.x[0];
    y_lo_ = y_hi_ = c.y[0];
    for (std::size_t i = 1; i < c.x.size(); ++i) {
      x_lo_ = min2(x_lo_, c.x[i]);
      x_hi_ = max2(x_hi_, c.x[i]);
      y_lo_ = min2(y_lo_, c.y[i]);
      y_hi_ = max2(y_hi_, c.y[i]);
    }
    x_lo_ -= margin;
    x_hi_ += margin;
    y_lo_ -= margin;
    y_hi_ += margin;
    // Any direction bounds the hull by its extreme projections; a unit one (to rounding)
    // keeps the margin a distance. A closed polygon has no chord: the box alone.
    origin_ = {c.x[0], c.y[0]};
    const double dx = c.x.back() - c.x[0], dy = c.y.back() - c.y[0];
    const double length = std::sqrt(dx * dx + dy * dy);
    if (length > 0) {
      normal_ = {-dy / length, dx / length};
      for (std::size_t i = 1; i + 1 < c.x.size(); ++i) {
        const double d = distance({c.x[i], c.y[i]});
        d_lo_ = min2(d_lo_, d);
        d_hi_ = max2(d_hi_, d);
      }
    }
    // The distances' rounding (a few u of coordinates <= about 1) is far below 2^-40.
    d_lo_ -= margin + 0x1p-40;
    d_hi_ += margin + 0x1p-40;
  }

  [[nodiscard]] bool holds(double x, double y) const noexcept {
    if (!(x_lo_ <= x && x <= x_hi_ && y_lo_ <= y && y <= y_hi_)) return false;
    const double d = distance({x, y});
    return d_lo_ <= d && d <= d_hi_;
  }

 private:
  [[nodiscard]] double distance(Point2 p) const noexcept {
    return normal_.x * (p.x - origin_.x) + normal_.y * (p.y - origin_.y);
  }

  double x_lo_, x_hi_, y_lo_, y_hi_;
  Point2 origin_;
  Point2 normal_{0.0, 0.0};  // zero: every distance is 0, inside the band
  double d_lo_ = 0.0, d_hi_ = 0.0;
};

}  // namespace

/// A necessary condition for find_overlaps to find anything, far cheaper than its monomial
/// coefficients. Each end of an overlap it reports is an end of f or of g (two different
/// ends: both of g, both of f, or one of each), and there the verified pieces' first (or
/// last) control points, one that end point and the other in the other curve's hull (a
/// portion's control points are convex combinations of the curve's, up to rounding), agree
/// to within overlap_tolerance. So at least two of the four end points lie within that
/// tolerance, plus rounding, of the other curve's hull region.
bool ends_may_overlap(const WorkingCurve& f, const WorkingCurve& g) noexcept {
  const int degree = std::max(f.degree, g.degree);
  // The portions' and elevations' rounding (a few n u of coordinates <= about 1) is far
  // below 2^-40; the factor 2 doubles the tolerance itself.
  const double margin = 2 * overlap_tolerance(degree) + 0x1p-40;
  const HullRegion fr(f, margin), gr(g, margin);
  const int ends = static_cast<int>(gr.holds(f.x[0], f.y[0])) +
                   static_cast<int>(gr.holds(f.x.back(), f.y.back())) +
                   static_cast<int>(fr.holds(g.x[0], g.y[0])) +
                   static_cast<int>(fr.holds(g.x.back(), g.y.back()));
  return ends >= 2;
}

double overlap_tolerance(int degree) noexcept {
  return 0x1p-42 * max2(1, degree);
}

double extent(std::span<const double> x, std::span<const double> y) noexcept {
  double x_lo = x[0], x_hi = x[0], y_lo = y[0], y_hi = y[0];
  for (std::size_t i = 1; i < x.size(); ++i) {
    x_lo = min2(x_lo, x[i]);
    x_hi = max2(x_hi, x[i]);
    y_lo = min2(y_lo, y[i]);
    y_hi = max2(y_hi, y[i]);
  }
  return max2(x_hi - x_lo, y_hi - y_lo);
}

namespace {

/// coincidence_tolerance with the smaller curve's size (at most 1) given.
double coincidence_tolerance_at(const WorkingCurve& f, const WorkingCurve& g,
                                double smaller) noexcept {
  const int degree = std::max(f.degree, g.degree);
  return overlap_tolerance(degree) * smaller +
         64 * degree * kUnitRoundoff * max2(f.magnitude, g.magnitude) + f.frame_error +
         g.frame_error;
}

}  // namespace

double coincidence_tolerance(const WorkingCurve& f, const WorkingCurve& g) noexcept {
  return coincidence_tolerance_at(
      f, g, min2(1.0, min2(extent(f.x, f.y), extent(g.x, g.y))));
}

double coincidence_tolerance_bound(const WorkingCurve& f, const WorkingCurve& g) noexcept {
  // Every operation rounds monotonically, so a size of 1 gives at least any smaller one's.
  return coincidence_tolerance_at(f, g, 1.0);
}

double locate_on_curve(const WorkingCurve& f, PointDD p, double start, double converged) {
  return gauss_newton(start, kProjectionSteps, converged, [&](double t) {
    const Residual r = residual(f, t, p);
    return ResidualAndSlope{{r.x, r.y}, evaluate_with_tangent(f, t).tangent};
  });
}

namespace {

/// The necessary condition on the top coefficients of degree d (a_d of f, b_d of g, both
/// coordinates): g's are beta^d times f's, to within what overlap_tolerance allows of the
/// control points plus the conversion's rounding (coefficient_error), every quotient's error
/// carried through. So (b_d)_other = r (a_d)_other with r = (b_d)_main / (a_d)_main, main
/// the coordinate where f's is larger.
bool top_coefficients_agree(const WorkingCurve& f, const WorkingCurve& g, Point2 a_d, Point2 b_d,
                            int d) {
  const int top_degree = std::max(f.degree, g.degree);
  const double f_error = coefficient_error(f, d, top_degree);
  const double g_error = coefficient_error(g, d, top_degree);
  const bool use_x = std::fabs(a_d.x) >= std::fabs(a_d.y);
  const double a = use_x ? a_d.x : a_d.y, a_other = use_x ? a_d.y : a_d.x;
  const double b = use_x ? b_d.x : b_d.y, b_other = use_x ? b_d.y : b_d.x;
  const double r = b / a;
  const double r_rel_error = g_error / std::fabs(b) + f_error / std::fabs(a);
  const double top_tol = 4 * (g_error + std::fabs(r) * (f_error + std::fabs(a_other) * r_rel_error));
  return std::fabs(b_other - r * a_other) <= top_tol;
}

/// The cheap necessary conditions, before any conversion: neither curve is a point; when
/// both have their full degree n (true_degree's test at k = n), their top coefficients
/// agree (top_coefficients_agree: a few differences instead of the hull regions and the
/// conversions, and for two random curves it fails); two of the four end points lie near
/// the other curve's hull (ends_may_overlap). False: the curves share no piece.
bool may_overlap(const WorkingCurve& f, const WorkingCurve& g) {
  if (f.is_point || g.is_point) return false;
  if (f.degree == g.degree && f.degree >= 1) {
    const int n = f.degree;
    const Point2 a_n = {top_monomial_coefficient(f.x), top_monomial_coefficient(f.y)};
    const Point2 b_n = {top_monomial_coefficient(g.x), top_monomial_coefficient(g.y)};
    if (significant_coefficient(n, n, a_n.x, a_n.y, f.magnitude) &&
        significant_coefficient(n, n, b_n.x, b_n.y, g.magnitude) &&
        !top_coefficients_agree(f, g, a_n, b_n, n))
      return false;
  }
  return ends_may_overlap(f, g);
}

double at(const Coeffs& v, int k) {
  return v[static_cast<std::size_t>(k)];
}

/// The monomial coefficients of f (a) and g (b) in the main coordinate, the one where f's
/// top coefficient is the larger, and in the other; d their common true degree (>= 1).
struct MonomialForms {
  Coeffs fx, fy, gx, gy;
  int d = 0;
  bool use_x = true;

  [[nodiscard]] const Coeffs& a() const { return use_x ? fx : fy; }
  [[nodiscard]] const Coeffs& b() const { return use_x ? gx : gy; }
  [[nodiscard]] const Coeffs& a_other() const { return use_x ? fy : fx; }
  [[nodiscard]] const Coeffs& b_other() const { return use_x ? gy : gx; }
};

/// The monomial forms of f and g when their true degrees are one d >= 1 and g's top
/// coefficients are beta^d times f's in both coordinates (top_coefficients_agree, on the
/// coefficients of the whole curves); nullopt otherwise, where no linear map relates them.
std::optional<MonomialForms> agreeing_monomial_forms(const WorkingCurve& f, const WorkingCurve& g) {
  MonomialForms m{monomial(f.x), monomial(f.y), monomial(g.x), monomial(g.y)};
  m.d = true_degree(m.fx, m.fy, f.magnitude);
  const int d = m.d;
  if (d < 1 || d != true_degree(m.gx, m.gy, g.magnitude)) return std::nullopt;
  m.use_x = std::fabs(at(m.fx, d)) >= std::fabs(at(m.fy, d));
  // The verification (pieces_coincide) looks at the overlapping pieces only, which cannot
  // tell a short piece of a coincident curve from a curve that leaves at a small angle
  // (regression test Overlap.SwappingTheCurvesGivesTheSameKindOfAnswer: segments 2.4e-7 rad
  // apart): the whole curves' coefficients must agree first.
  if (!top_coefficients_agree(f, g, {at(m.fx, d), at(m.fy, d)}, {at(m.gx, d), at(m.gy, d)}, d))
    return std::nullopt;
  return m;
}

/// At most two linear maps t = alpha + beta s, in the order found.
struct CandidateMaps {
  std::array<CoincidenceMap, 2> maps;
  std::size_t count = 0;
  [[nodiscard]] std::span<const CoincidenceMap> all() const { return {maps.data(), count}; }
};

/// The linear maps t = alpha + beta s that the monomial forms allow, at most two: beta a
/// real d-th root of r = b_d / a_d (both signs for even d), alpha from the coefficients of
/// degree d - 1 of the main coordinate, b_{d-1} = beta^(d-1) (a_{d-1} + d alpha a_d), and
/// the other coordinate's coefficients of degree d - 1 must then agree the same way. Both
/// hold to within what overlap_tolerance allows of the control points, plus the
/// conversion's rounding (coefficient_error), with every quotient's error carried through.
/// The positive root's map first.
CandidateMaps candidate_maps(const WorkingCurve& f, const WorkingCurve& g, const MonomialForms& m) {
  const int d = m.d;
  const Coeffs &a = m.a(), &b = m.b(), &a_other = m.a_other(), &b_other = m.b_other();
  const double r = at(b, d) / at(a, d);
  const int top_degree = std::max(f.degree, g.degree);
  const auto f_error = [&](int k) { return coefficient_error(f, k, top_degree); };
  const auto g_error = [&](int k) { return coefficient_error(g, k, top_degree); };
  const double r_rel_error = g_error(d) / std::fabs(at(b, d)) + f_error(d) / std::fabs(at(a, d));
  double betas[2];
  int beta_count = 0;
  if (d == 3) {
    betas[beta_count++] = std::cbrt(r);
  } else if (d % 2 == 1) {
    betas[beta_count++] = std::copysign(std::pow(std::fabs(r), 1.0 / d), r);
  } else if (r > 0) {
    betas[beta_count++] = std::pow(r, 1.0 / d);
    betas[beta_count++] = -betas[0];
  }
  CandidateMaps maps;
  for (int i = 0; i < beta_count; ++i) {
    const double beta = betas[i];
    if (!(std::isfinite(beta) && beta != 0.0)) continue;
    const double beta_k = std::pow(std::fabs(beta), d - 1);  // |beta|^(d-1)
    const double alpha = (at(b, d - 1) / std::pow(beta, d - 1) - at(a, d - 1)) / (d * at(a, d));
    if (!std::isfinite(alpha)) continue;
    const double next = std::pow(beta, d - 1) * (at(a_other, d - 1) + d * alpha * at(a_other, d));
    // The errors of g's coefficients, of f's mapped by beta^(d-1), of beta^(d-1) itself
    // (relative (d - 1)/d of r's), and of alpha (the chosen coordinate's, carried over by
    // |a_other_d| <= |a_d|), in g's scale.
    const double next_tol =
        4 * (g_error(d - 1) * 2 + beta_k * f_error(d - 1) * 2 +
             r_rel_error * (std::fabs(at(b, d - 1)) + std::fabs(at(b_other, d - 1))) +
             beta_k * std::fabs(alpha) * d * f_error(d) * 2);
    if (!(std::fabs(at(b_other, d - 1) - next) <= next_tol)) continue;
    maps.maps[maps.count++] = {alpha, beta};
  }
  return maps;
}

/// The ends of a candidate overlap: (t[0], s[0]) and (t[1], s[1]), s[0] < s[1].
struct OverlapEnds {
  double t[2], s[2];
};

/// The ends in [0, 1]^2 of the overlap that `map` would give: s with alpha + beta s in
/// [0, 1], within [0, 1]. Each end is an end of g (s exact, t located on f by Newton's
/// method from alpha + beta s) or an end of f (t exact, s located on g). nullopt when the
/// range is no longer than kShortestOverlap in s before the ends are pinned, or in s or t
/// after: a flat end (a piece within the tolerance of a point) otherwise passes the
/// verification against any curve through that point, as an overlap of width 0 in t in
/// one order and nothing in the other.
std::optional<OverlapEnds> pinned_ends(const WorkingCurve& f, const WorkingCurve& g,
                                       CoincidenceMap map) {
  const double alpha = map.alpha, beta = map.beta;
  double raw_lo = -alpha / beta, raw_hi = (1 - alpha) / beta;
  if (raw_lo > raw_hi) std::swap(raw_lo, raw_hi);
  // (Comparisons, not max/min: -0.0 must come out as 0.)
  const double s_a = raw_lo <= 0.0 ? 0.0 : raw_lo, s_b = raw_hi >= 1.0 ? 1.0 : raw_hi;
  if (!(s_b - s_a > kShortestOverlap)) return std::nullopt;
  OverlapEnds ends;
  const double s_end[2] = {s_a, s_b};
  const bool s_exact[2] = {raw_lo <= 0.0, raw_hi >= 1.0};
  for (int e = 0; e < 2; ++e) {
    const double phi = alpha + beta * s_end[e];
    if (s_exact[e]) {
      ends.s[e] = s_end[e];
      ends.t[e] = locate_on_curve(f, evaluate_dd(g, s_end[e]),
                                  min2(1.0, max2(0.0, phi)));
    } else {
      ends.t[e] = (e == 0) == (beta > 0) ? 0.0 : 1.0;
      ends.s[e] = locate_on_curve(g, evaluate_dd(f, ends.t[e]), s_end[e]);
    }
  }
  if (!(ends.s[1] - ends.s[0] > kShortestOverlap) ||
      !(std::fabs(ends.t[1] - ends.t[0]) > kShortestOverlap)) {
    return std::nullopt;
  }
  return ends;
}

/// The verification: f on [t[0], t[1]] and g on [s[0], s[1]], written with the same degree,
/// have the same control points to within coincidence_tolerance, and the pieces do not both
/// lie within that tolerance of a point. (Two such pieces, a tiny curve's end next to a
/// huge one's within the rounding of the huge one's scale, may be two distinct points, and
/// which pieces pass would depend on which curve comes first:
/// Overlap.TwoEndsWithinRoundingOfEachOtherAreNoOverlap, ends 3e-9 apart. The search
/// decides there as anywhere else. Such an "overlap" would have its map extrapolated over
/// the whole square and hide a crossing:
/// Overlap.AnOverlapWithinRoundingOfAPointHidesNoCrossing.)
bool pieces_coincide(const WorkingCurve& f, const WorkingCurve& g, const OverlapEnds& ends) {
  const int degree = std::max(f.degree, g.degree);
  const std::vector<double> px = elevated(piece(f.x, ends.t[0], ends.t[1]), degree);
  const std::vector<double> py = elevated(piece(f.y, ends.t[0], ends.t[1]), degree);
  const std::vector<double> qx = elevated(piece(g.x, ends.s[0], ends.s[1]), degree);
  const std::vector<double> qy = elevated(piece(g.y, ends.s[0], ends.s[1]), degree);
  double gap = 0.0;
  for (std::size_t i = 0; i < px.size(); ++i) {
    gap = max2(gap, max2(std::fabs(px[i] - qx[i]), std::fabs(py[i] - qy[i])));
  }
  const double tol = coincidence_tolerance(f, g);
  if (!(gap <= tol)) return false;
  return extent(px, py) > tol || extent(qx, qy) > tol;
}

/// The overlap between verified ends, with the map through them.
OverlapFinding finding_between(const OverlapEnds& ends) {
  OverlapFinding found;
  found.map.beta = (ends.t[1] - ends.t[0]) / (ends.s[1] - ends.s[0]);
  found.map.alpha = ends.t[0] - found.map.beta * ends.s[0];
  found.overlap.t_interval = {min2(ends.t[0], ends.t[1]),
                              max2(ends.t[0], ends.t[1])};
  found.overlap.s_interval = {ends.s[0], ends.s[1]};
  found.overlap.reversed = found.map.beta < 0;
  return found;
}

}  // namespace

std::vector<OverlapFinding> find_overlaps(const WorkingCurve& f, const WorkingCurve& g) {
  std::vector<OverlapFinding> out;
  // Necessary conditions first: most pairs stop at one of them.
  if (!may_overlap(f, g)) return out;
  const std::optional<MonomialForms> forms = agreeing_monomial_forms(f, g);
  if (!forms) return out;
  const CandidateMaps maps = candidate_maps(f, g, *forms);
  for (const CoincidenceMap map : maps.all()) {
    const std::optional<OverlapEnds> ends = pinned_ends(f, g, map);
    if (ends && pieces_coincide(f, g, *ends)) out.push_back(finding_between(*ends));
  }
  return out;
}

bool injective_on(std::span<const double> x, std::span<const double> y, double magnitude, double lo,
                  double hi) {
  const int n = static_cast<int>(x.size()) - 1;
  if (n < 1) return false;
  const Coeffs qx = bernstein::portion<double>(x, lo, hi);
  const Coeffs qy = bernstein::portion<double>(y, lo, hi);
  Coeffs hx(static_cast<std::size_t>(n)), hy(static_cast<std::size_t>(n));
  double h_max = 0.0;
  for (std::size_t i = 0; i < hx.size(); ++i) {
    hx[i] = qx[i + 1] - qx[i];
    hy[i] = qy[i + 1] - qy[i];
    h_max = max2(h_max, max2(std::fabs(hx[i]), std::fabs(hy[i])));
  }
  if (!(h_max > 0)) return false;
  // Extrapolated pieces (reaching outside [0, 1]) are larger; bound their rounding by the
  // largest control point.
  const double q_max = max2(bernstein::max_abs(qx), bernstein::max_abs(qy));
  const double err = 8 * (n + 1) * kUnitRoundoff * max2(q_max, magnitude) + 0x1p-40 * h_max;
  const std::size_t last = hx.size() - 1;
  const double n0 = std::hypot(hx[0], hy[0]), n1 = std::hypot(hx[last], hy[last]);
  const Point2 candidates[] = {
      {qx[hx.size()] - qx[0], qy[hx.size()] - qy[0]},
      {hx[0], hy[0]},
      {hx[last], hy[last]},
      {n0 > 0 && n1 > 0 ? hx[0] / n0 + hx[last] / n1 : 0.0,
       n0 > 0 && n1 > 0 ? hy[0] / n0 + hy[last] / n1 : 0.0},
  };
  for (const Point2 d : candidates) {
    const double d1 = std::fabs(d.x) + std::fabs(d.y);
    if (!(d1 > 0)) continue;
    bool all = true;
    for (std::size_t i = 0; i < hx.size() && all; ++i) all = d.x * hx[i] + d.y * hy[i] > d1 * err;
    if (all) return true;
  }
  return false;
}

bool covered_by_overlap(const WorkingCurve& f, const OverlapFinding& o, ParamInterval t,
                        ParamInterval s) {
  const CoincidenceMap& map = o.map;
  const double p0 = map.alpha + map.beta * s.lo, p1 = map.alpha + map.beta * s.hi;
  const double lo = min2(p0, p1), hi = max2(p0, p1);
  if (hi < t.lo - kCoverSlack || lo > t.hi + kCoverSlack) return false;
  const double u_lo = min2(t.lo, lo) - kCoverSlack;
  const double u_hi = max2(t.hi, hi) + kCoverSlack;
  return injective_on(f.x, f.y, f.magnitude, u_lo, u_hi);
}

CoincidenceTest coincide_at_precision(const WorkingCurve& f, const WorkingCurve& g,
                                      ParamInterval t, ParamInterval s, Point2 center) {
  // The local scale: the piece of f in the box's frame, and its rounding.
  const Piece fp = compensated_piece(f, t.lo, t.hi, center);
  double size = 0.0;
  for (std::size_t i = 0; i < fp.x.size(); ++i)
    size = max2(size, max2(std::fabs(fp.x[i]), std::fabs(fp.y[i])));
  const double floor = 16.0 * std::max(f.degree, g.degree) * (kUnitRoundoff * size + fp.error);
  const Point2 fchord = {fp.x.back() - fp.x[0], fp.y.back() - fp.y[0]};
  const Point2 gchord = evaluate_with_tangent(g, s.hi).point - evaluate_with_tangent(g, s.lo).point;
  const bool forward = dot(fchord, gchord) >= 0;
  CoincidenceTest test;
  for (int k = 0; k < kCoincidenceSamples; ++k) {
    const double tau = static_cast<double>(k) / (kCoincidenceSamples - 1);
    const double tk = t.lo + (t.hi - t.lo) * tau;
    const double guess = forward ? s.lo + (s.hi - s.lo) * tau : s.hi - (s.hi - s.lo) * tau;
    const PointDD p = evaluate_dd(f, tk);
    // locate_on_curve, counting its evaluations.
    const double sk = gauss_newton(guess, kProjectionSteps, kProjectionConverged, [&](double u) {
      ++test.evaluations;
      const Residual r = residual(g, u, p);
      return ResidualAndSlope{{r.x, r.y}, evaluate_with_tangent(g, u).tangent};
    });
    const Residual r = residual(g, sk, p);
    test.evaluations += 2;  // p, and the residual at sk
    if (!(max2(std::fabs(r.x), std::fabs(r.y)) <= floor)) return test;
  }
  test.coincide = true;
  return test;
}

bool on_overlap(const OverlapFinding& o, double t, double s) {
  if (o.arc) return on_arc_overlap(*o.arc, o.overlap, t, s);
  const ParamInterval s_range = o.overlap.s_interval;
  if (s < s_range.lo - kOnOverlapSlack || s > s_range.hi + kOnOverlapSlack) return false;
  return std::fabs(t - (o.map.alpha + o.map.beta * s)) <= kOnOverlapSlack;
}

}  // namespace bezier::core
