#include "core/self_intersect/self_intersection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "core/base/multiversion.hpp"
#include "core/bernstein/roots.hpp"
#include "core/bernstein/casteljau_row.hpp"
#include "core/self_intersect/collinear_fold.hpp"
#include "core/self_intersect/monotone_direction.hpp"
#include "core/cubic/double_point.hpp"
#include "core/cubic/predicates.hpp"
#include "core/numeric/error_free.hpp"
#include "core/numeric/power_of_two.hpp"
#include "core/numeric/unit_roundoff.hpp"
#include "core/curve/evaluate.hpp"
#include "core/intersect/common_arc.hpp"
#include "core/intersect/working_curve.hpp"
#include "core/self_intersect/refine.hpp"
#include "core/self_intersect/search.hpp"
#include "core/self_intersect/tuning.hpp"
#include "core/self_intersect/work_cost.hpp"
#include "core/curve/subdivide.hpp"

namespace bezier::core {

namespace {

using namespace self_intersect_tuning;

/// A candidate pair before clean-up.
struct Candidate {
  double u;
  double v;
  double residual;
  bool contact;  ///< from a contact refinement: a tangency by construction
};

/// Everything the clean-up needs about the curve.
struct CurveFacts {
  const Curve& curve;
  std::span<const Point2> points;
  double scale;
  double dist_tol;
  /// Rounding level of F = B(v) - B(u): 4 (n + 1) u scale.
  double rounding;
  bool closed;
};

/// Whether a Newton root is a real pair rather than a point of the diagonal blurred by
/// rounding (see double_point_uncertainty).
bool resolved(const CurveFacts& facts, double u, double v) {
  return is_resolved_double_point(facts.points, u, v, facts.rounding, facts.closed);
}

/// F = B(v) - B(u) from two compensated de Casteljau evaluations whose value parts and
/// error parts are subtracted separately: good to about u |F| + n^2 u^2 S. The difference of
/// the two rounded points (evaluate()) is only good to u |B|, one ulp of the double point,
/// which two branches crossing at a tiny angle turn into parameter errors of 1e-11.
BEZIER_FMA_CLONES Point2 compensated_difference(const Curve& curve, double u, double v) {
  CasteljauRow<Point2> at_u(curve.points()), at_v(curve.points());
  while (at_u.size() > 1) {
    at_u.casteljau_step(u);
    at_v.casteljau_step(v);
  }
  const TwoTerm<Point2>& bu = at_u.entry(0);
  const TwoTerm<Point2>& bv = at_v.entry(0);
  if (!is_finite(bu.lo) || !is_finite(bv.lo)) return at_v.point(0) - at_u.point(0);
  const TwoTerm<Point2> values = two_sum(bv.hi, -bu.hi);
  return values.hi + (values.lo + (bv.lo - bu.lo));
}

/// |B(v) - B(u)| and |B(v2) - B(u2)| of a cubic, each exactly as exact_residual() gives it:
/// CasteljauRow's compensated recurrence (casteljau_step, the same operations in the same
/// order) run on the four parameters side by side, so that the four independent evaluations
/// share the vector lanes instead of waiting on each other's rounding chains.
BEZIER_FMA_CLONES std::pair<double, double> cubic_exact_residuals(std::span<const Point2> p,
                                                                  double u, double v, double u2,
                                                                  double v2) {
  constexpr int kLanes = 4;
  const double t[kLanes] = {u, v, u2, v2};
  double r[kLanes], rho[kLanes];
  double hx[4][kLanes], hy[4][kLanes], lx[4][kLanes], ly[4][kLanes];
  for (int k = 0; k < kLanes; ++k) {
    const TwoTerm<double> one_minus_t = two_sum(1.0, -t[k]);
    r[k] = one_minus_t.hi;
    rho[k] = one_minus_t.lo;
    for (int i = 0; i < 4; ++i) {
      hx[i][k] = p[i].x;
      hy[i][k] = p[i].y;
      lx[i][k] = 0.0;
      ly[i][k] = 0.0;
    }
  }
  const auto step = [&](double (&h)[4][kLanes], double (&l)[4][kLanes], int i) {
    for (int k = 0; k < kLanes; ++k) {
      const TwoTerm<double> left = two_product(r[k], h[i][k]);
      const TwoTerm<double> right = two_product(t[k], h[i + 1][k]);
      const TwoTerm<double> sum = two_sum(left.hi, right.hi);
      const double local = (left.lo + right.lo) + (sum.lo + rho[k] * h[i][k]);
      l[i][k] = (r[k] * l[i][k] + t[k] * l[i + 1][k]) + local;
      h[i][k] = sum.hi;
    }
  };
  for (int size = 4; size > 1; --size) {
    for (int i = 0; i + 1 < size; ++i) {
      step(hx, lx, i);
      step(hy, ly, i);
    }
  }
  const auto residual = [&](int a, int b) {
    const TwoTerm<Point2> bu{{hx[0][a], hy[0][a]}, {lx[0][a], ly[0][a]}};
    const TwoTerm<Point2> bv{{hx[0][b], hy[0][b]}, {lx[0][b], ly[0][b]}};
    if (!is_finite(bu.lo) || !is_finite(bv.lo)) {
      // As CasteljauRow::point: the plain value where an error part overflowed.
      const auto rounded = [](const TwoTerm<Point2>& e) {
        return is_finite(e.lo) ? e.hi + e.lo : e.hi;
      };
      return norm(rounded(bv) - rounded(bu));
    }
    const TwoTerm<Point2> values = two_sum(bv.hi, -bu.hi);
    return norm(values.hi + (values.lo + (bv.lo - bu.lo)));
  };
  return {residual(0, 1), residual(2, 3)};
}

/// |B(v) - B(u)| from compensated_difference(): the most accurate residual available, used
/// to decide whether an end point is exactly part of the pair and to polish crossings.
double exact_residual(const Curve& curve, double u, double v) {
  return norm(compensated_difference(curve, u, v));
}

/// A crossing refined to full double precision: Newton steps on F = B(v) - B(u) with F from
/// compensated_difference() (mixed-precision iterative refinement). The search's Newton
/// works with plain de Casteljau, whose F is only good to the rounding level n u S: it stops
/// anywhere within double_point_uncertainty() of the root, which for branches crossing at
/// a small angle is far more than ulps: one double point reached from two boxes would come
/// out as two pairs too far apart to merge, and a real pair could fail the distance check on
/// |B(v) - B(u)|. With the accurate F the steps shrink quadratically down to the
/// noise floor, u |F| ||J^-1||; a step that does not halve the one before is noise and is
/// not taken. (Not "while |F| decreases": at an ill-conditioned root the doubles next to it
/// all have |F| at the level of the parameters' own rounding, and points 1e-12 away along
/// the ill-conditioned direction can have a smaller one.) Steps stay within reach of the
/// start, a few times its uncertainty: anything farther is another root, or none. An end
/// parameter exactly 0 or 1 stays, and the other one takes the 1-D least-squares step.
Candidate polished(Candidate c, const CurveFacts& facts) {
  const double reach =
      std::min(kPolishReachMax,
               std::max(kPolishReachMin,
                        kPolishReachFactor *
                            double_point_uncertainty(facts.points, c.u, c.v, facts.rounding)));
  const bool u_fixed = c.u == 0.0 || c.u == 1.0;
  const bool v_fixed = c.v == 0.0 || c.v == 1.0;
  if (u_fixed && v_fixed) return c;
  const double u0 = c.u, v0 = c.v;
  Point2 f = compensated_difference(facts.curve, c.u, c.v);
  double last_step = std::numeric_limits<double>::infinity();
  for (int k = 0; k < kPolishSteps && !(f.x == 0.0 && f.y == 0.0); ++k) {
    const Point2 tu = curve_jet(facts.points, c.u).d1, tv = curve_jet(facts.points, c.v).d1;
    double du = 0.0, dv = 0.0;
    if (u_fixed) {
      dv = -dot(f, tv) / dot(tv, tv);  // B(v + dv) = B(u) along the tangent at v
    } else if (v_fixed) {
      du = dot(f, tu) / dot(tu, tu);
    } else {
      // -B'(u) du + B'(v) dv = -F, by Cramer's rule.
      const Point2 a = -tu;
      const double det = cross(a, tv);
      du = cross(-f, tv) / det;
      dv = cross(a, -f) / det;
    }
    const double step = std::max(std::fabs(du), std::fabs(dv));
    const double nu = c.u + du, nv = c.v + dv;
    if (!(step < 0.5 * last_step) || !(std::isfinite(nu) && std::isfinite(nv))) break;
    if (std::fabs(nu - u0) > reach || std::fabs(nv - v0) > reach) break;
    if (nu == c.u && nv == c.v) break;
    c.u = nu;
    c.v = nv;
    f = compensated_difference(facts.curve, c.u, c.v);
    last_step = step;
  }
  c.residual = norm(f);
  return c;
}

/// The candidate with u moved to 0 (v to 1) when B(0) = B(v) (B(u) = B(1)) holds as well as
/// B(u) = B(v) did, up to rounding: a loop closing exactly at an end reports the end exactly.
/// Either side of the end: a root a few ulps outside [0, 1] is such a loop in all but
/// rounding; one that does not snap is a double point off the segment.
Candidate snapped_to_ends(Candidate c, const CurveFacts& facts) {
  const bool near_start = c.u != 0.0 && std::fabs(c.u) <= kNearEnd;
  const bool near_end = c.v != 1.0 && std::fabs(c.v - 1.0) <= kNearEnd;
  if (!near_start && !near_end) return c;
  const double here = std::max(exact_residual(facts.curve, c.u, c.v), facts.rounding);
  if (near_start && exact_residual(facts.curve, 0.0, c.v) <= here) c.u = 0.0;
  if (near_end && exact_residual(facts.curve, c.u, 1.0) <= here) c.v = 1.0;
  return c;
}

/// The pair as reported (u, v final: see polished()). The double point is the mean of B(t)
/// and B(s), both compensated; the kind comes from the tangents (a contact is tangent by
/// construction unless a tangent vanishes).
SelfIntersection finished_pair(const CurveFacts& facts, double u, double v, bool contact) {
  const CurveJet ju = curve_jet(facts.points, u);
  const CurveJet jv = curve_jet(facts.points, v);
  const double n = static_cast<double>(facts.points.size() - 1);
  const double zero = kZeroTangent * n * facts.scale;
  const double lu = norm(ju.d1), lv = norm(jv.d1);
  IntersectionKind kind = IntersectionKind::transversal;
  if (lu <= zero || lv <= zero) {
    kind = IntersectionKind::degenerate;
  } else if (contact || std::fabs(cross(ju.d1, jv.d1)) <= kTangentSine * lu * lv) {
    kind = IntersectionKind::tangent;
  }
  return {u, v, 0.5 * (evaluate(facts.curve, u) + evaluate(facts.curve, v)), kind};
}

/// Polishes the crossings, snaps to the ends, filters (outside [0,1], t >= s, the pair
/// (0, 1)), sorts and merges the candidates, then computes points and kinds. (0, 1) is
/// never a pair: on a closed curve it is the trivial one, on an open curve B(0) = P_0 and
/// B(1) = P_n differ exactly (it comes from an end loop closing a few ulps off the segment).
std::vector<SelfIntersection> clean_up(const std::vector<Candidate>& candidates,
                                       const CurveFacts& facts) {
  const auto by_u = [](const Candidate& a, const Candidate& b) {
    return a.u != b.u ? a.u < b.u : a.v < b.v;
  };
  std::vector<Candidate> kept;
  for (const Candidate& raw : candidates) {
    const Candidate c = snapped_to_ends(raw.contact ? raw : polished(raw, facts), facts);
    if (!(0.0 <= c.u && c.u < c.v && c.v <= 1.0)) continue;
    if (c.u == 0.0 && c.v == 1.0) continue;
    // A crossing must be a double point: next to an end where B' vanishes Newton can stop
    // (small steps, flat F) far from one. Contacts were checked against dist_tol already.
    if (!c.contact && exact_residual(facts.curve, c.u, c.v) > facts.dist_tol) continue;
    kept.push_back(c);
  }
  std::sort(kept.begin(), kept.end(), by_u);
  std::vector<Candidate> merged;
  for (const Candidate& c : kept) {
    // `merged` is sorted by u too: only its tail can be within the merge distance.
    bool duplicate = false;
    for (auto m = merged.rbegin(); m != merged.rend() && c.u - m->u <= kMergeContacts; ++m) {
      const double tol = (c.contact || m->contact) ? kMergeContacts : kMergeCrossings;
      if (std::fabs(c.u - m->u) <= tol && std::fabs(c.v - m->v) <= tol) {
        // Keep the better one; a Newton crossing beats a contact estimate.
        if ((m->contact && !c.contact) || (m->contact == c.contact && c.residual < m->residual)) {
          *m = c;
        }
        duplicate = true;
        break;
      }
    }
    if (!duplicate) merged.push_back(c);
  }
  std::sort(merged.begin(), merged.end(), by_u);
  std::vector<SelfIntersection> pairs;
  for (const Candidate& c : merged) pairs.push_back(finished_pair(facts, c.u, c.v, c.contact));
  return pairs;
}

/// Contact boxes that touch (within one box width) grouped into clusters, each the bounding
/// box of its members, the comparisons charged to `budget` (cluster_cost, for a degree-n
/// curve); nullopt, the budget exhausted, when they need more than is left.
std::optional<std::vector<ParameterBox>> cluster(std::vector<ParameterBox> boxes, int n,
                                                 WorkBudget& budget) {
  std::sort(boxes.begin(), boxes.end(),
            [](const ParameterBox& a, const ParameterBox& b) { return a.u.lo < b.u.lo; });
  const std::int64_t affordable = affordable_cluster_comparisons(budget.remaining(), n);
  std::int64_t comparisons = 0;
  std::vector<ParameterBox> clusters;
  for (const ParameterBox& b : boxes) {
    const double w = std::max(b.u.width(), b.v.width());
    bool joined = false;
    for (auto it = clusters.rbegin(); it != clusters.rend(); ++it) {
      if (++comparisons > affordable) {
        budget.charge(cluster_cost(affordable, n));
        budget.exhaust();
        return std::nullopt;
      }
      if (b.v.lo <= it->v.hi + w && it->v.lo <= b.v.hi + w && b.u.lo <= it->u.hi + w) {
        *it = {{std::min(it->u.lo, b.u.lo), std::max(it->u.hi, b.u.hi)},
               {std::min(it->v.lo, b.v.lo), std::max(it->v.hi, b.v.hi)}};
        joined = true;
        break;
      }
    }
    if (!joined) clusters.push_back(b);
  }
  budget.charge(cluster_cost(comparisons, n));
  return clusters;
}

/// What resolving the contact boxes gave.
struct ContactResolution {
  std::vector<Candidate> candidates;
  int newton_runs = 0;
  int newton_iterations = 0;
};

/// One candidate per cluster of contact boxes: Newton on F first (a crossing at a tiny
/// angle also ends up here), else the tangential-contact refinement; kept when the two
/// branches meet to within dist_tol and the pair is clear of the diagonal (near a cusp the
/// closest pair slides to u = v) and, on a closed curve, of the seam (next to an end where
/// B' vanishes to high order the closest pair slides along it, away from (0, 1) but not to
/// a double point). The clustering and each refinement (contact_refinement_cost) are
/// charged to `budget`; a refinement that does not fit in what is left is not started.
ContactResolution resolve_contacts(const std::vector<ParameterBox>& boxes, const CurveFacts& facts,
                                   WorkBudget& budget) {
  ContactResolution out;
  const int n = static_cast<int>(facts.points.size()) - 1;
  const auto clusters = cluster(boxes, n, budget);
  if (!clusters) return out;
  double width = 0.0;
  for (const ParameterBox& b : boxes) width = std::max({width, b.u.width(), b.v.width()});
  const std::int64_t refinement_cost = contact_refinement_cost(n);
  for (const ParameterBox& c : *clusters) {
    if (!budget.reserve(refinement_cost)) break;
    budget.charge(refinement_cost);
    const ParameterBox region{{std::max(0.0, c.u.lo - width), std::min(1.0, c.u.hi + width)},
                              {std::max(0.0, c.v.lo - width), std::min(1.0, c.v.hi + width)}};
    const double u0 = 0.5 * (c.u.lo + c.u.hi), v0 = 0.5 * (c.v.lo + c.v.hi);
    PairRefinement r = refine_double_point(facts.points, u0, v0, region, facts.rounding);
    // At a tangency Newton on F stalls, or lands on the double root with a singular
    // Jacobian (an exact start does): then locate the touching point instead.
    const bool contact = !(r.converged && resolved(facts, r.u, r.v));
    if (contact) r = refine_self_contact(facts.points, u0, v0, region);
    ++out.newton_runs;
    out.newton_iterations += r.iterations;
    if (r.residual <= facts.dist_tol &&
        parameter_separation(r.u, r.v, facts.closed) > 4.0 * width) {
      out.candidates.push_back({r.u, r.v, r.residual, contact});
    }
  }
  return out;
}

SelfIntersectionResult collinear_result(const CurveFacts& facts, const CollinearFrame& frame,
                                        WorkBudget& budget) {
  SelfIntersectionResult result;
  result.stats.method = SelfIntersectionMethod::collinear;
  result.overlaps = collinear_self_overlaps(facts.points, frame, facts.dist_tol, budget);
  return result;
}

/// P_i = P_{n-i} for every i: then B(1 - t) = B(t) (the Bernstein basis is symmetric), and
/// the curve runs out along B([0, 1/2]) and back over the same points.
bool is_palindrome(std::span<const Point2> p) {
  for (std::size_t i = 0, j = p.size() - 1; i < j; ++i, --j) {
    if (!(p[i] == p[j])) return false;
  }
  return true;
}

/// A palindromic curve retraces itself: the overlap [0, 1/2] x [1/2, 1] (B(t) = B(1 - t)),
/// and for each self-intersection (a, b) of the outbound half B on [0, 1/2] (found on that
/// half, reparametrised to [0, 1]) the four pairs it makes with the way back: (a, b),
/// (a, 1 - b), (b, 1 - a) and (1 - b, 1 - a). The general search cannot see this: the
/// continuum of pairs (t, 1 - t) would exhaust any work budget.
SelfIntersectionResult retracing_result(const CurveFacts& facts,
                                        const SelfIntersectionOptions& options,
                                        WorkBudget& budget) {
  SelfIntersectionResult result =
      self_intersections(subdivide(facts.curve, 0.5).left, options, budget);
  std::vector<Overlap> overlaps{{{0.0, 0.5}, {0.5, 1.0}}};
  for (const Overlap& o : result.overlaps) {
    const ParamInterval t = o.t_interval, s = o.s_interval;
    overlaps.push_back({{0.5 * t.lo, 0.5 * t.hi}, {0.5 * s.lo, 0.5 * s.hi}});
    overlaps.push_back({{1 - 0.5 * s.hi, 1 - 0.5 * s.lo}, {1 - 0.5 * t.hi, 1 - 0.5 * t.lo}});
  }
  std::vector<SelfIntersection> pairs;
  for (const SelfIntersection& h : result.pairs) {
    const double a = 0.5 * h.t, b = 0.5 * h.s;
    const bool tangent = h.kind == IntersectionKind::tangent;
    for (const auto& [u, v] : {std::pair{a, b}, {a, 1 - b}, {b, 1 - a}, {1 - b, 1 - a}}) {
      const Candidate c =
          tangent ? Candidate{u, v, 0.0, true} : polished({u, v, 0.0, false}, facts);
      pairs.push_back(finished_pair(facts, c.u, c.v, tangent));
    }
  }
  const auto by_t = [](const auto& x, const auto& y) { return x.t != y.t ? x.t < y.t : x.s < y.s; };
  std::sort(pairs.begin(), pairs.end(), by_t);
  // b = 1/2 (a pair at the fold) gives each pair twice.
  pairs.erase(std::unique(pairs.begin(), pairs.end(),
                          [](const auto& x, const auto& y) { return x.t == y.t && x.s == y.s; }),
              pairs.end());
  std::sort(overlaps.begin(), overlaps.end(), [](const Overlap& x, const Overlap& y) {
    return x.t_interval.lo != y.t_interval.lo ? x.t_interval.lo < y.t_interval.lo
                                              : x.s_interval.lo < y.s_interval.lo;
  });
  result.pairs = std::move(pairs);
  result.overlaps = std::move(overlaps);
  return result;
}

/// The t in [0, 1] with p(t) = u, for p in Bernstein form with range [0, 1]. u comes from
/// an approximation of h (about 1e-10 off): an end of [0, 1] within 2^-30 of the level
/// counts too (a root just outside, which the polish on B then settles).
std::vector<double> level_set(const Coeffs& p, double u) {
  std::vector<double> shifted(p.begin(), p.end());
  for (double& c : shifted) c -= u;
  std::vector<double> roots = bernstein_roots(shifted).roots;
  if (std::fabs(shifted.front()) <= kLevelEndSlack &&
      (roots.empty() || roots.front() > kLevelEndSlack)) {
    roots.insert(roots.begin(), 0.0);
  }
  if (std::fabs(shifted.back()) <= kLevelEndSlack &&
      (roots.empty() || roots.back() < 1 - kLevelEndSlack)) {
    roots.push_back(1.0);
  }
  return roots;
}

/// An improper curve B = h(p(t)) (factorise, intersect/common_arc.hpp) that turns back on
/// itself: B(t) = B(s) exactly where p(t) = p(s), between different pieces on which p is
/// monotone (the overlaps: find_self_arc_overlaps), or where h crosses itself,
/// h(u1) = h(u2): every t with p(t) = u1 against every s with p(s) = u2, found from h's own
/// self-intersections (h is proper: the search resolves them) and polished on B. The
/// palindrome is the case p(1 - t) = p(t); the general search cannot see either (a
/// continuum of pairs). Nothing when B is proper or p monotone
/// (no retraced piece: the general search then works).
std::optional<SelfIntersectionResult> improper_result(const CurveFacts& facts,
                                                      const SelfIntersectionOptions& options,
                                                      WorkBudget& budget) {
  if (facts.curve.degree() < 4) return std::nullopt;
  const WorkingCurve w = to_working(facts.curve, working_frame(facts.curve, facts.curve));
  const std::vector<OverlapFinding> found = find_self_arc_overlaps(w);
  if (found.empty()) return std::nullopt;
  SelfIntersectionResult result;
  for (const OverlapFinding& o : found) {
    result.overlaps.push_back({o.overlap.t_interval, o.overlap.s_interval});
  }
  const CommonArc& arc = *found.front().arc;
  std::vector<Point2> h;
  for (std::size_t i = 0; i < arc.hx.size(); ++i) h.push_back({arc.hx[i], arc.hy[i]});
  const SelfIntersectionResult on_h = self_intersections(Curve(std::move(h)), options, budget);
  result.stats = on_h.stats;
  std::vector<Candidate> candidates;
  for (const SelfIntersection& pair : on_h.pairs) {
    const bool tangent = pair.kind == IntersectionKind::tangent;
    for (const double t : level_set(arc.p, pair.t)) {
      for (const double s : level_set(arc.p, pair.s)) {
        candidates.push_back({std::min(t, s), std::max(t, s), 0.0, tangent});
      }
    }
  }
  result.pairs = clean_up(candidates, facts);
  return result;
}

/// What the cubic closed form says: a loop (the pair (t, s) with its point), no loop on
/// [0, 1] other than a closed curve's trivial pair (the caller then still checks for a
/// collinear or palindromic, retracing, cubic, which the closed form does not describe), or
/// nothing certain.
enum class ClosedFormVerdict { loop, no_loop, undecided };

struct ClosedFormAnswer {
  ClosedFormVerdict verdict = ClosedFormVerdict::undecided;
  double t = 0.0;
  double s = 0.0;
  Point2 point;
  int newton_iterations = 0;  ///< of the polish
};

/// Cubics: the exact closed form of cubic_double_point() (exact decisions, and t = 0 or 1
/// exactly when the loop closes at an end), polished by one Newton step to full precision.
/// The point is the closed form's (the mean of B(t1) and B(t2), exactly P0 or P3 at an exact
/// end; the polish moves t by ulps), and the kind is transversal: the only singular points a
/// cubic can have are a node, a cusp (no pair) and an isolated point (no real pair), so two
/// branches through a double point cross.
/// Coordinates spanning more than about 2^400 leave the predicates inexact
/// (CubicPredicates::exact false): then the answer is the closed form's only when it is a
/// pair with B(t) = B(s) to within the distance tolerance, and undecided otherwise (an
/// inexact "no loop", or a pair that is no double point, such as (0, 1) on an open curve).
ClosedFormAnswer closed_form_cubic(const CurveFacts& facts) {
  const std::span<const Point2, 4> p(facts.points.data(), 4);
  const CubicPredicates predicates = cubic_predicates(p);
  ClosedFormAnswer no_loop;
  if (predicates.exact) no_loop.verdict = ClosedFormVerdict::no_loop;
  const auto dp = cubic_double_point(p, predicates);
  if (!dp || !dp->on_segment) return no_loop;
  // (0, 1): the trivial pair; on an open curve only when the power-of-two rescaling made
  // the ends equal by underflow, a loop closing below the resolution.
  if (dp->t1 == 0.0 && dp->t2 == 1.0) return no_loop;
  if (!(dp->t1 < dp->t2)) return no_loop;  // a loop of width zero is no pair (t < s)
  double u = dp->t1, v = dp->t2;
  const PairRefinement polished =
      refine_double_point(facts.points, u, v, {{0.0, 1.0}, {0.0, 1.0}}, facts.rounding, 8);
  if (polished.converged && polished.u < polished.v) {
    // Ends decided exactly stay exact. The polish is kept only when it does not increase
    // the compensated residual |B(v) - B(u)|: on an ill-conditioned (nearly collinear)
    // cubic Newton can walk away from the closed form's root and still report converged.
    // Parameters strictly inside (0, 1) by the exact signs stay there.
    const double nu =
        u != 0.0 ? std::max(polished.u, std::numeric_limits<double>::denorm_min()) : u;
    const double nv = v != 1.0 ? std::min(polished.v, std::nextafter(1.0, 0.0)) : v;
    const auto [polished_residual, closed_form_residual] =
        cubic_exact_residuals(facts.points, nu, nv, u, v);
    if (polished_residual <= closed_form_residual) {
      u = nu;
      v = nv;
    }
  }
  if (!predicates.exact &&
      ((u == 0.0 && v == 1.0) || !(exact_residual(facts.curve, u, v) <= facts.dist_tol))) {
    return {};
  }
  return {ClosedFormVerdict::loop, u, v, dp->point, polished.iterations};
}

/// Whether B runs over a retraced piece backwards the second time: B(t_interval.lo) nearer
/// B(s_interval.hi) than B(s_interval.lo) (evaluated, so it holds for every kind of overlap
/// above, however its intervals were found).
bool runs_backwards(const Curve& curve, const Overlap& o) {
  const Point2 a = evaluate(curve, o.t_interval.lo);
  const double same = length(a - evaluate(curve, o.s_interval.lo));
  const double opposite = length(a - evaluate(curve, o.s_interval.hi));
  return opposite < same;
}

/// cubic_predicates is exact for every cubic whose nonzero coordinates are all at least this
/// times its largest one: its exact path scales the largest coordinate into [2^200, 2^201)
/// and loses only coordinates that fall below 2^-216 there, i.e. below 2^-416 times the
/// largest (core/cubic/predicates.cpp); its filter is exact whenever it decides.
constexpr double kExactPredicatesRange = 0x1p-415;

/// Whether a cubic is one that closed_form_cubic and the branches after it answer with
/// nothing (no pair, no overlap, method closed_form_cubic, nothing charged), shown without
/// them:
///  - its largest coordinate s lies in [kSmallestUnscaled, kLargestUnscaled], so it is
///    worked on as given, and every nonzero coordinate is at least kExactPredicatesRange s,
///    so the closed form's predicates are exact (closed_form_cubic answers loop or no_loop);
///  - it is certainly monotone along a direction (certainly_monotone), hence injective on
///    [0, 1]: the closed form, whose on_segment is decided exactly, has no double point
///    there (one would be a pair t1 < t2 with B(t1) = B(t2)), and P_0 != P_3, so the cubic
///    is neither closed nor palindromic;
///  - collinear_frame finds no line at the distance tolerance, so the collinear branch,
///    tried before "no loop" is accepted, is not taken (a collinear curve can be monotone
///    along some direction and fold back along its line within the tolerance).
/// Degree 3 has no improper branch (improper_result starts at degree 4).
/// Precondition: a cubic (four control points, read with a fixed extent).
bool certainly_loop_free_cubic(const Curve& curve, const SelfIntersectionOptions& options) noexcept {
  const std::span<const Point2, 4> points = curve.points().first<4>();
  // s = scale(curve) (the same maximum, without the libm calls of fmax; the coordinates are
  // finite) and the smallest nonzero |coordinate|, in one pass without branches.
  double s = 0.0, smallest = std::numeric_limits<double>::infinity();
  for (const Point2 p : points) {
    const double ax = std::fabs(p.x), ay = std::fabs(p.y);
    s = std::max(s, std::max(ax, ay));
    // A zero coordinate loses nothing; it counts as infinite here.
    const double nx = ax > 0.0 ? ax : std::numeric_limits<double>::infinity();
    const double ny = ay > 0.0 ? ay : std::numeric_limits<double>::infinity();
    smallest = std::min(smallest, std::min(nx, ny));
  }
  return self_intersect_tuning::kSmallestUnscaled <= s &&
         s <= self_intersect_tuning::kLargestUnscaled && smallest >= kExactPredicatesRange * s &&
         certainly_monotone(points) && !collinear_frame(points, options.dist_rel * s);
}

}  // namespace

bool certainly_without_self_intersections(const Curve& curve,
                                          const SelfIntersectionOptions& options) noexcept {
  return curve.degree() == 3 && options.cubic_closed_form &&
         certainly_loop_free_cubic(curve, options);
}

SelfIntersectionResult self_intersections(const Curve& curve,
                                          const SelfIntersectionOptions& options) {
  WorkBudget budget(options.max_work);
  SelfIntersectionResult result = self_intersections(curve, options, budget);
  if (budget.exhausted()) result.status = IntersectStatus::work_cap_reached;
  return result;
}

SelfIntersectionResult self_intersections(const Curve& curve,
                                          const SelfIntersectionOptions& options,
                                          WorkBudget& budget) {
  if (certainly_without_self_intersections(curve, options)) {
    SelfIntersectionResult result;
    result.stats.method = SelfIntersectionMethod::closed_form_cubic;
    return result;
  }
  const std::int64_t spent_before = budget.spent();
  // Squared lengths in the inner loops (sqrt(v·v), not the slower overflow-safe hypot) need
  // coordinates within about 2^±300: outside that range, work on the curve scaled by 2^k
  // so that its largest coordinate lies in [1, 2). Scaling by a power of two is exact
  // (barring underflow of coordinates 2^-1000 below the largest) and every step of the
  // method scales with it, so parameters come out the same either way.
  const double original_scale = scale(curve);
  const bool moderate = self_intersect_tuning::kSmallestUnscaled <= original_scale &&
                        original_scale <= self_intersect_tuning::kLargestUnscaled;
  const int k = moderate || original_scale == 0.0 ? 0 : -exponent_of(original_scale);
  std::optional<Curve> rescaled;
  if (k != 0) rescaled.emplace(scaled_by_power_of_two(curve.points(), k));
  const Curve& work_curve = rescaled ? *rescaled : curve;
  const std::span<const Point2> points = work_curve.points();
  const double s = k != 0 ? PowerOfTwo(k).times(original_scale) : original_scale;
  const double rounding = 4.0 * static_cast<double>(points.size()) * kUnitRoundoff * s;
  const CurveFacts facts{work_curve,           points,   s,
                         options.dist_rel * s, rounding, curve.front() == curve.back()};

  ClosedFormAnswer cubic;
  if (curve.degree() == 3 && options.cubic_closed_form) cubic = closed_form_cubic(facts);
  SelfIntersectionResult result;
  if (cubic.verdict == ClosedFormVerdict::loop) {
    result.stats.method = SelfIntersectionMethod::closed_form_cubic;
    result.stats.newton_runs = 1;
    result.stats.newton_iterations = cubic.newton_iterations;
    result.pairs.push_back({cubic.t, cubic.s, cubic.point, IntersectionKind::transversal});
  } else if (const auto frame = collinear_frame(points, facts.dist_tol)) {
    result = collinear_result(facts, *frame, budget);
  } else if (is_palindrome(points)) {
    result = retracing_result(facts, options, budget);
  } else if (auto improper = improper_result(facts, options, budget)) {
    result = std::move(*improper);
  } else if (cubic.verdict == ClosedFormVerdict::no_loop) {
    result.stats.method = SelfIntersectionMethod::closed_form_cubic;
  } else {
    const SelfIntersectionSearchOutcome found = search_self_intersections(
        points, {facts.dist_tol, facts.rounding, options.max_depth, facts.closed}, budget);
    result.stats = found.stats;
    result.stats.method = SelfIntersectionMethod::subdivision;
    std::vector<Candidate> candidates;
    for (const PairRefinement& r : found.crossings) {
      candidates.push_back({r.u, r.v, r.residual, false});
    }
    // After a capped search the contact boxes are an arbitrary part of a pathological
    // input's (typically a retraced piece's): not worth refining.
    if (!budget.exhausted() && !found.contact_boxes.empty()) {
      const ContactResolution contacts = resolve_contacts(found.contact_boxes, facts, budget);
      candidates.insert(candidates.end(), contacts.candidates.begin(), contacts.candidates.end());
      result.stats.newton_runs += contacts.newton_runs;
      result.stats.newton_iterations += contacts.newton_iterations;
    }
    result.pairs = clean_up(candidates, facts);
  }
  if (k != 0) {
    const PowerOfTwo back(-k);
    for (SelfIntersection& pair : result.pairs) pair.point = back.times(pair.point);
  }
  for (Overlap& o : result.overlaps) o.reversed = runs_backwards(curve, o);
  result.stats.work = budget.spent() - spent_before;
  return result;
}

}  // namespace bezier::core
