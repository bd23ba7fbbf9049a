#include "core/measure/arc_length.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <memory_resource>
#include <span>
#include <tuple>
#include <type_traits>

#include "core/numeric/binomial.hpp"
#include "core/bernstein/bernstein1d.hpp"
#include "core/curve/derivative.hpp"
#include "core/measure/bernstein_product.hpp"
#include "core/measure/interval_roots.hpp"
#include "core/measure/normalised.hpp"
#include "core/measure/tuning.hpp"
#include "core/numeric/unit_roundoff.hpp"

namespace bezier::core {

namespace {

double norm1(Point2 p) noexcept { return std::fabs(p.x) + std::fabs(p.y); }
double norm1(Point3 p) noexcept { return std::fabs(p.x) + std::fabs(p.y) + std::fabs(p.z); }

// The nested rules on [-1, 1], each symmetric: abscissae x_k > 0 and the centre, with their
// weights. Gauss's 3-point rule (exact for polynomials of degree 5); its Kronrod extension
// K7, which adds 4 nodes (exact to degree 11; Kronrod 1965); and Patterson's extension P15 of
// K7, which adds 8 more (exact to degree 23; Patterson, "The optimum addition of points to
// quadrature formulae", Math. Comp. 22, 1968). Each rule reuses every node of the one before.
// The values are the roots of the Stieltjes polynomials of those papers and the weights that
// make each rule exact to its degree, to 36 digits.
constexpr std::array<double, 8> kPattersonNodes = {
    0.993831963212755022208512841307951444, 0.960491268708020283423507092629079963,
    0.888459232872256998890420167258502893, 0.774596669241483377035853079956479922,
    0.621102946737226402940687443816594795, 0.434243749346802558002071502844627817,
    0.223386686428966881628203986843998040, 0.0};
constexpr std::array<double, 8> kPattersonWeights = {
    0.0170017196299402603390274174026535252, 0.0516032829970797396969201205678609837,
    0.0929271953151245376858942226541688264, 0.134415255243784220359968764802491521,
    0.171511909136391380787353165019717218,  0.200628529376989021033931873331359306,
    0.219156858401587496403693161643773748,  0.225510499798206687386422549155949745};
// K7 on kPattersonNodes[1], [3], [5] and the centre; G3 on kPattersonNodes[3] = sqrt(3/5) and
// the centre.
constexpr std::array<double, 4> kKronrodWeights = {
    0.104656226026467265193823857192073038, 0.268488089868333440728569280666709625,
    0.401397414775962222905051818618431879, 0.450916538658474142345110087045570917};
constexpr std::array<double, 2> kGaussWeights = {5.0 / 9.0, 8.0 / 9.0};

/// |B'(t)| from the hodograph's control points by de Casteljau and the square root of the
/// sum of squares (plain: the rounding is bounded in arc_length's error term), at up to
/// kBatch parameters at once: the de Casteljau rounds run across the parameters, one
/// coordinate at a time, the same operations in the same order as one parameter at a time.
/// The curve is normalised (coordinates below 1), so the squares cannot overflow; where they
/// would underflow (|B'| below 2^-480) hypot takes over.
template <class P>
class Speed {
 public:
  static constexpr std::size_t kBatch = 8;

  explicit Speed(const BasicCurve<P>& curve) : hodograph_(hodograph_points(curve.points())) {}

  /// out[j] = |B'(ts[j])| for j < ts.size() <= kBatch.
  void operator()(std::span<const double> ts, double* out) const {
    assert(ts.size() <= kBatch);
    const std::span<const P> h = hodograph();
    const std::size_t m = h.size();
    constexpr std::size_t kInlinePoints = measure_tuning::kSpeedInlinePoints;
    std::array<double, kInlinePoints * kBatch> inline_row;
    std::vector<double> heap_row;
    double* row = inline_row.data();
    if (m > kInlinePoints) {
      heap_row.resize(m * kBatch);
      row = heap_row.data();
    }
    std::array<double, kBatch> t{}, s{}, squared{};
    std::array<std::array<double, kBatch>, kDimension> component;
    std::copy(ts.begin(), ts.end(), t.begin());
    for (std::size_t j = 0; j < kBatch; ++j) s[j] = 1.0 - t[j];
    for (std::size_t d = 0; d < kDimension; ++d) {
      for (std::size_t i = 0; i < m; ++i) {
        const double c = coordinate(h[i], d);
        for (std::size_t j = 0; j < kBatch; ++j) row[i * kBatch + j] = c;
      }
      for (std::size_t level = m - 1; level > 0; --level) {
        for (std::size_t i = 0; i < level; ++i) {
          std::array<double, kBatch> next;
          for (std::size_t j = 0; j < kBatch; ++j) next[j] = s[j] * row[i * kBatch + j] + t[j] * row[(i + 1) * kBatch + j];
          std::copy(next.begin(), next.end(), row + i * kBatch);
        }
      }
      for (std::size_t j = 0; j < kBatch; ++j) {
        component[d][j] = row[j];
        squared[j] += row[j] * row[j];
      }
    }
    for (std::size_t j = 0; j < ts.size(); ++j) {
      if (squared[j] >= measure_tuning::kPlainSquaredSpeed) {
        out[j] = std::sqrt(squared[j]);
      } else {
        P at;
        at.x = component[0][j];
        at.y = component[1][j];
        if constexpr (kDimension == 3) at.z = component[2][j];
        out[j] = length(at);
      }
    }
  }

  double operator()(double t) const {
    double value = 0.0;
    (*this)(std::span<const double>(&t, 1), &value);
    return value;
  }

  [[nodiscard]] std::span<const P> hodograph() const noexcept {
    return {hodograph_.data(), hodograph_.size()};
  }

 private:
  static constexpr std::size_t kDimension = std::is_same_v<P, Point3> ? 3 : 2;
  static double coordinate(const P& p, std::size_t d) noexcept {
    if (d == 0) return p.x;
    if constexpr (kDimension == 3) {
      if (d == 2) return p.z;
    }
    return p.y;
  }

  SmallArray<P> hodograph_;
};

/// One piece of [a, b] under the nested rules: its length by K7, or by P15 once extended,
/// and the estimate of that value's error, |K7 - G3| or |P15 - K7|.
struct Piece {
  double a = 0.0;
  double b = 0.0;
  double length = 0.0;
  double error = 0.0;
  bool extended = false;
  /// f at the centre and f(c - h x_k) + f(c + h x_k) at K7's three abscissae, kept so that
  /// the extension to P15 evaluates only its 8 new nodes.
  std::array<double, 4> kronrod_values{};
};

/// The piece [a, b] by K7, with |K7 - G3| as its error: 7 evaluations of |B'|.
template <class P>
Piece kronrod7(const Speed<P>& speed, double a, double b) {
  const double centre = a + (b - a) / 2, half = (b - a) / 2;
  std::array<double, 7> ts, f;
  for (std::size_t k = 0; k < 3; ++k) {
    const double dx = half * kPattersonNodes[2 * k + 1];
    ts[2 * k] = centre - dx;
    ts[2 * k + 1] = centre + dx;
  }
  ts[6] = centre;
  speed(ts, f.data());
  Piece piece{a, b};
  for (std::size_t k = 0; k < 3; ++k) piece.kronrod_values[k] = f[2 * k] + f[2 * k + 1];
  piece.kronrod_values[3] = f[6];
  double kronrod = 0.0;
  for (std::size_t k = 0; k < 4; ++k) kronrod += kKronrodWeights[k] * piece.kronrod_values[k];
  const double gauss = kGaussWeights[0] * piece.kronrod_values[1] + kGaussWeights[1] * piece.kronrod_values[3];
  piece.length = kronrod * half;
  piece.error = std::fabs((kronrod - gauss) * half);
  return piece;
}

/// The piece by P15, with |P15 - K7| as its error: the 8 nodes K7 lacks.
template <class P>
void extend(const Speed<P>& speed, Piece& piece) {
  const double centre = piece.a + (piece.b - piece.a) / 2, half = (piece.b - piece.a) / 2;
  std::array<double, 8> ts, f;
  for (std::size_t k = 0; k < 4; ++k) {
    const double dx = half * kPattersonNodes[2 * k];
    ts[2 * k] = centre - dx;
    ts[2 * k + 1] = centre + dx;
  }
  speed(ts, f.data());
  double patterson = kPattersonWeights[7] * piece.kronrod_values[3];
  for (std::size_t k = 0; k < 7; ++k) {
    const double pair = k % 2 == 1 ? piece.kronrod_values[k / 2] : f[k] + f[k + 1];
    patterson += kPattersonWeights[k] * pair;
  }
  patterson *= half;
  piece.error = std::fabs(patterson - piece.length);
  piece.length = patterson;
  piece.extended = true;
}

template <class P>
Piece patterson15(const Speed<P>& speed, double a, double b) {
  Piece piece = kronrod7(speed, a, b);
  extend(speed, piece);
  return piece;
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
double integrated_condition(std::span<const P> h, double a, double b) {
  const int m = static_cast<int>(h.size()) - 1;
  const auto antiderivative = [&](double x) {
    double sum = 0.0, prefix = 0.0;
    if (x == 0.0) return 0.0;
    if (x == 1.0) {  // b_{j,m+1}(1) is 1 for j = m + 1, else 0
      for (const P& p : h) prefix += norm1(p);
      return prefix / (m + 1);
    }
    for (int j = 1; j <= m + 1; ++j) {
      const P p = h[static_cast<std::size_t>(j - 1)];
      prefix += norm1(p);
      sum += binomial(m + 1, j) * std::pow(x, j) * std::pow(1 - x, m + 1 - j) * prefix;
    }
    return sum / (m + 1);
  };
  return std::fabs(antiderivative(b) - antiderivative(a));
}

/// Where a minimum t0 of S = |B'|^2 is small, S(t) ~ S(t0) + S''(t0) (t - t0)^2 / 2 has its
/// complex zeros at t0 ± i w, w = sqrt(2 S(t0) / S''(t0)): |B'| is a kink smoothed over a
/// width w. A Gauss rule on a piece [t0, t0 + h] with w << h converges slowly, and two nested
/// rules can agree far better than either is right (the kink is resolved by neither). The
/// piece is therefore cut at t0 + w 4^k, k = 0, 1, ..., so that each cut piece is at most
/// four times as far from the complex zeros as it is wide, the regime where the difference
/// of the nested rules tracks the error. Below w = 1e-8 h (measure_tuning::kUngradedWidth) the
/// smoothing changes the integral
/// by about (w / h)^2 log(h / w) < 1e-14 of it relative to the kink |t - t0| that the split
/// at t0 already makes exact: no grading then.
void grade_toward(double t0, double w, double toward, std::pmr::vector<double>& cuts) {
  const double h = std::fabs(toward - t0);
  if (!(w > measure_tuning::kUngradedWidth * h)) return;
  const double direction = toward > t0 ? 1.0 : -1.0;
  for (double step = w; step < h / 2; step *= 4) cuts.push_back(t0 + direction * step);
}

/// Whether p, in Bernstein form on [0, 1], may rise through zero in (0, 1): false when its
/// coefficients, each taken with the rounding allowance e = 3.02 n u max|c_i| of
/// interval_roots, are surely positive up to some index and surely negative after it (all
/// positive and all negative included). Such a p has at most one sign change on (0, 1), by
/// the variation-diminishing property of the Bernstein basis, and starts positive, so it
/// never rises through zero there.
bool may_rise_through_zero(std::span<const double> c) {
  double largest = 0.0;
  for (const double x : c) largest = std::fmax(largest, std::fabs(x));
  const double e = 3.02 * static_cast<double>(c.size() - 1) * kUnitRoundoff * largest;
  std::size_t i = 0;
  while (i < c.size() && c[i] > e) ++i;
  while (i < c.size() && c[i] < -e) ++i;
  return i < c.size();
}

/// The cuts of [a, b]: a, b, the minima of |B'| in (a, b) (the roots of (B' · B')' where it
/// rises through zero), and the grading around each small minimum (grade_toward),
/// increasing. A maximum of |B'| needs no cut: S > 0 there, and |B'| is analytic around it.
template <class P>
std::pmr::vector<double> split_points(const Speed<P>& speed, double a, double b,
                                      std::pmr::memory_resource* memory) {
  std::pmr::vector<double> cuts(memory);
  cuts.reserve(16);
  cuts.push_back(a);
  const std::span<const P> h = speed.hodograph();
  if (h.size() >= 2) {
    const Coeffs squared_speed = dot_product_polynomial<P>(h, h);
    const Coeffs slope = bernstein_derivative(squared_speed);
    IntervalRoots found;
    if (may_rise_through_zero(slope)) found = interval_roots(slope, a, b, IntervalEnds::open, Crossings::rising);
    const auto& minima = found.roots;
    const Coeffs second = minima.empty() ? Coeffs() : bernstein_derivative(slope);
    for (std::size_t i = 0; i < minima.size(); ++i) {
      const double t0 = minima[i];
      cuts.push_back(t0);
      const double value = std::max(bernstein::evaluate(squared_speed, t0), 0.0);
      const double curvature = bernstein::evaluate(second, t0);
      if (!(curvature > 0.0)) continue;  // a flat stretch reported as a root: no width to grade by
      const double w = std::sqrt(2 * value / curvature);
      grade_toward(t0, w, i > 0 ? minima[i - 1] : a, cuts);
      grade_toward(t0, w, i + 1 < minima.size() ? minima[i + 1] : b, cuts);
    }
  }
  cuts.push_back(b);
  std::sort(cuts.begin(), cuts.end());
  return cuts;
}

template <class P>
ArcLength measure(const BasicCurve<P>& curve, double a, double b, const ArcLengthOptions& options,
                  WorkBudget& budget) {
  assert(0.0 <= a && a <= b && b <= 1.0);
  ArcLength out;
  out.a = a;
  out.b = b;
  if (!(a < b)) return out;
  const Speed<P> speed(curve);
  const double n = curve.degree();
  const double integrand_rounding =
      2 * (3.01 * n + 3) * kUnitRoundoff * integrated_condition(speed.hodograph(), a, b);

  // The cuts and the pieces live in a stack arena (the vectors' growth falls back to the
  // heap beyond it): allocations are a fixed cost of every call, a large part of it at
  // loose tolerances.
  std::array<std::byte, 4096> arena_bytes;
  std::pmr::monotonic_buffer_resource arena(arena_bytes.data(), arena_bytes.size());
  std::pmr::vector<Piece> heap(&arena);  // a max-heap on the error estimate
  const auto by_error = [](const Piece& x, const Piece& y) { return x.error < y.error; };
  const std::pmr::vector<double> cuts = split_points(speed, a, b, &arena);
  heap.reserve(cuts.size() + 8);
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) heap.push_back(kronrod7(speed, cuts[i], cuts[i + 1]));
  std::make_heap(heap.begin(), heap.end(), by_error);
  const std::int64_t evaluation = speed_evaluation_cost(curve.degree());
  const auto sums = [](std::size_t pieces) {
    return kLengthSumCostPerPiece * static_cast<std::int64_t>(pieces);
  };
  budget.charge(7 * evaluation * static_cast<std::int64_t>(heap.size()) + sums(heap.size()));

  const auto totals = [&] {
    CompensatedSum sum, error;
    for (const Piece& p : heap) {
      sum.add(p.length);
      error.add(p.error);
    }
    // Each rule's weighted sum of at most 15 positive terms rounds within 16 u of its value;
    // the compensated total within 2 u (and u more for the error sum itself).
    const double sums_rounding = 20 * kUnitRoundoff * sum.value();
    return std::pair{sum.value(), error.value() + integrand_rounding + sums_rounding};
  };
  double total = 0.0, error = 0.0;
  std::tie(total, error) = totals();
  // The piece with the largest estimate is first extended from K7 to P15 (8 evaluations
  // raise the degree of exactness from 11 to 23), then, if still the largest, halved; the
  // halves of a piece that needed P15 start at P15.
  while (error > options.relative_tolerance * total) {
    std::pop_heap(heap.begin(), heap.end(), by_error);
    Piece& worst = heap.back();
    if (!worst.extended) {
      const std::int64_t extension = 8 * evaluation + sums(heap.size());
      if (!budget.reserve(extension)) {
        std::push_heap(heap.begin(), heap.end(), by_error);
        break;
      }
      budget.charge(extension);
      extend(speed, worst);
      std::push_heap(heap.begin(), heap.end(), by_error);
      std::tie(total, error) = totals();
      continue;
    }
    const double middle = worst.a + (worst.b - worst.a) / 2;
    const std::int64_t halving = 2 * 15 * evaluation + sums(heap.size() + 1);
    if (!(worst.a < middle && middle < worst.b) || !budget.reserve(halving)) {
      // Two adjacent doubles with nothing left to halve, or no work left: the estimates
      // stay in the bound.
      std::push_heap(heap.begin(), heap.end(), by_error);
      break;
    }
    budget.charge(halving);
    const double start = worst.a, end = worst.b;
    worst = patterson15(speed, start, middle);
    std::push_heap(heap.begin(), heap.end(), by_error);
    heap.push_back(patterson15(speed, middle, end));
    std::push_heap(heap.begin(), heap.end(), by_error);
    std::tie(total, error) = totals();
  }
  std::sort(heap.begin(), heap.end(), [](const Piece& x, const Piece& y) { return x.a < y.a; });
  out.pieces.reserve(heap.size());
  CompensatedSum sum;
  for (const Piece& p : heap) {
    out.pieces.push_back({p.a, p.b, p.length});
    sum.add(p.length);
  }
  out.length = sum.value();
  out.error_bound = error;
  out.tolerance_met = !(error > options.relative_tolerance * total);
  return out;
}

template <class P>
double invert(const BasicCurve<P>& curve, const ArcLength& measured, double target) {
  assert(target >= 0.0);
  if (measured.pieces.empty() || target <= 0.0) return measured.a;
  if (target >= measured.length) return measured.b;  // the pieces' running sum may round below it
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
    const double excess = (t > piece.a ? patterson15(speed, piece.a, t).length : 0.0) - wanted;
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
                         const ArcLengthOptions& options, WorkBudget& budget) {
  if (normalising_exponent(curve) == 0) return measure(curve, a, b, options, budget);
  const Normalised<P> unit = normalised(curve);
  ArcLength out = measure(unit.curve, a, b, options, budget);
  out.length = unit.from_unit(out.length);
  out.error_bound = unit.from_unit(out.error_bound);
  for (LengthPiece& piece : out.pieces) piece.length = unit.from_unit(piece.length);
  return out;
}

template <class P>
double scaled_invert(const BasicCurve<P>& curve, const ArcLength& measured, double length) {
  const Normalised<P> unit = normalised(curve);
  ArcLength unit_measured = measured;
  unit_measured.length = unit.to_unit(unit_measured.length);
  for (LengthPiece& piece : unit_measured.pieces) piece.length = unit.to_unit(piece.length);
  return invert(unit.curve, unit_measured, unit.to_unit(length));
}

}  // namespace

ArcLength arc_length(const Curve& curve, double a, double b, const ArcLengthOptions& options,
                     WorkBudget& budget) {
  return scaled_measure(curve, a, b, options, budget);
}
ArcLength arc_length(const Curve3& curve, double a, double b, const ArcLengthOptions& options,
                     WorkBudget& budget) {
  return scaled_measure(curve, a, b, options, budget);
}
ArcLength arc_length(const Curve& curve, double a, double b, const ArcLengthOptions& options) {
  WorkBudget budget(options.max_work);
  return scaled_measure(curve, a, b, options, budget);
}
ArcLength arc_length(const Curve3& curve, double a, double b, const ArcLengthOptions& options) {
  WorkBudget budget(options.max_work);
  return scaled_measure(curve, a, b, options, budget);
}

double parameter_at_length(const Curve& curve, const ArcLength& measured, double length) {
  return scaled_invert(curve, measured, length);
}
double parameter_at_length(const Curve3& curve, const ArcLength& measured, double length) {
  return scaled_invert(curve, measured, length);
}

}  // namespace bezier::core
