#include "core/intersect/high_order_contact.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/bernstein/exact_casteljau.hpp"
#include "core/intersect/kind.hpp"
#include "core/intersect/tuning.hpp"
#include "core/intersect/work_cost.hpp"
#include "core/numeric/binomial.hpp"
#include "core/numeric/expansion.hpp"
#include "core/numeric/outward.hpp"
#include "core/numeric/power_of_two.hpp"

namespace bezier::core {

namespace {

using namespace intersect_tuning;

/// The exponent of x's least significant set bit (x finite, nonzero).
int lsb_exponent(double x) noexcept {
  int e = 0;
  const double m = std::frexp(std::fabs(x), &e);  // x = m 2^e, m in [0.5, 1)
  const auto bits = static_cast<std::uint64_t>(std::ldexp(m, 53));
  return e - 53 + std::countr_zero(bits);
}

/// The least lsb exponent and the greatest exponent of an expansion's components.
struct ExponentRange {
  int lsb = 0;
  int top = 0;
};

ExponentRange exponent_range(const Expansion& e) noexcept {
  ExponentRange r{1 << 20, -(1 << 20)};
  for (const double c : e.components()) {
    r.lsb = std::min(r.lsb, lsb_exponent(c));
    r.top = std::max(r.top, exponent_of(c) + 1);
  }
  return r;
}

/// Exact products of expansions within their contract (expansion.hpp): a product is taken
/// only when its operands' least significant bits keep its rounding errors above the
/// subnormal range and its size below 2^1000 (so no later sum overflows); otherwise, or when
/// `max_products` are spent, the arithmetic fails and the certificate with it.
class ExactArithmetic {
 public:
  explicit ExactArithmetic(std::int64_t max_products) noexcept : left_(max_products) {}

  Expansion mul(const Expansion& a, const Expansion& b) {
    if (!ok_ || a.sign() == 0 || b.sign() == 0) return {};
    if (left_ <= 0) {
      ok_ = false;
      return {};
    }
    --left_;
    ++used_;
    const ExponentRange ra = exponent_range(a), rb = exponent_range(b);
    if (ra.lsb + rb.lsb < -1000 || ra.top + rb.top > 1000) {
      ok_ = false;
      return {};
    }
    return a * b;
  }
  Expansion mul(const Expansion& a, double b) { return mul(a, Expansion(b)); }

  [[nodiscard]] bool ok() const noexcept { return ok_; }
  [[nodiscard]] std::int64_t used() const noexcept { return used_; }

 private:
  std::int64_t left_;
  std::int64_t used_ = 0;
  bool ok_ = true;
};

using Poly = std::vector<Expansion>;  // power-basis coefficients, lowest first

/// P(x) = scale * b^n c((a + x)/b) for the curve c (coordinates axis by axis, translated by
/// `origin` and multiplied by 2^shift): the power form sum_i alpha_i t^i with
/// alpha_i = C(n,i) sum_{j<=i} (-1)^(i-j) C(i,j) P_j, then
/// P_j = scale * sum_{i>=j} alpha_i C(i,j) a^(i-j) b^(n-i).
std::array<Poly, 2> shifted_power_form(const Curve& c, Point2 origin, double shift_scale,
                                       RationalParameter p, const Expansion& scale,
                                       ExactArithmetic& ar) {
  const int n = c.degree();
  std::array<Poly, 2> out;
  std::array<Poly, 2> alpha;
  for (int axis = 0; axis < 2; ++axis) {
    Poly pts;
    for (const Point2 q : c.points()) {
      const Expansion d = axis == 0 ? Expansion::difference(q.x, origin.x)
                                    : Expansion::difference(q.y, origin.y);
      pts.push_back(ar.mul(d, shift_scale));
    }
    for (int i = 0; i <= n; ++i) {
      Expansion sum;
      for (int j = 0; j <= i; ++j) {
        const double w = ((i - j) % 2 == 0 ? 1.0 : -1.0) * binomial(i, j);
        sum = sum + ar.mul(pts[static_cast<std::size_t>(j)], w);
      }
      alpha[axis].push_back(ar.mul(sum, binomial(n, i)));
    }
  }
  Poly pow_a{Expansion(1.0)}, pow_b{Expansion(1.0)};
  for (int i = 1; i <= n; ++i) {
    pow_a.push_back(ar.mul(pow_a.back(), p.num));
    pow_b.push_back(ar.mul(pow_b.back(), p.den));
  }
  for (int axis = 0; axis < 2; ++axis) {
    for (int j = 0; j <= n; ++j) {
      Expansion sum;
      for (int i = j; i <= n; ++i) {
        const auto ui = static_cast<std::size_t>(i);
        const Expansion ab = ar.mul(pow_a[static_cast<std::size_t>(i - j)], pow_b[static_cast<std::size_t>(n - i)]);
        sum = sum + ar.mul(ar.mul(alpha[axis][ui], binomial(i, j)), ab);
      }
      out[axis].push_back(ar.mul(sum, scale));
    }
  }
  return out;
}

const Expansion& coeff(const Poly& p, int j) {
  static const Expansion zero;
  return j >= 0 && static_cast<std::size_t>(j) < p.size() ? p[static_cast<std::size_t>(j)] : zero;
}

/// An upper bound on |e|.
double abs_upper(const Expansion& e) {
  return std::max(std::fabs(rounded_down(e)), std::fabs(rounded_up(e)));
}

/// A lower bound on |e|.
double abs_lower(const Expansion& e) {
  return e.sign() >= 0 ? rounded_down(e) : -rounded_up(e);
}

/// Products of polynomials with exact coefficients.
Poly multiply(const Poly& p, const Poly& q, ExactArithmetic& ar) {
  if (p.empty() || q.empty()) return {};
  Poly r(p.size() + q.size() - 1);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < q.size(); ++j) r[i + j] = r[i + j] + ar.mul(p[i], q[j]);
  return r;
}

/// The two-sided enclosure of a / b by doubles.
ParamInterval enclosure(RationalParameter p) {
  const double q = p.num / p.den;  // correctly rounded
  if (std::fma(q, p.den, -p.num) == 0.0) return {q, q};
  return {next_down(q), next_up(q)};
}

/// Step 1 of the certificate (see the header): the polynomial maps P (of f) and Q (of g)
/// in power form, lowest coefficient first, per axis, and the axis e of Q'(0)'s component
/// of larger magnitude, c = Q[e][1].
struct ContactMaps {
  std::array<Poly, 2> P, Q;
  int e = 0;
};

/// P(x) = b'^m b^n f((a + x)/b) and Q(y) = b^n b'^m g((a' + y)/b') exactly, with the curves
/// translated to f's first point and scaled by a power of two to magnitudes about 1 (the
/// exact products then stay far inside the exponent window), and both sides scaled by one
/// power of two that centres c on 1, its least significant bit as far below as its leading
/// bit is above: E's coefficient of z^j carries c^(2j), whose bits (2j times c's) must fit
/// inside the exponent window up to j = m k. nullopt when the curves are one point, c is
/// zero (then `g_stationary` is set: g' vanishes at s), the arithmetic fails, or P(0) != Q(0)
/// (the curves do not meet there).
std::optional<ContactMaps> contact_maps(const Curve& f, const Curve& g, RationalParameter t,
                                        RationalParameter s, ExactArithmetic& ar,
                                        bool& g_stationary) {
  const int n = f.degree(), m = g.degree();
  const Point2 origin = f.front();
  double extent = 0.0;
  for (const Curve* c : {&f, &g})
    for (const Point2 q : c->points())
      extent = std::max({extent, std::fabs(q.x - origin.x), std::fabs(q.y - origin.y)});
  if (!(extent > 0.0) || !std::isfinite(extent)) return std::nullopt;
  const double shift_scale = power_of_two(-exponent_of(extent));

  Expansion bn(1.0), bm(1.0);  // b^n, b'^m
  for (int i = 0; i < n; ++i) bn = ar.mul(bn, t.den);
  for (int i = 0; i < m; ++i) bm = ar.mul(bm, s.den);
  ContactMaps maps;
  maps.P = shifted_power_form(f, origin, shift_scale, t, bm, ar);
  maps.Q = shifted_power_form(g, origin, shift_scale, s, bn, ar);
  if (!ar.ok()) return std::nullopt;
  std::array<Poly, 2>& Q = maps.Q;
  maps.e = std::fabs(Q[0][1].estimate()) >= std::fabs(Q[1][1].estimate()) ? 0 : 1;
  if (Q[maps.e][1].sign() == 0) {
    g_stationary = true;
    return std::nullopt;
  }
  const ExponentRange c_bits = exponent_range(Q[maps.e][1]);
  const double c_scale = power_of_two(-(c_bits.lsb + c_bits.top) / 2);
  for (std::array<Poly, 2>* side : {&maps.P, &maps.Q})
    for (Poly& axis : *side)
      for (Expansion& coefficient : axis) coefficient = ar.mul(coefficient, c_scale);
  if (!ar.ok()) return std::nullopt;
  for (int axis = 0; axis < 2; ++axis)
    if ((maps.P[axis][0] - maps.Q[axis][0]).sign() != 0) return std::nullopt;
  return maps;
}

/// c^i, each power taken once (in the order first asked for) and kept.
class PowersOf {
 public:
  PowersOf(Expansion c, ExactArithmetic& ar) : c_(std::move(c)), ar_(ar) {}
  const Expansion& operator()(int i) {
    while (powers_.size() <= static_cast<std::size_t>(i))
      powers_.push_back(ar_.mul(powers_.back(), c_));
    return powers_[static_cast<std::size_t>(i)];
  }

 private:
  Expansion c_;
  ExactArithmetic& ar_;
  Poly powers_{Expansion(1.0)};
};

/// Step 2's reparametrisation: Phi_1, ..., Phi_k (phi[0] = 0; phi has max_order + 1
/// entries) and the order k.
struct Reparametrisation {
  Poly phi;
  int order = 0;  ///< 0: none up to max_order (a common component), or the arithmetic failed
};

/// Builds Psi term by term so that the e-component of E(z) = P(c^2 z) - Q(c Psi(z))
/// vanishes to order j + 1, up to the first order j <= max_order at which the other
/// component's coefficient of z^j does not vanish: that j is k (m = g's degree).
Reparametrisation reparametrisation(const ContactMaps& maps, int m, int max_order,
                                    PowersOf& c_power, ExactArithmetic& ar) {
  const std::array<Poly, 2>&P = maps.P, &Q = maps.Q;
  const int e = maps.e;
  const int o = 1 - e;
  // pw[r][j]: the coefficient of z^j in Psi^r (r = 1..m), from the Phi_i found so far.
  std::vector<Poly> pw(static_cast<std::size_t>(m) + 1,
                       Poly(static_cast<std::size_t>(max_order) + 1));
  Reparametrisation out{Poly(static_cast<std::size_t>(max_order) + 1), 0};
  Poly& phi = out.phi;
  for (int j = 1; j <= max_order && out.order == 0; ++j) {
    const auto uj = static_cast<std::size_t>(j);
    for (int r = 2; r <= std::min(j, m); ++r) {
      Expansion sum;
      for (int i = 1; i <= j - r + 1; ++i)
        sum = sum + ar.mul(phi[static_cast<std::size_t>(i)],
                           pw[static_cast<std::size_t>(r - 1)][static_cast<std::size_t>(j - i)]);
      pw[static_cast<std::size_t>(r)][uj] = sum;
    }
    Expansion phi_j = ar.mul(coeff(P[e], j), c_power(2 * j - 2));
    for (int r = 2; r <= std::min(j, m); ++r)
      phi_j = phi_j - ar.mul(ar.mul(Q[e][static_cast<std::size_t>(r)], c_power(r - 2)),
                             pw[static_cast<std::size_t>(r)][uj]);
    phi[uj] = phi_j;
    pw[1][uj] = phi_j;
    Expansion e_o = ar.mul(coeff(P[o], j), c_power(2 * j));
    for (int r = 1; r <= std::min(j, m); ++r)
      e_o = e_o - ar.mul(ar.mul(Q[o][static_cast<std::size_t>(r)], c_power(r)),
                         pw[static_cast<std::size_t>(r)][uj]);
    if (!ar.ok()) {
      out.order = 0;
      return out;
    }
    if (e_o.sign() != 0) out.order = j;
  }
  return out;
}

/// E(z) = P(c^2 z) - Q(c Psi(z)) whole, per axis (coefficients of z^0..z^max(n, m k)), with
/// Psi cut at degree k, and the construction checked: z^k divides E, and E_k lies along
/// the other axis, nonzero. nullopt when the check fails or the arithmetic does.
std::optional<std::array<Poly, 2>> contact_residual(const ContactMaps& maps,
                                                    const Reparametrisation& psi_k, int n, int m,
                                                    PowersOf& c_power, ExactArithmetic& ar) {
  const std::array<Poly, 2>&P = maps.P, &Q = maps.Q;
  const int k = psi_k.order;
  const Poly psi(psi_k.phi.begin(), psi_k.phi.begin() + k + 1);  // psi[0] = 0
  std::vector<Poly> full{Poly{Expansion(1.0)}, psi};
  for (int r = 2; r <= m; ++r) full.push_back(multiply(full.back(), psi, ar));
  const int degree_e = std::max(n, m * k);
  std::array<Poly, 2> E;
  for (int axis = 0; axis < 2; ++axis) {
    for (int j = 0; j <= degree_e; ++j) {
      Expansion v = ar.mul(coeff(P[axis], j), c_power(2 * j));
      for (int r = 0; r <= m; ++r)
        v = v - ar.mul(ar.mul(Q[axis][static_cast<std::size_t>(r)], c_power(r)),
                       coeff(full[static_cast<std::size_t>(r)], j));
      E[axis].push_back(v);
    }
  }
  if (!ar.ok()) return std::nullopt;
  for (int j = 0; j < k; ++j)
    for (int axis = 0; axis < 2; ++axis)
      if (E[axis][static_cast<std::size_t>(j)].sign() != 0) return std::nullopt;
  const auto uk = static_cast<std::size_t>(k);
  if (E[maps.e][uk].sign() != 0 || E[1 - maps.e][uk].sign() == 0) return std::nullopt;
  return E;
}

/// Step 3's data, the exact quantities rounded outward.
struct IsolationBounds {
  double lower = 0.0;          ///< <= |c E_k,o| = |w(0) x Q'(0)|
  double w0 = 0.0;             ///< >= |E_k,o|
  std::vector<double> w_tail;  ///< >= |E_j|_inf, j = k + 1..deg E (w's Taylor tail)
  std::vector<double> q_norm;  ///< >= |Q_j|_inf, j = 0..m
  std::vector<double> c_phi;   ///< >= |c Phi_i|, i = 1..k
  double c_low = 0.0;          ///< <= |c|
};

/// The bounds of step 3 from the maps, Psi and E (order k = psi.order, m = g's degree);
/// the arithmetic may fail (the caller asks ar.ok()).
IsolationBounds isolation_bounds(const ContactMaps& maps, const Reparametrisation& psi,
                                 const std::array<Poly, 2>& E, int m, ExactArithmetic& ar) {
  const std::array<Poly, 2>& Q = maps.Q;
  const Expansion& c = Q[maps.e][1];
  const int o = 1 - maps.e;
  const int k = psi.order;
  const auto uk = static_cast<std::size_t>(k);
  IsolationBounds b;
  const Expansion cross0 = ar.mul(c, E[o][uk]);
  if (!ar.ok()) return b;
  b.lower = abs_lower(cross0);
  b.w0 = abs_upper(E[o][uk]);
  const int degree_e = static_cast<int>(E[0].size()) - 1;
  for (int j = k + 1; j <= degree_e; ++j)
    b.w_tail.push_back(std::max(abs_upper(E[0][static_cast<std::size_t>(j)]),
                                abs_upper(E[1][static_cast<std::size_t>(j)])));
  for (int j = 0; j <= m; ++j)
    b.q_norm.push_back(std::max(abs_upper(Q[0][static_cast<std::size_t>(j)]),
                                abs_upper(Q[1][static_cast<std::size_t>(j)])));
  for (int i = 1; i <= k; ++i)
    b.c_phi.push_back(abs_upper(ar.mul(c, psi.phi[static_cast<std::size_t>(i)])));
  b.c_low = abs_lower(c);
  return b;
}

/// Step 3's search for rho: the t-radius c^2 rho / b = 2^-level for level = 1, 2, ... down
/// to 2 kLeastIsolation, the first where |w(0) x Q'(0)| exceeds the bound on the tails
/// (|a x b| <= 2 |a|_inf |b|_inf) gives the contact of order k with its isolating boxes;
/// nullopt when none does, or when the boxes would be narrower than kLeastIsolation.
std::optional<HighOrderContact> isolating_box(const IsolationBounds& bounds, RationalParameter t,
                                              RationalParameter s, int k) {
  const std::size_t m = bounds.q_norm.size() - 1;
  // Every bound below is a sum of at most a few hundred products of nonnegative doubles,
  // so its rounding is below 2^-40 relative; kBoundSlack covers it.
  constexpr double kBoundSlack = 1.0 + 0x1p-30;
  // rho is chosen so that the t-radius c^2 rho / b is 2^-level.
  const double c_low = bounds.c_low;
  const double rho_unit = t.den / (c_low * c_low);
  if (!(rho_unit > 0.0) || !std::isfinite(rho_unit)) return std::nullopt;
  for (int level = 1; power_of_two(-level) >= 2 * kLeastIsolation; ++level) {
    const double rho = power_of_two(-level) * rho_unit;
    double r_min = 0.0, rho_i = 1.0;
    for (const double a : bounds.c_phi) r_min += a * (rho_i *= rho);
    const double big_r = 2.0 * r_min;
    if (!(big_r > 0.0)) return std::nullopt;
    double dq = 0.0, r_j = 1.0;  // sum_{j>=2} j |Q_j| R^(j-1)
    for (std::size_t j = 2; j <= m; ++j)
      dq += static_cast<int>(j) * bounds.q_norm[j] * (r_j *= big_r);
    double dw = 0.0;
    rho_i = 1.0;
    for (const double a : bounds.w_tail) dw += a * (rho_i *= rho);
    const double rhs = 2.0 * (bounds.w0 * dq + dw * bounds.q_norm[1] + dw * dq) * kBoundSlack;
    if (!(bounds.lower > rhs)) continue;
    // The parameter boxes: |t - t*| <= c^2 rho / b, |s - s*| <= R / b'; half of each,
    // which also absorbs the rounding of these quotients and of the box ends.
    const double ht = 0.5 * (c_low * c_low * rho / t.den);
    const double hs = 0.5 * (big_r / s.den);
    if (!(ht >= kLeastIsolation && hs >= kLeastIsolation)) return std::nullopt;
    HighOrderContact x;
    x.t_exact = t;
    x.s_exact = s;
    x.t = enclosure(t);
    x.s = enclosure(s);
    x.t_isolated = {std::max(0.0, x.t.lo - ht), std::min(1.0, x.t.hi + ht)};
    x.s_isolated = {std::max(0.0, x.s.lo - hs), std::min(1.0, x.s.hi + hs)};
    x.order = k;
    return x;
  }
  return std::nullopt;
}

}  // namespace

std::optional<RationalParameter> simplest_rational(ParamInterval iv, int max_den) {
  for (int b = 1; b <= max_den; ++b) {
    const double den = b;
    double a = std::ceil(iv.lo * den);
    // a / b >= lo exactly, and the least such a (the signs of fma are exact).
    while (std::fma(-iv.lo, den, a) < 0.0) a += 1.0;
    while (a >= 1.0 && std::fma(-iv.lo, den, a - 1.0) >= 0.0) a -= 1.0;
    if (std::fma(-iv.hi, den, a) <= 0.0 && a <= den) return RationalParameter{a, den};
  }
  return std::nullopt;
}

namespace {

/// The certificate with f's map as P and g's as Q (the header's steps), on `ar`; sets
/// `g_stationary` when it fails because g' vanishes at s (c = 0).
std::optional<HighOrderContact> certify_in_order(const Curve& f, const Curve& g,
                                                 RationalParameter t, RationalParameter s,
                                                 ExactArithmetic& ar, bool& g_stationary) {
  const int n = f.degree(), m = g.degree();
  if (n < 1 || m < 1) return std::nullopt;
  // 1. The maps, meeting at 0.
  const std::optional<ContactMaps> maps = contact_maps(f, g, t, s, ar, g_stationary);
  if (!maps) return std::nullopt;
  // 2. The reparametrisation, along the larger component e of Q'(0), and E.
  PowersOf c_power(maps->Q[maps->e][1], ar);
  const int max_order = std::min(n * m, kMaxContactOrder);
  const Reparametrisation psi = reparametrisation(*maps, m, max_order, c_power, ar);
  if (psi.order < kLeastCertifiedOrder) return std::nullopt;  // no order found is 0: a common component
  const std::optional<std::array<Poly, 2>> E = contact_residual(*maps, psi, n, m, c_power, ar);
  if (!E) return std::nullopt;
  // 3. Isolation: |c E_k,o| = |w(0) x Q'(0)| against the tails, all rounded outward.
  const IsolationBounds bounds = isolation_bounds(*maps, psi, *E, m, ar);
  if (!ar.ok()) return std::nullopt;
  return isolating_box(bounds, t, s, psi.order);
}

}  // namespace

std::optional<HighOrderContact> certify_high_order_contact(const Curve& f, const Curve& g,
                                                           RationalParameter t, RationalParameter s,
                                                           std::int64_t max_products,
                                                           std::int64_t& products) {
  ExactArithmetic ar(max_products);
  bool g_stationary = false;
  std::optional<HighOrderContact> contact = certify_in_order(f, g, t, s, ar, g_stationary);
  // The certificate is symmetric in the two curves but needs Q'(0) != 0: where g stops at s
  // (a zero end derivative, a cusp) and f moves, it is taken with the roles exchanged, and
  // the box read back with t and s exchanged.
  if (!contact && g_stationary && ar.ok()) {
    bool f_stationary = false;
    contact = certify_in_order(g, f, s, t, ar, f_stationary);
    if (contact) {
      std::swap(contact->t_exact, contact->s_exact);
      std::swap(contact->t, contact->s);
      std::swap(contact->t_isolated, contact->s_isolated);
    }
  }
  products = ar.used();
  return contact;
}

std::int64_t HighOrderContactFinder::try_box(ParamInterval t, ParamInterval s,
                                             std::int64_t budget) {
  if (!worth_trying(t, s)) return 0;
  const double width = std::max(t.width(), s.width());
  ++calls_;
  // The box lies somewhere on the stretch where the curves agree to within rounding, not
  // necessarily at the contact: the proposals come from the box widened by growing margins.
  const std::int64_t precheck = 2 * newton_cost(wf_.degree, wg_.degree);
  std::int64_t spent = 0;
  for (double margin = std::max(width, kContactFirstMargin); margin <= kContactTryWidth;
       margin *= kContactMarginGrowth) {
    // The proposal (two loops over the denominators, charged at their longest) and the
    // precheck.
    const std::int64_t cost = 2 * kMaxContactDenominator + precheck;
    if (spent + cost > budget || tried_.size() >= static_cast<std::size_t>(kContactAttempts))
      break;
    spent += cost;
    const auto widened = [margin](ParamInterval iv) {
      return ParamInterval{std::max(0.0, iv.lo - margin), std::min(1.0, iv.hi + margin)};
    };
    const auto p = simplest_rational(widened(t), kMaxContactDenominator);
    const auto q = simplest_rational(widened(s), kMaxContactDenominator);
    if (!p || !q) continue;
    const auto same = [&](RationalParameter a, RationalParameter b) {
      return a == *p && b == *q;
    };
    if (std::any_of(tried_.begin(), tried_.end(), [&](const Tried& x) { return same(x.t, x.s); }))
      continue;
    tried_.push_back({*p, *q});
    // A contact of order >= 3 has parallel tangents: a crossing at rational parameters (a
    // common case) is turned away here, before any exact arithmetic.
    const PointAndTangent a = evaluate_with_tangent(wf_, p->num / p->den);
    const PointAndTangent b = evaluate_with_tangent(wg_, q->num / q->den);
    if (!(std::fabs(a.point.x - b.point.x) <= kContactPrecheck &&
          std::fabs(a.point.y - b.point.y) <= kContactPrecheck &&
          sine_between(a.tangent, b.tangent) <= kContactPrecheck))
      continue;
    std::int64_t products = 0;
    const auto contact = certify_high_order_contact(
        f_, g_, *p, *q, (budget - spent) / kExpansionProductCost, products);
    spent += products * kExpansionProductCost;
    if (contact) {
      found_.push_back(*contact);
      break;
    }
  }
  return spent;
}

bool HighOrderContactFinder::isolated_by_some(ParamInterval t, ParamInterval s) const noexcept {
  return std::any_of(found_.begin(), found_.end(), [&](const HighOrderContact& x) {
    return x.t_isolated.lo <= t.lo && t.hi <= x.t_isolated.hi && x.s_isolated.lo <= s.lo &&
           s.hi <= x.s_isolated.hi;
  });
}

}  // namespace bezier::core
