#include "core/bernstein/roots.hpp"

#include <algorithm>
#include <cmath>

#include "core/bernstein/bernstein1d.hpp"
#include "core/bernstein/tuning.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {

using namespace bernstein_tuning;

namespace {

/// An interval still to examine; an end flagged as a zero is an exact zero of p found where
/// the parent was split (or at 0 or 1).
struct Job {
  double a, b;
  int depth;
  bool zero_a, zero_b;
};

/// A root of p in (a, b), where p(a) and p(b) have opposite signs: bisection on the sign of
/// p evaluated from the original coefficients, until the bracket is one ulp wide.
double bisect(std::span<const double> c, double a, double b, double pa) {
  for (int i = 0; i < kBisectionSteps; ++i) {
    const double m = a + (b - a) / 2;
    if (!(a < m && m < b)) break;
    const double pm = bernstein::evaluate(c, m);
    if (pm == 0.0) return m;
    if ((pm < 0) == (pa < 0)) {
      a = m;
      pa = pm;
    } else {
      b = m;
    }
  }
  return a + (b - a) / 2;
}

}  // namespace

BernsteinRoots bernstein_roots(std::span<const double> c, int max_depth) {
  BernsteinRoots out;
  const int n = static_cast<int>(c.size()) - 1;
  if (n < 0) return out;
  const double e = 3.02 * std::max(n, 1) * kUnitRoundoff * bernstein::max_abs(c);
  const bool zero_0 = c.front() == 0.0, zero_1 = c.back() == 0.0;
  if (zero_0) out.roots.push_back(0.0);
  if (zero_1) out.roots.push_back(1.0);
  std::vector<Job> stack = {{0.0, 1.0, 0, zero_0, zero_1}};
  while (!stack.empty()) {
    const Job job = stack.back();
    stack.pop_back();
    ++out.intervals;
    const Coeffs q = bernstein::portion<double>(c, job.a, job.b);
    // An end that is an exact zero is left out of the count: p = (t - end) r(t) there, and
    // r's coefficients on the interval have the other coefficients' signs.
    const std::size_t first = job.zero_a ? 1 : 0, end = job.zero_b ? q.size() - 1 : q.size();
    const auto [changes, any_small, all_small] =
        sign_changes(std::span<const double>(q).subspan(first, end > first ? end - first : 0), e);
    if (all_small) {
      // Zero to within rounding on the whole interval.
      out.isolated = false;
      out.roots.push_back(job.a + (job.b - job.a) / 2);
      continue;
    }
    if (changes == 0 && !any_small) continue;
    const double pa = bernstein::evaluate(c, job.a), pb = bernstein::evaluate(c, job.b);
    if (changes == 1 && !any_small && pa != 0.0 && pb != 0.0 && (pa < 0) != (pb < 0)) {
      out.roots.push_back(bisect(c, job.a, job.b, pa));
      continue;
    }
    const double m = job.a + (job.b - job.a) / 2;
    if (job.depth >= max_depth || !(job.a < m && m < job.b)) {
      const bool signs_differ = pa != 0.0 && pb != 0.0 && (pa < 0) != (pb < 0);
      if (changes > 0 || signs_differ || std::fabs(bernstein::evaluate(c, m)) <= e) {
        out.isolated = false;
        out.roots.push_back(m);
      }
      continue;
    }
    const bool zero_m = bernstein::evaluate(c, m) == 0.0;
    if (zero_m) out.roots.push_back(m);
    stack.push_back({m, job.b, job.depth + 1, zero_m, job.zero_b});
    stack.push_back({job.a, m, job.depth + 1, job.zero_a, zero_m});
  }
  // Roots reported at the depth limit (a root on a split point, a cluster) are polished by
  // Newton's method, kept only while |p| decreases and the step stays tiny.
  std::vector<double> derivative(static_cast<std::size_t>(std::max(n, 1)), 0.0);
  for (int i = 0; i < n; ++i)
    derivative[static_cast<std::size_t>(i)] =
        n * (c[static_cast<std::size_t>(i) + 1] - c[static_cast<std::size_t>(i)]);
  for (double& r : out.roots) {
    if (n == 0) break;
    for (int i = 0; i < kPolishSteps; ++i) {
      const double v = bernstein::evaluate(c, r), d = bernstein::evaluate(derivative, r);
      if (v == 0.0 || !(d != 0.0)) break;
      const double next = r - v / d;
      if (!(next >= 0.0 && next <= 1.0) || std::fabs(next - r) > kPolishLargestStep ||
          !(std::fabs(bernstein::evaluate(c, next)) < std::fabs(v))) {
        break;
      }
      r = next;
    }
  }
  std::sort(out.roots.begin(), out.roots.end());
  // Where p stays within e of zero (a multiple root, a cluster, a root where p rounds to a
  // tiny nonzero value at a split point) several points a little apart may have been
  // reported, each with a computed |p| <= e, so a true |p| <= 2e. Near a multiple root |p|
  // is no larger between two such points, so its computed value at their midpoint is at most
  // 3e: consecutive points with that are one flat stretch, as are points closer than
  // kSameRoot. A stretch is one root, the point where |p| is smallest (an exact zero wins).
  std::vector<double> unique;
  double last = 0.0;  // the point before r, whether kept or not
  for (const double r : out.roots) {
    if (!unique.empty()) {
      const bool flat = std::fabs(bernstein::evaluate(c, last + (r - last) / 2)) <= 3 * e;
      if (flat || r - last <= kSameRoot) {
        if (std::fabs(bernstein::evaluate(c, r)) < std::fabs(bernstein::evaluate(c, unique.back())))
          unique.back() = r;
        if (flat && r != last) out.isolated = false;
        last = r;
        continue;
      }
    }
    unique.push_back(r);
    last = r;
  }
  out.roots = std::move(unique);
  return out;
}

}  // namespace bezier::core
