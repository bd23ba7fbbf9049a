#include "core/measure/interval_roots.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/bernstein/bernstein1d.hpp"

namespace bezier::core {

namespace {

constexpr double kU = bernstein::kU;
constexpr int kMaxDepth = 40;

/// A piece [lo, hi] still to examine; an end flagged as a known root is an exact zero of p
/// found when the parent was split there.
struct Job {
  double lo, hi;
  int depth;
  bool zero_lo, zero_hi;
};

struct ValueAndSlope {
  double value, slope;
};

/// p(t) and p'(t) from the last level of de Casteljau's triangle (p = lerp of its two
/// entries, p' = n times their difference).
ValueAndSlope value_and_slope(std::span<const double> c, double t) {
  const std::size_t n = c.size() - 1;
  if (n == 0) return {c[0], 0.0};
  SmallArray<double> row(c);
  for (std::size_t level = n; level > 1; --level) {
    for (std::size_t k = 0; k < level; ++k) row[k] = bernstein::lerp(row[k], row[k + 1], t);
  }
  return {bernstein::lerp(row[0], row[1], t), static_cast<double>(n) * (row[1] - row[0])};
}

/// The root of p in (lo, hi), where p(lo) and p(hi) have opposite signs and p has exactly
/// one root: Newton's method kept inside the bracket, which shrinks with the sign of p at
/// every iterate (a step out of it, or a zero slope, is a bisection), until the step or the
/// bracket is one ulp. The sign test decides as bisection would; Newton only chooses where
/// to test, so a simple root is reached in a few steps instead of 55.
double refine(std::span<const double> c, double lo, double hi, double p_lo) {
  double t = lo + (hi - lo) / 2;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const ValueAndSlope p = value_and_slope(c, t);
    if (p.value == 0.0) return t;
    if ((p.value < 0) == (p_lo < 0)) {
      lo = t;
    } else {
      hi = t;
    }
    const double middle = lo + (hi - lo) / 2;
    if (!(lo < middle && middle < hi)) return t;
    double next = t - p.value / p.slope;
    if (!(lo < next && next < hi)) next = middle;
    if (std::fabs(next - t) <= kU * std::fabs(t)) return next;
    t = next;
  }
  return t;
}

}  // namespace

IntervalRoots interval_roots(std::span<const double> c, double a, double b, IntervalEnds ends) {
  assert(!c.empty() && 0.0 <= a && a <= b && b <= 1.0);
  const std::size_t n = c.size() - 1;
  // The rounding bound of a coefficient of a piece (bernstein::portion_into: 3.01 n u max|c|).
  const double e = 3.02 * static_cast<double>(std::max<std::size_t>(n, 1)) * kU * bernstein::max_abs(c);
  IntervalRoots out;
  std::vector<double> found;
  const double p_a = bernstein::evaluate(c, a), p_b = bernstein::evaluate(c, b);
  if (p_a == 0.0) found.push_back(a);
  if (p_b == 0.0) found.push_back(b);
  std::vector<Job> stack;
  if (a < b) stack.push_back({a, b, 0, p_a == 0.0, p_b == 0.0});
  while (!stack.empty()) {
    const Job job = stack.back();
    stack.pop_back();
    const Coeffs q = bernstein::portion<double>(c, job.lo, job.hi);
    // Descartes' rule on the coefficients that are clearly nonzero; an end that is an exact
    // zero is left out (p = (t - end) r(t), and r's coefficients have the others' signs).
    const std::size_t first = job.zero_lo ? 1 : 0, last_index = job.zero_hi ? n - 1 : n;
    int changes = 0, last = 0;
    bool any_small = false;
    for (std::size_t i = first; i <= last_index && i <= n; ++i) {
      const double v = q[i];
      if (std::fabs(v) <= e) {
        any_small = true;
        continue;
      }
      const int sign = v > 0 ? 1 : -1;
      if (last != 0 && sign != last) ++changes;
      last = sign;
    }
    const double middle = job.lo + (job.hi - job.lo) / 2;
    if (last == 0) {
      // Zero to within rounding on the whole piece.
      out.isolated = false;
      found.push_back(middle);
      continue;
    }
    if (changes == 0 && !any_small) continue;
    const double p_lo = bernstein::evaluate(c, job.lo), p_hi = bernstein::evaluate(c, job.hi);
    if (changes == 1 && !any_small && p_lo != 0.0 && p_hi != 0.0 && (p_lo < 0) != (p_hi < 0)) {
      found.push_back(refine(c, job.lo, job.hi, p_lo));
      continue;
    }
    if (job.depth >= kMaxDepth || !(job.lo < middle && middle < job.hi)) {
      // A root on the piece, possibly at an end where p rounds to a tiny nonzero value
      // (then neither piece of the split shows a clear sign change, but p's signs differ).
      const bool signs_differ = p_lo != 0.0 && p_hi != 0.0 && (p_lo < 0) != (p_hi < 0);
      if (changes > 0 || signs_differ || std::fabs(bernstein::evaluate(c, middle)) <= e) {
        out.isolated = false;
        found.push_back(middle);
      }
      continue;
    }
    const bool zero_middle = bernstein::evaluate(c, middle) == 0.0;
    if (zero_middle) found.push_back(middle);
    stack.push_back({middle, job.hi, job.depth + 1, zero_middle, job.zero_hi});
    stack.push_back({job.lo, middle, job.depth + 1, job.zero_lo, zero_middle});
  }
  std::sort(found.begin(), found.end());
  for (const double r : found) {
    const bool inside = ends == IntervalEnds::closed ? (a <= r && r <= b) : (a < r && r < b);
    if (!inside) continue;
    if (!out.roots.empty()) {
      const double previous = out.roots.back();
      if (r == previous) continue;
      if (std::fabs(bernstein::evaluate(c, previous + (r - previous) / 2)) <= e) {
        // One flat stretch of p (a multiple root, a cluster): keep its best representative.
        if (std::fabs(bernstein::evaluate(c, r)) < std::fabs(bernstein::evaluate(c, previous)))
          out.roots.back() = r;
        out.isolated = false;
        continue;
      }
    }
    out.roots.push_back(r);
  }
  return out;
}

}  // namespace bezier::core
