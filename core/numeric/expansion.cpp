#include "core/numeric/expansion.hpp"

#include <cmath>
#include <cstddef>

#include "core/numeric/error_free.hpp"

namespace bezier::core {

Expansion Expansion::difference(double a, double b) {
  const TwoTerm<double> d = two_sum(a, -b);
  Expansion out;
  if (d.lo != 0.0) out.components_.push_back(d.lo);
  if (d.hi != 0.0) out.components_.push_back(d.hi);
  return out;
}

int Expansion::sign() const noexcept {
  if (components_.empty()) return 0;
  return components_.back() > 0.0 ? 1 : -1;
}

double Expansion::estimate() const noexcept {
  double sum = 0.0;
  for (const double c : components_) sum += c;
  return sum;
}

Expansion operator-(Expansion e) {
  for (double& c : e.components_) c = -c;
  return e;
}

// Shewchuk's algorithms call Fast-Two-Sum where their proofs show the ordering
// |a| >= |b|; two_sum gives the same pair there and stays exact everywhere, so it is used
// throughout: exactness of every step never rests on a precondition.

// Shewchuk's Fast-Expansion-Sum-Zeroelim (Theorem 13): merge the components of e and f by
// increasing magnitude, then carry a running sum Q through them with TwoSum, emitting each
// nonzero rounding error. Written as an explicit merge, so nothing reads past an end.
Expansion operator+(const Expansion& e, const Expansion& f) {
  if (e.components_.empty()) return f;
  if (f.components_.empty()) return e;
  std::vector<double> merged;
  merged.reserve(e.components_.size() + f.components_.size());
  std::size_t i = 0, j = 0;
  while (i < e.components_.size() && j < f.components_.size()) {
    if (std::fabs(e.components_[i]) <= std::fabs(f.components_[j])) {
      merged.push_back(e.components_[i++]);
    } else {
      merged.push_back(f.components_[j++]);
    }
  }
  while (i < e.components_.size()) merged.push_back(e.components_[i++]);
  while (j < f.components_.size()) merged.push_back(f.components_[j++]);

  Expansion h;
  h.components_.reserve(merged.size());
  double q = merged[0];
  for (std::size_t k = 1; k < merged.size(); ++k) {
    const TwoTerm<double> s = two_sum(q, merged[k]);
    if (s.lo != 0.0) h.components_.push_back(s.lo);
    q = s.hi;
  }
  if (q != 0.0) h.components_.push_back(q);
  h.compress();
  return h;
}

Expansion operator-(const Expansion& e, const Expansion& f) {
  return e + (-f);
}

// Shewchuk's Scale-Expansion-Zeroelim (Theorem 19), with the fused multiply-add TwoProduct.
Expansion operator*(const Expansion& e, double b) {
  Expansion h;
  if (e.components_.empty() || b == 0.0) return h;
  h.components_.reserve(2 * e.components_.size());
  TwoTerm<double> p = two_product(e.components_[0], b);
  if (p.lo != 0.0) h.components_.push_back(p.lo);
  double q = p.hi;
  for (std::size_t i = 1; i < e.components_.size(); ++i) {
    p = two_product(e.components_[i], b);
    const TwoTerm<double> sum = two_sum(q, p.lo);
    if (sum.lo != 0.0) h.components_.push_back(sum.lo);
    const TwoTerm<double> carry = two_sum(p.hi, sum.hi);
    if (carry.lo != 0.0) h.components_.push_back(carry.lo);
    q = carry.hi;
  }
  if (q != 0.0) h.components_.push_back(q);
  h.compress();
  return h;
}

Expansion operator*(const Expansion& e, const Expansion& f) {
  Expansion product;
  for (const double fj : f.components_) product = product + e * fj;
  return product;
}

// Shewchuk's Compress (§2.8): a downward pass accumulates from the top, keeping each
// nonzero remainder; an upward pass renormalises. The result is nonoverlapping, and its
// largest component is within one ulp of the value.
void Expansion::compress() {
  std::vector<double>& e = components_;
  const std::size_t n = e.size();
  if (n < 2) return;
  std::vector<double> h(n);
  std::size_t bottom = n - 1;
  double q = e[n - 1];
  for (std::size_t k = n - 1; k-- > 0;) {
    const TwoTerm<double> s = two_sum(q, e[k]);
    if (s.lo != 0.0) {
      h[bottom--] = s.hi;
      q = s.lo;
    } else {
      q = s.hi;
    }
  }
  std::size_t top = 0;
  for (std::size_t k = bottom + 1; k < n; ++k) {
    const TwoTerm<double> s = two_sum(h[k], q);
    if (s.lo != 0.0) h[top++] = s.lo;
    q = s.hi;
  }
  h[top++] = q;
  h.resize(top);
  // Compress can leave a single zero only when the value is zero.
  if (top == 1 && h[0] == 0.0) h.clear();
  e = std::move(h);
}

}  // namespace bezier::core
