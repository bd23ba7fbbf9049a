#include "core/self_intersection.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/collinear_self_overlap.hpp"
#include "core/cubic_double_point.hpp"
#include "core/evaluate.hpp"
#include "core/self_intersection_refine.hpp"
#include "core/self_intersection_search.hpp"
#include "core/subdivide.hpp"

namespace bezier::core {

namespace {

constexpr double kUnitRoundoff = 0x1p-53;
// Pairs found twice (from neighbouring boxes) agree to a few ulps; distinct transversal
// pairs this close in both parameters do not occur above the resolution of the search.
constexpr double kMergeCrossings = 1e-10;
// Tangential contacts are located less sharply (and from clusters of boxes).
constexpr double kMergeContacts = 1e-7;
// Sine of the angle between the tangents below which a pair counts as tangent: about
// sqrt(u), the precision to which a double root's tangent directions can be matched.
constexpr double kTangentSine = 1e-7;

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
  return is_resolved_double_point(facts.points, u, v, facts.rounding);
}

/// |B(v) - B(u)| with the compensated evaluation: the most accurate residual available,
/// used to decide whether an end point is exactly part of the pair.
double exact_residual(const Curve& curve, double u, double v) {
  return norm(evaluate(curve, v) - evaluate(curve, u));
}

/// The candidate with u moved to 0 (v to 1) when B(0) = B(v) (B(u) = B(1)) holds as well as
/// B(u) = B(v) did, up to rounding: a loop closing exactly at an end reports the end exactly.
Candidate snapped_to_ends(Candidate c, const CurveFacts& facts) {
  constexpr double kNearEnd = 0x1p-20;
  const bool near_start = c.u != 0.0 && std::fabs(c.u) <= kNearEnd;
  const bool near_end = c.v != 1.0 && std::fabs(c.v - 1.0) <= kNearEnd;
  if (!near_start && !near_end) return c;
  const double here = std::max(exact_residual(facts.curve, c.u, c.v), facts.rounding);
  if (near_start && exact_residual(facts.curve, 0.0, c.v) <= here) c.u = 0.0;
  if (near_end && exact_residual(facts.curve, c.u, 1.0) <= here) c.v = 1.0;
  return c;
}

/// The pair as reported. A transversal pair gets one last Newton step whose residual
/// F = B(s) - B(t) comes from the compensated evaluate() (mixed-precision iterative
/// refinement): plain de Casteljau's residual is only good to about n u S, the compensated
/// one to about u |B|, so the step lands within about an ulp of a well-conditioned root.
/// Parameters already exactly at an end stay there. The double point is the mean of B(t)
/// and B(s), both compensated; the kind comes from the tangents (a contact is tangent by
/// construction unless a tangent vanishes).
SelfIntersection finished_pair(const CurveFacts& facts, double u, double v, bool contact) {
  const CurveJet ju = curve_jet(facts.points, u);
  const CurveJet jv = curve_jet(facts.points, v);
  const double n = static_cast<double>(facts.points.size() - 1);
  const double zero = 1e-12 * n * facts.scale;
  const double lu = norm(ju.d1), lv = norm(jv.d1);
  SelfIntersectionKind kind = SelfIntersectionKind::transversal;
  if (lu <= zero || lv <= zero) {
    kind = SelfIntersectionKind::degenerate;
  } else if (contact || std::fabs(cross(ju.d1, jv.d1)) <= kTangentSine * lu * lv) {
    kind = SelfIntersectionKind::tangent;
  }
  Point2 bu = evaluate(facts.curve, u), bv = evaluate(facts.curve, v);
  if (kind == SelfIntersectionKind::transversal) {
    const Point2 f = bv - bu, a = -ju.d1;
    const double det = cross(a, jv.d1);
    const double du = cross(-f, jv.d1) / det, dv = cross(a, -f) / det;
    // A correction at rounding level only; anything larger means the pair was not settled.
    constexpr double kPolish = 0x1p-40;
    if (std::fabs(du) <= kPolish && std::fabs(dv) <= kPolish) {
      const double nu = (u == 0.0 || u == 1.0) ? u : u + du;
      const double nv = (v == 0.0 || v == 1.0) ? v : v + dv;
      // The points move by B' times a step of a few ulps: to first order, exactly enough.
      bu = bu + (nu - u) * ju.d1;
      bv = bv + (nv - v) * jv.d1;
      u = nu;
      v = nv;
    }
  }
  return {u, v, 0.5 * (bu + bv), kind};
}

/// Snaps, filters (outside [0,1], t >= s, the trivial pair of a closed curve), sorts and
/// merges the candidates, then computes points and kinds.
std::vector<SelfIntersection> clean_up(const std::vector<Candidate>& candidates,
                                       const CurveFacts& facts) {
  const auto by_u = [](const Candidate& a, const Candidate& b) {
    return a.u != b.u ? a.u < b.u : a.v < b.v;
  };
  std::vector<Candidate> kept;
  for (const Candidate& raw : candidates) {
    const Candidate c = snapped_to_ends(raw, facts);
    if (!(0.0 <= c.u && c.u < c.v && c.v <= 1.0)) continue;
    if (facts.closed && c.u == 0.0 && c.v == 1.0) continue;
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

// Costs of the contact stage in units of the work budget (parameter boxes): a refinement
// takes up to ~60 Newton steps, about what 8 boxes cost; 64 cluster comparisons one box.
constexpr std::int64_t kRefinementWork = 8;
constexpr std::int64_t kComparisonsPerWork = 64;

/// Contact boxes grouped into clusters, and the work that took.
struct Clusters {
  std::vector<ParameterBox> boxes;
  std::int64_t work = 0;
};

/// Contact boxes that touch (within one box width) grouped into clusters, each the bounding
/// box of its members; nullopt when the comparisons exceed `budget` work units.
std::optional<Clusters> cluster(std::vector<ParameterBox> boxes, std::int64_t budget) {
  std::sort(boxes.begin(), boxes.end(),
            [](const ParameterBox& a, const ParameterBox& b) { return a.u_lo < b.u_lo; });
  std::int64_t comparisons = 0;
  std::vector<ParameterBox> clusters;
  for (const ParameterBox& b : boxes) {
    const double w = std::max(b.u_hi - b.u_lo, b.v_hi - b.v_lo);
    bool joined = false;
    for (auto it = clusters.rbegin(); it != clusters.rend(); ++it) {
      if (++comparisons > budget * kComparisonsPerWork) return std::nullopt;
      if (b.v_lo <= it->v_hi + w && it->v_lo <= b.v_hi + w && b.u_lo <= it->u_hi + w) {
        *it = {std::min(it->u_lo, b.u_lo), std::max(it->u_hi, b.u_hi), std::min(it->v_lo, b.v_lo),
               std::max(it->v_hi, b.v_hi)};
        joined = true;
        break;
      }
    }
    if (!joined) clusters.push_back(b);
  }
  return Clusters{std::move(clusters), comparisons / kComparisonsPerWork};
}

/// What resolving the contact boxes gave, and cost.
struct ContactResolution {
  std::vector<Candidate> candidates;
  int newton_runs = 0;
  int newton_iterations = 0;
  std::int64_t work = 0;
  bool work_cap_reached = false;
};

/// One candidate per cluster of contact boxes: Newton on F first (a crossing at a tiny
/// angle also ends up here), else the tangential-contact refinement; kept when the two
/// branches meet to within dist_tol and the pair is clear of the diagonal (near a cusp the
/// closest pair slides to u = v). Stops at `budget` work units.
ContactResolution resolve_contacts(const std::vector<ParameterBox>& boxes, const CurveFacts& facts,
                                   std::int64_t budget) {
  ContactResolution out;
  const auto clusters = cluster(boxes, budget);
  if (!clusters) {
    out.work = budget;
    out.work_cap_reached = true;
    return out;
  }
  out.work = clusters->work;
  double width = 0.0;
  for (const ParameterBox& b : boxes) width = std::max({width, b.u_hi - b.u_lo, b.v_hi - b.v_lo});
  for (const ParameterBox& c : clusters->boxes) {
    if (out.work + kRefinementWork > budget) {
      out.work_cap_reached = true;
      break;
    }
    out.work += kRefinementWork;
    const ParameterBox region{std::max(0.0, c.u_lo - width), std::min(1.0, c.u_hi + width),
                              std::max(0.0, c.v_lo - width), std::min(1.0, c.v_hi + width)};
    const double u0 = 0.5 * (c.u_lo + c.u_hi), v0 = 0.5 * (c.v_lo + c.v_hi);
    PairRefinement r = refine_double_point(facts.points, u0, v0, region, facts.rounding);
    // At a tangency Newton on F stalls, or lands on the double root with a singular
    // Jacobian (an exact start does): then locate the touching point instead.
    const bool contact = !(r.converged && resolved(facts, r.u, r.v));
    if (contact) r = refine_contact(facts.points, u0, v0, region);
    ++out.newton_runs;
    out.newton_iterations += r.iterations;
    if (r.residual <= facts.dist_tol && r.v - r.u > 4.0 * width) {
      out.candidates.push_back({r.u, r.v, r.residual, contact});
    }
  }
  return out;
}

SelfIntersectionResult collinear_result(const CurveFacts& facts, const CollinearFrame& frame,
                                        const SelfIntersectionOptions& options) {
  SelfIntersectionResult result;
  result.stats.method = SelfIntersectionMethod::collinear;
  CollinearOverlaps found =
      collinear_self_overlaps(facts.points, frame, facts.dist_tol, options.max_work);
  result.stats.work = found.work;
  result.overlaps = std::move(found.overlaps);
  if (found.work_cap_reached) {
    result.status = SelfIntersectionStatus::work_cap_reached;
  } else if (!result.overlaps.empty()) {
    result.status = SelfIntersectionStatus::degenerate;
  }
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
                                        const SelfIntersectionOptions& options) {
  SelfIntersectionResult result = self_intersections(subdivide(facts.curve, 0.5).left, options);
  if (result.status != SelfIntersectionStatus::work_cap_reached) {
    result.status = SelfIntersectionStatus::degenerate;
  }
  std::vector<SelfOverlap> overlaps{{0.0, 0.5, 0.5, 1.0}};
  for (const SelfOverlap& o : result.overlaps) {
    overlaps.push_back({0.5 * o.t_lo, 0.5 * o.t_hi, 0.5 * o.s_lo, 0.5 * o.s_hi});
    overlaps.push_back({1 - 0.5 * o.s_hi, 1 - 0.5 * o.s_lo, 1 - 0.5 * o.t_hi, 1 - 0.5 * o.t_lo});
  }
  std::vector<SelfIntersection> pairs;
  for (const SelfIntersection& h : result.pairs) {
    const double a = 0.5 * h.t, b = 0.5 * h.s;
    const bool tangent = h.kind == SelfIntersectionKind::tangent;
    for (const auto& [u, v] : {std::pair{a, b}, {a, 1 - b}, {b, 1 - a}, {1 - b, 1 - a}}) {
      pairs.push_back(finished_pair(facts, u, v, tangent));
    }
  }
  const auto by_t = [](const auto& x, const auto& y) { return x.t != y.t ? x.t < y.t : x.s < y.s; };
  std::sort(pairs.begin(), pairs.end(), by_t);
  // b = 1/2 (a pair at the fold) gives each pair twice.
  pairs.erase(std::unique(pairs.begin(), pairs.end(),
                          [](const auto& x, const auto& y) { return x.t == y.t && x.s == y.s; }),
              pairs.end());
  std::sort(overlaps.begin(), overlaps.end(), [](const SelfOverlap& x, const SelfOverlap& y) {
    return x.t_lo != y.t_lo ? x.t_lo < y.t_lo : x.s_lo < y.s_lo;
  });
  result.pairs = std::move(pairs);
  result.overlaps = std::move(overlaps);
  return result;
}

/// Cubics: the exact closed form of cubic_double_point() (exact decisions, and t = 0 or 1
/// exactly when the loop closes at an end), polished by one Newton step to full precision.
/// nullopt when the cubic has no loop on [0, 1] other than a closed curve's trivial pair;
/// the caller then still checks for a collinear or palindromic (retracing) cubic, which the
/// closed form does not describe. The point is the closed form's (the mean of B(t1) and
/// B(t2), exactly P0 or P3 at an exact end; the polish moves t by ulps), and the kind is
/// transversal: the only singular points a cubic can have are a node, a cusp (no pair) and
/// an isolated point (no real pair), so two branches through a double point cross.
std::optional<SelfIntersectionResult> closed_form_cubic(const CurveFacts& facts) {
  const auto dp = cubic_double_point(std::span<const Point2, 4>(facts.points.data(), 4));
  if (!dp || !dp->on_segment) return std::nullopt;
  if (facts.closed && dp->t1 == 0.0 && dp->t2 == 1.0) return std::nullopt;  // the trivial pair
  if (!(dp->t1 < dp->t2)) return std::nullopt;  // a loop of width zero is no pair (t < s)
  SelfIntersectionResult result;
  result.stats.method = SelfIntersectionMethod::closed_form_cubic;
  double u = dp->t1, v = dp->t2;
  const PairRefinement polished =
      refine_double_point(facts.points, u, v, {0.0, 1.0, 0.0, 1.0}, facts.rounding, 8);
  ++result.stats.newton_runs;
  result.stats.newton_iterations += polished.iterations;
  if (polished.converged && polished.u < polished.v) {
    // Ends decided exactly stay exact. The polish is kept only when it does not increase
    // the compensated residual |B(v) - B(u)|: on an ill-conditioned (nearly collinear)
    // cubic Newton can walk away from the closed form's root and still report converged.
    const double nu = u != 0.0 ? polished.u : u;
    const double nv = v != 1.0 ? polished.v : v;
    if (exact_residual(facts.curve, nu, nv) <= exact_residual(facts.curve, u, v)) {
      u = nu;
      v = nv;
    }
  }
  result.pairs.push_back({u, v, dp->point, SelfIntersectionKind::transversal});
  return result;
}

}  // namespace

SelfIntersectionResult self_intersections(const Curve& curve,
                                          const SelfIntersectionOptions& options) {
  // Squared lengths in the inner loops (sqrt(v·v), not the slower overflow-safe hypot) need
  // coordinates within about 2^±300: outside that range, work on the curve scaled by 2^k
  // so that its largest coordinate lies in [1, 2). Scaling by a power of two is exact
  // (barring underflow of coordinates 2^-1000 below the largest) and every step of the
  // method scales with it, so parameters come out the same either way.
  const double original_scale = scale(curve);
  const bool moderate = 0x1p-300 <= original_scale && original_scale <= 0x1p300;
  const int k = moderate || original_scale == 0.0 ? 0 : -std::ilogb(original_scale);
  // 2^k as two normal factors (k reaches 1074 for subnormal input).
  const double f1 = std::ldexp(1.0, k / 2), f2 = std::ldexp(1.0, k - k / 2);
  std::optional<Curve> rescaled;
  if (k != 0) {
    std::vector<Point2> scaled;
    scaled.reserve(curve.points().size());
    for (const Point2 p : curve.points()) scaled.push_back((p * f1) * f2);
    rescaled.emplace(std::move(scaled));
  }
  const Curve& work_curve = rescaled ? *rescaled : curve;
  const std::span<const Point2> points = work_curve.points();
  const double s = k != 0 ? (original_scale * f1) * f2 : original_scale;
  const double rounding = 4.0 * static_cast<double>(points.size()) * kUnitRoundoff * s;
  const CurveFacts facts{work_curve,           points,   s,
                         options.dist_rel * s, rounding, curve.front() == curve.back()};

  const bool cubic_fast_path = curve.degree() == 3 && options.cubic_closed_form;
  std::optional<SelfIntersectionResult> cubic_loop;
  if (cubic_fast_path) cubic_loop = closed_form_cubic(facts);
  SelfIntersectionResult result;
  if (cubic_loop) {
    result = std::move(*cubic_loop);
  } else if (const auto frame = collinear_frame(points, facts.dist_tol)) {
    result = collinear_result(facts, *frame, options);
  } else if (is_palindrome(points)) {
    result = retracing_result(facts, options);
  } else if (cubic_fast_path) {
    result.stats.method = SelfIntersectionMethod::closed_form_cubic;  // no loop
  } else {
    const SelfIntersectionSearchOutcome found = search_self_intersections(
        points,
        {facts.dist_tol, facts.rounding, options.max_work, options.max_depth, facts.closed});
    result.stats = found.stats;
    result.stats.method = SelfIntersectionMethod::subdivision;
    std::vector<Candidate> candidates;
    for (const PairRefinement& r : found.crossings) {
      candidates.push_back({r.u, r.v, r.residual, false});
    }
    bool capped = found.work_cap_reached;
    // After a capped search the contact boxes are an arbitrary part of a pathological
    // input's (typically a retraced piece's): not worth refining.
    if (!capped && !found.contact_boxes.empty()) {
      const ContactResolution contacts =
          resolve_contacts(found.contact_boxes, facts, options.max_work - found.stats.work);
      candidates.insert(candidates.end(), contacts.candidates.begin(), contacts.candidates.end());
      result.stats.work += contacts.work;
      result.stats.newton_runs += contacts.newton_runs;
      result.stats.newton_iterations += contacts.newton_iterations;
      capped = contacts.work_cap_reached;
    }
    result.pairs = clean_up(candidates, facts);
    if (capped) result.status = SelfIntersectionStatus::work_cap_reached;
  }
  if (k != 0) {
    for (SelfIntersection& pair : result.pairs) pair.point = (pair.point / f1) / f2;
  }
  return result;
}

}  // namespace bezier::core
