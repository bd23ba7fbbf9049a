#include "core/measure/arc_length.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <tuple>

#include "core/numeric/binomial.hpp"
#include "core/curve/derivative.hpp"
#include "core/bernstein/bernstein1d.hpp"
#include "core/measure/bernstein_product.hpp"
#include "core/measure/interval_roots.hpp"
#include "core/measure/normalised.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {

namespace {

double norm1(Point2 p) noexcept { return std::fabs(p.x) + std::fabs(p.y); }
double norm1(Point3 p) noexcept { return std::fabs(p.x) + std::fabs(p.y) + std::fabs(p.z); }

// The 7-point Gauss / 15-point Kronrod pair on [-1, 1] (QUADPACK qk15, Piessens et al. 1983):
// abscissae x_k > 0 (the rule is symmetric) and the centre, with their weights. The Gauss
// nodes are the odd-indexed Kronrod nodes and the centre.
constexpr std::array<double, 8> kKronrodNodes = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
constexpr std::array<double, 8> kKronrodWeights = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr std::array<double, 4> kGaussWeights = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

/// |B'(t)| from the hodograph's control points by de Casteljau (plain: the rounding is
/// bounded in arc_length's error term).
template <class P>
class Speed {
 public:
  explicit Speed(const BasicCurve<P>& curve) : hodograph_(derivative(curve)) {}

  double operator()(double t) const {
    const auto h = hodograph_.points();
    std::array<P, 24> inline_row;
    std::vector<P> heap_row;
    P* row = inline_row.data();
    if (h.size() > inline_row.size()) {
      heap_row.assign(h.begin(), h.end());
      row = heap_row.data();
    } else {
      std::copy(h.begin(), h.end(), row);
    }
    for (std::size_t level = h.size() - 1; level > 0; --level) {
      for (std::size_t k = 0; k < level; ++k) row[k] = lerp(row[k], row[k + 1], t);
    }
    return length(row[0]);
  }

  [[nodiscard]] const BasicCurve<P>& hodograph() const noexcept { return hodograph_; }

 private:
  BasicCurve<P> hodograph_;
};

struct RulePair {
  double kronrod = 0.0;
  double gauss_error = 0.0;  // |K15 - G7|
};

template <class P>
RulePair gauss_kronrod(const Speed<P>& speed, double a, double b) {
  const double centre = a + (b - a) / 2, half = (b - a) / 2;
  const double f_centre = speed(centre);
  double kronrod = kKronrodWeights[7] * f_centre, gauss = kGaussWeights[3] * f_centre;
  for (std::size_t k = 0; k < 7; ++k) {
    const double dx = half * kKronrodNodes[k];
    const double pair = speed(centre - dx) + speed(centre + dx);
    kronrod += kKronrodWeights[k] * pair;
    if (k % 2 == 1) gauss += kGaussWeights[k / 2] * pair;
  }
  return {kronrod * half, std::fabs((kronrod - gauss) * half)};
}

/// Σ x_i by Neumaier's compensated summation: within 2 u |Σ x_i| + O(N u^2) Σ |x_i| for
/// any count (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed., §4.3).
class CompensatedSum {
 public:
  void add(double x) noexcept {
    const double next = sum_ + x;
    correction_ += std::fabs(sum_) >= std::fabs(x) ? (sum_ - next) + x : (x - next) + sum_;
    sum_ = next;
  }
  [[nodiscard]] double value() const noexcept { return sum_ + correction_; }

 private:
  double sum_ = 0.0;
  double correction_ = 0.0;
};

/// ∫_a^b Σ_i ||h_i||_1 b_{i,m}(t) dt for the hodograph's points h_0..h_m: the integral of
/// the de Casteljau condition scale of |B'|, which bounds its evaluation's rounding at each
/// t (componentwise, Higham §5; the 1-norm bounds the Euclidean length's error) and so its
/// integral's. With ∫_0^x b_{i,m} = 1/(m+1) Σ_{j>i} b_{j,m+1}(x) (Farin §5.1), it is
/// W(b) - W(a), W(x) = 1/(m+1) Σ_{j=1..m+1} b_{j,m+1}(x) Σ_{i<j} ||h_i||_1. Unlike max ||h_i||,
/// it stays proportional to the length where the speed is concentrated (one large
/// hodograph point), and is at least the length itself. Its own rounding is a few u of it,
/// negligible once multiplied by the rounding constant.
template <class P>
double integrated_condition(const BasicCurve<P>& hodograph, double a, double b) {
  const auto h = hodograph.points();
  const int m = static_cast<int>(h.size()) - 1;
  const auto antiderivative = [&](double x) {
    double sum = 0.0, prefix = 0.0;
    for (int j = 1; j <= m + 1; ++j) {
      const P p = h[static_cast<std::size_t>(j - 1)];
      prefix += norm1(p);
      sum += binomial(m + 1, j) * std::pow(x, j) * std::pow(1 - x, m + 1 - j) * prefix;
    }
    return sum / (m + 1);
  };
  return std::fabs(antiderivative(b) - antiderivative(a));
}

struct Piece {
  double a, b;
  RulePair rule;
};

/// Where a minimum t0 of S = |B'|^2 is small, S(t) ~ S(t0) + S''(t0) (t - t0)^2 / 2 has its
/// complex zeros at t0 ± i w, w = sqrt(2 S(t0) / S''(t0)): |B'| is a kink smoothed over a
/// width w. A Gauss rule on a piece [t0, t0 + h] with w << h converges slowly, and its G7 and
/// K15 can agree far better than either is right (the kink is not resolved by either). The
/// piece is therefore cut at t0 + w 4^k, k = 0, 1, ..., so that each cut piece is at most
/// four times as far from the complex zeros as it is wide, the regime where |K15 - G7|
/// tracks the error. Below w = 1e-8 h the smoothing changes the integral by about
/// (w / h)^2 log(h / w) < 1e-14 of it relative to the kink |t - t0| that the split at t0
/// already makes exact: no grading then.
void grade_toward(double t0, double w, double toward, std::vector<double>& cuts) {
  const double h = std::fabs(toward - t0);
  if (!(w > 1e-8 * h)) return;
  const double direction = toward > t0 ? 1.0 : -1.0;
  for (double step = w; step < h / 2; step *= 4) cuts.push_back(t0 + direction * step);
}

/// The cuts of [a, b]: a, b, the critical points of |B'| in (a, b) (roots of (B' · B')'),
/// and the grading around each small minimum (grade_toward), increasing.
template <class P>
std::vector<double> split_points(const Speed<P>& speed, double a, double b) {
  std::vector<double> critical = {a};
  const auto h = speed.hodograph().points();
  std::vector<double> squared_speed, second;
  if (h.size() >= 2) {
    squared_speed = dot_product_polynomial<P>(h, h);
    const std::vector<double> slope = bernstein_derivative(squared_speed);
    second = bernstein_derivative(slope);
    for (const double t : interval_roots(slope, a, b, IntervalEnds::open).roots) critical.push_back(t);
  }
  critical.push_back(b);
  std::vector<double> cuts = critical;
  for (std::size_t i = 1; i + 1 < critical.size(); ++i) {
    const double t0 = critical[i];
    const double value = std::max(bernstein::evaluate(squared_speed, t0), 0.0);
    const double curvature = bernstein::evaluate(second, t0);
    if (!(curvature > 0.0)) continue;  // a maximum of |B'|
    const double w = std::sqrt(2 * value / curvature);
    grade_toward(t0, w, critical[i - 1], cuts);
    grade_toward(t0, w, critical[i + 1], cuts);
  }
  std::sort(cuts.begin(), cuts.end());
  return cuts;
}

template <class P>
ArcLength measure(const BasicCurve<P>& curve, double a, double b, const ArcLengthOptions& options) {
  assert(0.0 <= a && a <= b && b <= 1.0);
  ArcLength out;
  out.a = a;
  out.b = b;
  if (!(a < b)) return out;
  const Speed<P> speed(curve);
  const double n = curve.degree();
  const double integrand_rounding =
      2 * (3.01 * n + 1) * kUnitRoundoff * integrated_condition(speed.hodograph(), a, b);

  std::vector<Piece> heap;  // a max-heap on the error estimate
  const auto by_error = [](const Piece& x, const Piece& y) {
    return x.rule.gauss_error < y.rule.gauss_error;
  };
  const std::vector<double> cuts = split_points(speed, a, b);
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    heap.push_back({cuts[i], cuts[i + 1], gauss_kronrod(speed, cuts[i], cuts[i + 1])});
  }
  std::make_heap(heap.begin(), heap.end(), by_error);

  const auto totals = [&] {
    CompensatedSum sum, error;
    for (const Piece& p : heap) {
      sum.add(p.rule.kronrod);
      error.add(p.rule.gauss_error);
    }
    // Each rule's weighted sum of 15 positive terms rounds within 16 u of its value; the
    // compensated total within 2 u (and u more for the error sum itself).
    const double sums_rounding = 20 * kUnitRoundoff * sum.value();
    return std::pair{sum.value(), error.value() + integrand_rounding + sums_rounding};
  };
  double total = 0.0, error = 0.0;
  std::tie(total, error) = totals();
  while (error > options.relative_tolerance * total) {
    if (static_cast<int>(heap.size()) >= options.max_pieces) {
      out.status = ArcLengthStatus::work_cap_reached;
      break;
    }
    std::pop_heap(heap.begin(), heap.end(), by_error);
    const Piece worst = heap.back();
    heap.pop_back();
    const double middle = worst.a + (worst.b - worst.a) / 2;
    if (!(worst.a < middle && middle < worst.b)) {
      // Two adjacent doubles: nothing left to halve; its estimate stays in the bound.
      out.status = ArcLengthStatus::work_cap_reached;
      heap.push_back(worst);
      break;
    }
    heap.push_back({worst.a, middle, gauss_kronrod(speed, worst.a, middle)});
    std::push_heap(heap.begin(), heap.end(), by_error);
    heap.push_back({middle, worst.b, gauss_kronrod(speed, middle, worst.b)});
    std::push_heap(heap.begin(), heap.end(), by_error);
    std::tie(total, error) = totals();
  }
  std::sort(heap.begin(), heap.end(), [](const Piece& x, const Piece& y) { return x.a < y.a; });
  CompensatedSum sum;
  for (const Piece& p : heap) {
    out.pieces.push_back({p.a, p.b, p.rule.kronrod});
    sum.add(p.rule.kronrod);
  }
  out.length = sum.value();
  out.error_bound = error;
  return out;
}

template <class P>
double invert(const BasicCurve<P>& curve, const ArcLength& measured, double target) {
  assert(target >= 0.0);
  if (measured.pieces.empty() || target <= 0.0) return measured.a;
  // The piece where the cumulative length reaches the target.
  double before = 0.0;
  std::size_t index = 0;
  for (; index + 1 < measured.pieces.size(); ++index) {
    if (before + measured.pieces[index].length >= target) break;
    before += measured.pieces[index].length;
  }
  const LengthPiece& piece = measured.pieces[index];
  if (index + 1 == measured.pieces.size() && target >= before + piece.length) return measured.b;
  const Speed<P> speed(curve);
  const double wanted = target - before;  // length from piece.a
  double lo = piece.a, hi = piece.b;
  double t = piece.length > 0.0 ? piece.a + (piece.b - piece.a) * std::clamp(wanted / piece.length, 0.0, 1.0)
                                : piece.a;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double excess = (t > piece.a ? gauss_kronrod(speed, piece.a, t).kronrod : 0.0) - wanted;
    if (excess == 0.0) return t;
    if (excess < 0.0) {
      lo = t;
    } else {
      hi = t;
    }
    const double slope = speed(t);
    double next = t - excess / slope;
    if (!(slope > 0.0) || !(lo < next && next < hi)) next = lo + (hi - lo) / 2;
    if (next == t || !(lo < next && next < hi)) break;
    // Converged when the step is within a few ulps of t.
    const bool tiny = std::fabs(next - t) <= 4 * kUnitRoundoff * std::fabs(t);
    t = next;
    if (tiny) break;
  }
  return t;
}

/// The length of the normalised curve, scaled back (exactly: powers of two).
template <class P>
ArcLength scaled_measure(const BasicCurve<P>& curve, double a, double b,
                         const ArcLengthOptions& options) {
  if (normalising_factor(curve) == 1.0) return measure(curve, a, b, options);
  const Normalised<P> unit = normalised(curve);
  ArcLength out = measure(unit.curve, a, b, options);
  out.length /= unit.factor;
  out.error_bound /= unit.factor;
  for (LengthPiece& piece : out.pieces) piece.length /= unit.factor;
  return out;
}

template <class P>
double scaled_invert(const BasicCurve<P>& curve, const ArcLength& measured, double length) {
  const Normalised<P> unit = normalised(curve);
  ArcLength unit_measured = measured;
  for (LengthPiece& piece : unit_measured.pieces) piece.length *= unit.factor;
  return invert(unit.curve, unit_measured, length * unit.factor);
}

}  // namespace

ArcLength arc_length(const Curve& curve, double a, double b, const ArcLengthOptions& options) {
  return scaled_measure(curve, a, b, options);
}
ArcLength arc_length(const Curve3& curve, double a, double b, const ArcLengthOptions& options) {
  return scaled_measure(curve, a, b, options);
}

double parameter_at_length(const Curve& curve, const ArcLength& measured, double length) {
  return scaled_invert(curve, measured, length);
}
double parameter_at_length(const Curve3& curve, const ArcLength& measured, double length) {
  return scaled_invert(curve, measured, length);
}

}  // namespace bezier::core
