#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/base/curve.hpp"
#include "core/base/interval.hpp"
#include "core/intersect/tuning.hpp"
#include "core/intersect/working_curve.hpp"

namespace bezier::core {

// High-order contacts, certified exactly instead of subdivided.
//
// Where two curves touch with a contact of order k (the distance between them grows like
// |t - t*|^k), f(t) - g(s) stays below rounding on a stretch of length about u^(1/k) around
// the contact, and a box search cannot separate anything there: every box of the stretch is
// split down to the precision floor (order 5: thousands of boxes). The contact itself is a
// finite algebraic fact, and when it lies at rational parameters it can be proved in exact
// arithmetic, with a box around it in which it is the only solution. This is that proof.
//
// The certificate (for t* = a/b and s* = a'/b', small integers):
//  1. With t = (a + x)/b and s = (a' + y)/b', P(x) = b'^m b^n f(t) and Q(y) = b^n b'^m g(s)
//     are polynomial maps with dyadic coefficients (exact expansions,
//     core/numeric/expansion.hpp), and f(t) = g(s) exactly when P(x) = Q(y). First P(0) =
//     Q(0), exactly.
//  2. A reparametrisation y = c Psi(z), x = c^2 z, Psi(z) = sum_{j=1..k} Phi_j z^j, where c
//     is the component of Q'(0) largest in magnitude (along axis e), is built term by term so
//     that the e-component of E(z) = P(c^2 z) - Q(c Psi(z)) vanishes to order k + 1; the
//     scaling by c keeps every Phi_j a polynomial in the data (no division). k is the first
//     order at which the other component of E does not vanish: E(z) = z^k w(z) with
//     w(0) = E_k, and w(0) x Q'(0) = +-c E_k,o != 0. No such k up to n m (Bezout's bound on
//     the intersection multiplicity) means a common component: no certificate.
//  3. Isolation. On Z x Y = [-rho, rho] x [-R, R] with R >= |c Psi(Z)|, suppose
//     w(z) x M != 0 for every z in Z and every M in the convex hull of Q'(Y). If
//     P(c^2 z) = Q(y) there, then with phi = c Psi(z), Q(y) - Q(phi) = (y - phi) M for the
//     mean M of Q' on [phi, y] (inside Y), so z^k w(z) = E(z) = (y - phi) M and
//     z^k (w(z) x M) = 0: z = 0, then y M = 0 and y = 0. So (t*, s*) is the only solution of
//     f(t) = g(s) with t - t* in c^2 Z / b and s - s* in Y / b'. The condition is checked
//     with |a x b| <= 2 |a|_inf |b|_inf, the Taylor tails of w and Q' bounded from the
//     exact coefficients rounded outward, for rho giving t-radii c^2 rho / b = 2^-1, 2^-2,
//     ... until it holds (down to 2 kLeastIsolation).
// Orders 1 (a crossing) and 2 (an ordinary tangency, where the search and the tangency
// system of refine.hpp are fast) are left to the search. Contacts at irrational parameters
// have no certificate here: the search handles them as before (which, at order >= 4, may
// mean the work cap).

/// A parameter a / b with integers 0 <= a <= b, 1 <= b (exact in doubles).
struct RationalParameter {
  double num = 0.0;
  double den = 1.0;
  friend bool operator==(RationalParameter, RationalParameter) = default;
};

/// A certified contact of f and g.
struct HighOrderContact {
  RationalParameter t_exact, s_exact;  ///< the contact, exactly
  /// The doubles enclosing t_exact and s_exact: zero width when they are doubles, else the
  /// two neighbours of the rounded quotient.
  ParamInterval t, s;
  /// (t_exact, s_exact) is the only solution of f(t) = g(s) with t in t_isolated and s in
  /// s_isolated (half of the certified box, rounded inward, cut to [0, 1]).
  ParamInterval t_isolated, s_isolated;
  int order = 0;  ///< k: the curves' distance grows like |t - t*|^k (the intersection multiplicity)
};

/// Work units one exact expansion product is charged (allocation and a product of two
/// expansions of a few dozen components: about a hundred updates of de Casteljau's algorithm
/// in doubles, the unit of work_cost.hpp).
inline constexpr std::int64_t kExpansionProductCost = 100;

/// The certificate above for the contact of f and g (degrees n, m >= 1) at (t, s), or nothing
/// when it does not hold: f(t) != g(s), a contact of order below 3, zero derivatives of both
/// curves there (where only g's vanishes, the certificate, symmetric in the two curves, is
/// taken with their roles exchanged: Q the map of f), a common component, an exact product outside the expansions' exponent window, no rho
/// down to 2^-52, or more than `max_products` exact products needed. `products` receives
/// the number of exact products taken (the caller charges them).
/// Preconditions: finite control points; 0 <= num <= den.
[[nodiscard]] std::optional<HighOrderContact> certify_high_order_contact(
    const Curve& f, const Curve& g, RationalParameter t, RationalParameter s,
    std::int64_t max_products, std::int64_t& products);

/// The simplest rational in [lo, hi] (subset of [0, 1]): the one with the least denominator
/// (then the least numerator), if some denominator up to max_den has one.
[[nodiscard]] std::optional<RationalParameter> simplest_rational(ParamInterval iv, int max_den);

/// The search's companion (search.hpp): it proposes contacts at the simplest rationals near a
/// box where the search found the curves within rounding of each other, certifies them, and
/// tells the search which boxes hold nothing else. One object per intersection call.
class HighOrderContactFinder {
 public:
  /// f and g as given and in their working frame (the double precheck). The curves must
  /// outlive the finder.
  HighOrderContactFinder(const Curve& f, const Curve& g, const WorkingCurve& wf,
                         const WorkingCurve& wg) noexcept
      : f_(f), g_(g), wf_(wf), wg_(wg) {}

  /// A box where the curves may touch: one the search is about to take to double-double
  /// pieces (rounding decides its tests), or, in the subdivision method, one whose nearly
  /// parallel pieces the implicit clip could not separate. When it is narrow enough
  /// (kContactTryWidth), the simplest rationals in it widened by growing margins are tried
  /// once each (at most kContactAttempts pairs and kContactCalls boxes per intersection
  /// call): a double evaluation first, the exact certificate when the curves meet there to
  /// within kContactPrecheck with parallel tangents. Returns the work units spent, never
  /// more than `budget`.
  std::int64_t try_box(ParamInterval t, ParamInterval s, std::int64_t budget);

  /// Whether try_box would look at the box: its larger width between kContactLeastWidth and
  /// kContactTryWidth, and calls and attempts left. Inline, for the search's hot path.
  [[nodiscard]] bool worth_trying(ParamInterval t, ParamInterval s) const noexcept {
    const double w = t.width() > s.width() ? t.width() : s.width();
    return w <= intersect_tuning::kContactTryWidth && w >= intersect_tuning::kContactLeastWidth &&
           calls_ < intersect_tuning::kContactCalls &&
           tried_.size() < static_cast<std::size_t>(intersect_tuning::kContactAttempts);
  }

  /// The box lies in a certified contact's isolating box: it holds no other solution.
  [[nodiscard]] bool isolates(ParamInterval t, ParamInterval s) const noexcept {
    return !found_.empty() && isolated_by_some(t, s);
  }

  [[nodiscard]] std::span<const HighOrderContact> contacts() const noexcept { return found_; }

 private:
  [[nodiscard]] bool isolated_by_some(ParamInterval t, ParamInterval s) const noexcept;

  const Curve& f_;
  const Curve& g_;
  const WorkingCurve& wf_;
  const WorkingCurve& wg_;
  struct Tried {
    RationalParameter t, s;
  };
  std::vector<Tried> tried_;
  int calls_ = 0;
  std::vector<HighOrderContact> found_;
};

}  // namespace bezier::core
