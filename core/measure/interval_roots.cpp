#include "core/measure/interval_roots.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <utility>
#include <vector>

#include "core/bernstein/bernstein1d.hpp"
#include "core/bernstein/horner_form.hpp"
#include "core/bernstein/roots.hpp"
#include "core/measure/tuning.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {

namespace {

using measure_tuning::kHalvedDepth;
using measure_tuning::kMaxDepth;
using measure_tuning::kUnrolledSizes;

/// A piece [lo, hi] still to examine, with p at its ends (Evaluator::value there, or where
/// a split took it from the halves, a value with the sign of p there); an end flagged as a
/// known root is an exact zero of p found when the parent was split there.
struct Job {
  double lo, hi;
  double p_lo, p_hi;
  int depth;
  bool zero_lo, zero_hi;
};

using bernstein::ValueAndSlope;

/// p(t) and p'(t) from the last level of de Casteljau's triangle (p = lerp of its two
/// entries, p' = n times their difference), for E = n + 1 coefficients fixed at compile
/// time (the same value as bernstein::evaluate).
template <std::size_t E>
BEZIER_SCALAR_ROUNDS ValueAndSlope value_and_slope_of(const double* c, double t) {
  if constexpr (E == 1) {
    return {c[0], 0.0};
  } else {
    const auto last = bernstein::last_casteljau_level(std::span<const double, E>(c, E), t);
    return {bernstein::lerp(last[0], last[1], t), static_cast<double>(E - 1) * (last[1] - last[0])};
  }
}

ValueAndSlope value_and_slope_any(std::span<const double> c, double t) {
  const std::size_t n = c.size() - 1;
  SmallArray<double> row(c);
  for (std::size_t level = n; level > 1; --level) {
    for (std::size_t k = 0; k < level; ++k) row[k] = bernstein::lerp(row[k], row[k + 1], t);
  }
  return {bernstein::lerp(row[0], row[1], t), static_cast<double>(n) * (row[1] - row[0])};
}

/// The root of p in (lo, hi), where p(lo) and p(hi) have opposite signs and p has exactly
/// one root: Newton's method kept inside the bracket, which shrinks with the sign of p at
/// every iterate (a step out of it, or a zero slope, is a bisection). It stops at the first
/// iterate where |p| is within e, the rounding bound of its evaluation, after one more
/// Newton step if that stays in the bracket: closer than that the computed signs are
/// rounding, and the step from there is already within about e / |p'| of the root, which
/// is as closely as p's rounding determines it (a step that rounds onto the bracket's end
/// just set would otherwise turn the rest into bisection, about 15 steps per root). It
/// stops too when the step or the bracket is one ulp. The first test is at `start` (the
/// middle if that is not inside the bracket).
template <class ValueAndSlopeAt>
double refine(ValueAndSlopeAt p_at, double e, double lo, double hi, double p_lo, double start) {
  double t = start;
  if (!(lo < t && t < hi)) t = lo + (hi - lo) / 2;
  for (int iteration = 0; iteration < measure_tuning::kRefineIterations; ++iteration) {
    const ValueAndSlope p = p_at(t);
    if (p.value == 0.0) return t;
    if ((p.value < 0) == (p_lo < 0)) {
      lo = t;
    } else {
      hi = t;
    }
    const double middle = lo + (hi - lo) / 2;
    if (!(lo < middle && middle < hi)) return t;
    double next = t - p.value / p.slope;
    const bool inside = lo < next && next < hi;
    if (std::fabs(p.value) <= e) return inside ? next : t;
    if (!inside) next = middle;
    if (std::fabs(next - t) <= kUnitRoundoff * std::fabs(t)) return next;
    t = next;
  }
  return t;
}

/// The two halves of the piece q (on [lo, hi]) on [lo, middle] and [middle, hi], by de
/// Casteljau's subdivision at 1/2: every entry is the average of two, (x + y) / 2 with
/// exact halvings, so each rounds once and a half's coefficients are within n u max|q| of
/// the piece's own halves. q is copied before anything is written, so either half may take
/// its place.
/// The rounds in `row` (n + 1 entries, q's copy), inlined into the loop of each caller.
template <class Row>
[[gnu::always_inline]] inline void halves_of(Row& row, std::size_t n, double* left, double* right) {
  left[0] = row[0];
  right[n] = row[n];
#pragma GCC unroll 24
  for (std::size_t level = 1; level <= n; ++level) {
#pragma GCC unroll 24
    for (std::size_t k = 0; k + level <= n; ++k) row[k] = bernstein::lerp(row[k], row[k + 1], 0.5);
    left[level] = row[0];
    right[n - level] = row[n - level];
  }
}

BEZIER_SCALAR_ROUNDS void halves(std::span<const double> q, double* left, double* right) {
  SmallArray<double> row(q);
  halves_of(row, q.size() - 1, left, right);
}

/// halves() for E = n + 1 coefficients fixed at compile time: the triangle unrolled, in
/// registers.
template <std::size_t E>
BEZIER_SCALAR_ROUNDS void halves_fixed(const double* q, double* left, double* right) {
  std::array<double, E> row;
  std::copy(q, q + E, row.begin());
  halves_of(row, E - 1, left, right);
}

/// Where the control polygon of the piece q on [lo, hi] first crosses zero: with one sign
/// change among q's coefficients, near the piece's root (the crossing converges to it
/// quadratically under subdivision), the refinement's first point.
double polygon_crossing(std::span<const double> q, double lo, double hi) {
  const std::size_t n = q.size() - 1;
  for (std::size_t j = 0; j < n; ++j) {
    if ((q[j] < 0) != (q[j + 1] < 0)) {
      const double local = (static_cast<double>(j) + q[j] / (q[j] - q[j + 1])) / static_cast<double>(n);
      return lo + (hi - lo) * local;
    }
  }
  return lo + (hi - lo) / 2;
}

/// Evaluation and refinement for E = n + 1 coefficients fixed at compile time, so that
/// each Newton step's evaluation is inlined into the loop.
template <std::size_t E>
struct Unrolled {
  static ValueAndSlope at(const double* c, double t) { return value_and_slope_of<E>(c, t); }
  static void portion(const double* c, double a, double b, double* out) {
    bernstein::portion_into_fixed<E>(c, a, b, out);
  }
  static void halves(const double* q, double* left, double* right) { halves_fixed<E>(q, left, right); }
  /// The refinement evaluates p by its Horner form (O(n) a step) until |p| is within that
  /// form's own rounding bound, then takes one Newton step from de Casteljau's value and
  /// slope there (kept if it stays in the bracket): de Casteljau's rounds are exact where
  /// the Horner form's ratio t / (1 - t) is not (p(1/4) of small integer coefficients is
  /// computed exactly), so a root that is a short binary fraction comes out exactly, as
  /// from de Casteljau alone. De Casteljau's throughout where the coefficients are too
  /// large for the Horner form, and below measure_tuning::kHornerFromDegree.
  static double root(const double* c, double e, double lo, double hi, double p_lo, double start) {
    const auto exact_rounds = [c](double t) { return value_and_slope_of<E>(c, t); };
    if constexpr (E - 1 < measure_tuning::kHornerFromDegree) {
      return refine(exact_rounds, e, lo, hi, p_lo, start);
    } else {
      const bernstein::HornerForm<E> form(c);
      if (!form.prepared()) return refine(exact_rounds, e, lo, hi, p_lo, start);
      const double t = refine([&form](double u) { return form.value_and_slope(u); }, form.value_bound(),
                              lo, hi, p_lo, start);
      const ValueAndSlope p = exact_rounds(t);
      if (p.value == 0.0 || !(p.slope != 0.0)) return t;
      const double next = t - p.value / p.slope;
      return lo < next && next < hi ? next : t;
    }
  }
};

struct UnrolledFunctions {
  ValueAndSlope (*at)(const double*, double) = nullptr;
  void (*portion)(const double*, double, double, double*) = nullptr;
  void (*halves)(const double*, double*, double*) = nullptr;
  double (*root)(const double*, double, double, double, double, double) = nullptr;
};

template <std::size_t... I>
constexpr std::array<UnrolledFunctions, sizeof...(I)> unrolled(std::index_sequence<I...>) {
  return {UnrolledFunctions{&Unrolled<I + 1>::at, &Unrolled<I + 1>::portion, &Unrolled<I + 1>::halves,
                            &Unrolled<I + 1>::root}...};
}

/// p and p' at t, and the root in a bracket, for one polynomial: chooses the code for its
/// size once.
class Evaluator {
 public:
  explicit Evaluator(std::span<const double> c) : c_(c) {
    static constexpr auto kTable = unrolled(std::make_index_sequence<kUnrolledSizes>{});
    if (c.size() <= kUnrolledSizes) unrolled_ = kTable[c.size() - 1];
  }
  [[nodiscard]] double value(double t) const {
    return unrolled_.at != nullptr ? unrolled_.at(c_.data(), t).value : value_and_slope_any(c_, t).value;
  }
  /// The piece of p on [lo, hi] (bernstein::portion_into) into out[0..n].
  void portion(double lo, double hi, double* out) const {
    if (unrolled_.portion != nullptr) {
      unrolled_.portion(c_.data(), lo, hi, out);
    } else {
      bernstein::portion_into(c_, lo, hi, out);
    }
  }
  /// The halves of the piece q (see halves()).
  void halves(std::span<const double> q, double* left, double* right) const {
    if (unrolled_.halves != nullptr) {
      unrolled_.halves(q.data(), left, right);
    } else {
      bezier::core::halves(q, left, right);
    }
  }
  /// The root in (lo, hi) from `start` (see refine), e the rounding bound of p's
  /// evaluation by de Casteljau.
  [[nodiscard]] double root(double e, double lo, double hi, double p_lo, double start) const {
    if (unrolled_.root != nullptr) return unrolled_.root(c_.data(), e, lo, hi, p_lo, start);
    return refine([this](double t) { return value_and_slope_any(c_, t); }, e, lo, hi, p_lo, start);
  }

 private:
  std::span<const double> c_;
  UnrolledFunctions unrolled_;
};

/// The points found so far, in an inline store that doubles when it is full.
struct Found {
  SmallArray<double> values = SmallArray<double>(SmallArray<double>::kInline, SmallArray<double>::Uninitialized{});
  std::size_t count = 0;

  void add(double t) {
    if (count == values.size()) {
      SmallArray<double> larger(2 * count, SmallArray<double>::Uninitialized{});
      std::copy(values.begin(), values.end(), larger.begin());
      values = std::move(larger);
    }
    values[count++] = t;
  }
};

// The phases of interval_roots below are always inlined into it: inlined late, as functions
// called once, they would leave the search loop's state in memory instead of registers.

/// Where the pieces of the first kHalvedDepth levels of a search on [0, 1] come from their
/// parent's coefficients (`on`): every split point there is a dyadic rational, exactly the
/// middle of its piece, so one subdivision at 1/2 (halves(), n + 1 entries per stack slot)
/// gives both halves, cheaper than portion_into from c. Their rounding grows by at most
/// `error` = 1.01 n u max|c| a level (the pieces are convex combinations of c), so a piece
/// d levels down is within d n u max|c| of the exact one, and its sign test allows that
/// much where it exceeds e (from depth 3 on: bound()). Deeper pieces and those of other
/// intervals are portion_into's, as are all pieces of degree 3 or less (straight-line code
/// whose end coefficients are p at the ends, no evaluation needed).
struct Halving {
  bool on = false;
  double error = 0.0;

  /// Whether the pieces at `depth` are halves.
  [[nodiscard]] bool at(int depth) const noexcept { return on && depth <= kHalvedDepth; }
  /// The rounding bound of a halved piece's coefficients at `depth`.
  [[nodiscard]] double bound(double e, int depth) const noexcept {
    return std::max(e, error * depth);
  }
};

[[gnu::always_inline]] inline Halving halving_of(std::span<const double> c, double a, double b) {
  const std::size_t n = c.size() - 1;
  const bool on = a == 0.0 && b == 1.0 && n > 3;
  return {on, on ? 1.01 * static_cast<double>(n) * kUnitRoundoff * bernstein::max_abs(c) : 0.0};
}

/// The search keeps pending <= job.depth (one sibling a level), so the halved pieces need
/// kHalvedSlots slots of n + 1 coefficients, slot i for the job at stack position i.
constexpr std::size_t kHalvedSlots = kHalvedDepth + 2;

struct HalvedSlots {
  double* base;
  std::size_t size;  ///< n + 1
  [[nodiscard]] double* slot(std::size_t i) const noexcept { return base + i * size; }
};

/// The pieces still to examine, depth first: at most one pending sibling per depth below
/// the piece split last.
using JobStack = std::array<Job, kMaxDepth + 2>;

/// Splits `job` (its piece q, neither discarded nor resolved, less than kMaxDepth levels
/// deep, its middle strictly inside) at its middle: pushes the right half, then the left
/// (examined first), each with p at its ends and the middle flagged when p is exactly zero
/// there, which is then a root in `found`. A halved piece's children come from q by
/// halves() (the right half into q's own slot: halves reads q before it writes); their
/// shared coefficient at the middle is within their bound of p there, so beyond that bound
/// plus e, p and its evaluation have its sign and neither is zero, and the sign is all that
/// the tests and the refinement take from a piece's end (beside the first point of the
/// refinement, which may be anywhere in the bracket). Else p at the middle is evaluated.
[[gnu::always_inline]] inline void split(const Job& job, double middle, std::span<const double> q,
                                         const Evaluator& p_at, double e, Halving halving,
                                         HalvedSlots halved, JobStack& stack, std::size_t& pending,
                                         Found& found) {
  assert(pending + 2 <= stack.size());
  double p_middle = 0.0;
  bool known_middle = false;
  if (halving.at(job.depth + 1)) {
    assert(pending + 1 < kHalvedSlots);
    p_at.halves(q, halved.slot(pending + 1), halved.slot(pending));
    const double shared = halved.slot(pending)[0];
    known_middle = std::fabs(shared) > halving.bound(e, job.depth + 1) + e;
    if (known_middle) p_middle = shared;
  }
  if (!known_middle) p_middle = p_at.value(middle);
  const bool zero_middle = p_middle == 0.0;
  if (zero_middle) found.add(middle);
  const int depth = job.depth + 1;
  stack[pending++] = {middle, job.hi, p_middle, job.p_hi, depth, zero_middle, job.zero_hi};
  stack[pending++] = {job.lo, middle, job.p_lo, p_middle, depth, job.zero_lo, zero_middle};
}

/// The isolation (see the header): subdivides `whole` (the piece [a, b] with p at its
/// ends), examining each piece's Bernstein coefficients (computed within e, or within
/// halving.bound for halved pieces) by Descartes' rule; adds to `found` the root refined in
/// each one-root piece (only the rising ones when `wanted` says so), the middle of each
/// piece zero to within rounding throughout and of each cluster still unresolved at
/// kMaxDepth or at one ulp (when a root may be on it), and every exact zero of p at a split
/// point. `isolated` becomes false when a piece zero to within rounding or an unresolved
/// cluster is met.
[[gnu::always_inline]] inline void isolate(std::span<const double> c, const Evaluator& p_at,
                                           double e, const Job& whole, Crossings wanted,
                                           Found& found, bool& isolated) {
  const std::size_t n = c.size() - 1;
  JobStack stack;
  std::size_t pending = 0;
  stack[pending++] = whole;
  Coeffs piece(n + 1, Coeffs::Uninitialized{});
  const Halving halving = halving_of(c, whole.lo, whole.hi);
  std::array<double, kHalvedSlots * kUnrolledSizes> slots_inline;
  std::vector<double> slots_beyond;
  if (halving.on && n + 1 > kUnrolledSizes) slots_beyond.resize(kHalvedSlots * (n + 1));
  const HalvedSlots halved{n + 1 > kUnrolledSizes ? slots_beyond.data() : slots_inline.data(),
                           n + 1};
  while (pending > 0) {
    const Job job = stack[--pending];
    // On [0, 1] the piece is c itself (de Casteljau steps at 0 and 1 are exact).
    const bool is_whole = job.lo == 0.0 && job.hi == 1.0;
    const bool is_halved = !is_whole && halving.at(job.depth);
    if (!is_whole && !is_halved) p_at.portion(job.lo, job.hi, piece.data());
    const std::span<const double> q = is_whole ? c
                                      : is_halved
                                          ? std::span<const double>(halved.slot(pending), n + 1)
                                          : std::span<const double>(piece);
    // Descartes' rule on the coefficients that are clearly nonzero; an end that is an exact
    // zero is left out (p = (t - end) r(t), and r's coefficients have the others' signs).
    const std::size_t first = job.zero_lo ? 1 : 0, end = job.zero_hi ? n : n + 1;
    const double bound = is_halved ? halving.bound(e, job.depth) : e;
    const auto [changes, any_small, all_small] =
        sign_changes(q.subspan(first, end > first ? end - first : 0), bound);
    const double middle = job.lo + (job.hi - job.lo) / 2;
    if (all_small) {
      // Zero to within rounding on the whole piece.
      isolated = false;
      found.add(middle);
      continue;
    }
    if (changes == 0 && !any_small) continue;
    // A piece's end coefficients from portion_into are p at its ends: the same de
    // Casteljau rounds (and exact on [0, 1]); halves' are only near them, so a halved
    // piece takes the values found where its ends were split.
    const double p_lo = is_halved ? job.p_lo : q[0];
    const double p_hi = is_halved ? job.p_hi : q[n];
    if (changes == 1 && !any_small && p_lo != 0.0 && p_hi != 0.0 && (p_lo < 0) != (p_hi < 0)) {
      if (wanted == Crossings::any || p_lo < 0) {
        found.add(p_at.root(e, job.lo, job.hi, p_lo, polygon_crossing(q, job.lo, job.hi)));
      }
      continue;
    }
    if (job.depth >= kMaxDepth || !(job.lo < middle && middle < job.hi)) {
      // A root on the piece, possibly at an end where p rounds to a tiny nonzero value
      // (then neither piece of the split shows a clear sign change, but p's signs differ).
      const bool signs_differ = p_lo != 0.0 && p_hi != 0.0 && (p_lo < 0) != (p_hi < 0);
      if (changes > 0 || signs_differ || std::fabs(p_at.value(middle)) <= e) {
        isolated = false;
        found.add(middle);
      }
      continue;
    }
    split(job, middle, q, p_at, e, halving, halved, stack, pending, found);
  }
}

/// The points found, sorted, those inside [a, b] (or (a, b)) kept, each flat stretch one
/// root (see the header): each point is compared with the point before it, kept or not, so
/// that a stretch is one root however far apart its ends are, and is represented by its
/// point with the smallest computed |p|. `isolated` becomes false when a stretch holds two
/// points.
[[gnu::always_inline]] inline SmallArray<double> merge_flat_stretches(Found& found, double a,
                                                                      double b, IntervalEnds ends,
                                                                      const Evaluator& p_at,
                                                                      double e, bool& isolated) {
  double* const roots = found.values.data();
  std::sort(roots, roots + found.count);
  std::size_t kept = 0;
  double last = 0.0;         // the point before r, kept or not
  double kept_value = -1.0;  // |p| at the last point kept, once needed (-1 before)
  for (std::size_t i = 0; i < found.count; ++i) {
    const double r = roots[i];
    const bool inside = ends == IntervalEnds::closed ? (a <= r && r <= b) : (a < r && r < b);
    if (!inside) continue;
    if (kept > 0) {
      if (r == last) continue;
      if (std::fabs(p_at.value(last + (r - last) / 2)) <= 3 * e) {
        // One flat stretch of p (a multiple root, a cluster): keep its best representative.
        if (kept_value < 0) kept_value = std::fabs(p_at.value(roots[kept - 1]));
        const double value = std::fabs(p_at.value(r));
        if (value < kept_value) {
          roots[kept - 1] = r;
          kept_value = value;
        }
        isolated = false;
        last = r;
        continue;
      }
    }
    roots[kept++] = r;
    kept_value = -1.0;
    last = r;
  }
  return SmallArray<double>(std::span<const double>(roots, kept));
}

}  // namespace

IntervalRoots interval_roots(std::span<const double> c, double a, double b, IntervalEnds ends,
                             Crossings wanted) {
  assert(!c.empty() && 0.0 <= a && a <= b && b <= 1.0);
  const std::size_t n = c.size() - 1;
  // The rounding bound of a coefficient of a piece (bernstein::portion_into: 3.01 n u max|c|),
  // and of p at a point (de Casteljau: the same n steps).
  const double e = 3.02 * static_cast<double>(std::max<std::size_t>(n, 1)) * kUnitRoundoff *
                   bernstein::max_abs(c);
  IntervalRoots out;
  // Roots and root-like points as found, sorted and merged in place at the end.
  Found found;
  const Evaluator p_at(c);
  // De Casteljau's rounds at 0 and 1 are exact: p there is the end coefficient.
  const double p_a = a == 0.0 ? c.front() : p_at.value(a);
  const double p_b = b == 1.0 ? c.back() : p_at.value(b);
  if (p_a == 0.0) found.add(a);
  if (p_b == 0.0) found.add(b);
  if (a < b)
    isolate(c, p_at, e, {a, b, p_a, p_b, 0, p_a == 0.0, p_b == 0.0}, wanted, found, out.isolated);
  out.roots = merge_flat_stretches(found, a, b, ends, p_at, e, out.isolated);
  return out;
}

}  // namespace bezier::core
