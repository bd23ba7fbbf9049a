#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/intersect/merge.hpp"
#include "core/intersect/result.hpp"
#include "core/intersect/working_curve.hpp"

namespace bezier::core {

/// Where two curves on one common line meet: overlapping pieces, and single points where
/// their ranges only touch.
struct CollinearContact {
  ParamInterval t;
  ParamInterval s;
  double t_estimate = 0.0;
  double s_estimate = 0.0;
};

struct CollinearOutcome {
  std::vector<Overlap> overlaps;
  std::vector<CollinearContact> touches;
};

/// When every control point of f and of g lies on one line (to within
/// coincidence_tolerance, relative to the smaller curve), the problem is one-dimensional: with u(t)
/// and v(s) the positions along the line (scalar Bernstein polynomials), f(t) = g(s) iff u(t) =
/// v(s). Each curve is cut at the roots of its derivative into monotone pieces (a straight curve
/// may double back); every pair of pieces whose ranges overlap gives an overlap, with the
/// parameters of the range's ends found by bisection on the monotone pieces; ranges that only touch
/// give a single contact. nullopt when the curves are not on one common line (the general search
/// then applies; collinear curves on different lines cross at most at isolated points).
/// End points equal bit for bit (exact_roots) are part of the answer: an overlap that ends
/// within 2^-40 of one ends on it, a contact next to one is estimated at it, and any other
/// is a contact of its own.
/// Precondition: neither curve is a single point.
[[nodiscard]] std::optional<CollinearOutcome> collinear_intersections(
    const WorkingCurve& f, const WorkingCurve& g, std::span<const ExactRoot> exact_roots);

}  // namespace bezier::core
