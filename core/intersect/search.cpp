#include "core/intersect/search.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <optional>

#include "core/numeric/min_max.hpp"
#include "core/intersect/clip/bezier_clip.hpp"
#include "core/intersect/common_arc.hpp"
#include "core/intersect/high_order_contact.hpp"
#include "core/intersect/clip/hybrid.hpp"
#include "core/intersect/clip/implicit_clip.hpp"
#include "core/intersect/clip/implicit_cubic_clip.hpp"
#include "core/intersect/kind.hpp"
#include "core/intersect/krawczyk.hpp"
#include "core/intersect/overlap.hpp"
#include "core/intersect/clip/subdivision.hpp"
#include "core/intersect/work_cost.hpp"
#include "core/intersect/tuning.hpp"
#include "core/numeric/power_of_two.hpp"

namespace bezier::core {

namespace {

using namespace intersect_tuning;

struct Box {
  ParamInterval t{0.0, 1.0};
  ParamInterval s{0.0, 1.0};
  bool compensated = false;  ///< pieces in double-double, centred on the box
  bool clip_s = false;       ///< whose turn it is to be clipped
  bool along = false;        ///< direction of the line through a point-like piece
  int depth = 0;
  /// The box's larger width when the Krawczyk test last failed on it (or an ancestor).
  double krawczyk_failed_at = INFINITY;
  /// The same for the implicit cubic clip: the box's larger width when it last kept most of
  /// the piece on the box or an ancestor.
  double cubic_clip_failed_at = INFINITY;
};

/// The two halves of an interval, or nothing when it is too narrow to split in doubles.
struct Halves {
  ParamInterval parts[2];
  int count = 0;
};

Halves halves(ParamInterval iv) noexcept {
  const double m = iv.lo + (iv.hi - iv.lo) * 0.5;
  if (!(iv.lo < m && m < iv.hi)) return {{iv, iv}, 1};
  return {{{iv.lo, m}, {m, iv.hi}}, 2};
}

bool nearly_parallel(const Piece& a, const Piece& b) noexcept {
  const Point2 ca = {a.x.back() - a.x[0], a.y.back() - a.y[0]};
  const Point2 cb = {b.x.back() - b.x[0], b.y.back() - b.y[0]};
  return sine_between(ca, cb) <= kParallelSine;
}

/// The intersection of two kept intervals (both contain every root), or nothing.
std::optional<ParamInterval> intersect_kept(std::optional<ParamInterval> a,
                                            std::optional<ParamInterval> b) {
  if (!a || !b) return std::nullopt;
  const ParamInterval r{max2(a->lo, b->lo), min2(a->hi, b->hi)};
  if (r.hi < r.lo) return std::nullopt;
  return r;
}

/// A stack of boxes, inline for the first 32 (most searches never have more pending) and on
/// the heap beyond: no allocation per call in the common case.
class BoxStack {
 public:
  void push(const Box& b) {
    if (size_ < kInline)
      inline_[size_].box = b;
    else
      overflow_.push_back(b);
    ++size_;
  }
  Box pop() {
    --size_;
    if (size_ < kInline) return inline_[size_].box;
    const Box b = overflow_.back();
    overflow_.pop_back();
    return b;
  }
  [[nodiscard]] bool empty() const noexcept { return size_ == 0; }

 private:
  static constexpr std::size_t kInline = intersect_tuning::kSearchStackInline;
  /// Left unconstructed (Box has member initialisers): a slot is written before it is read.
  union Slot {
    Slot() {}  // NOLINT(modernize-use-equals-default): = default would initialise the Box
    Box box;
  };
  Slot inline_[kInline];
  std::vector<Box> overflow_;
  std::size_t size_ = 0;
};

/// One call's search state: the stack of boxes, the counters and the results. Nothing here
/// outlives the call.
class Searcher {
 public:
  Searcher(const SearchInput& input, WorkBudget& budget)
      : in_(input),
        budget_(budget),
        krawczyk_radius_(power_of_two_at_most(input.width / 2)),
        use_krawczyk_(input.method == IntersectMethod::hybrid && !input.t_free && !input.s_free &&
                      krawczyk_radius_ >= intersect_tuning::kKrawczykSmallestRadius &&
                      krawczyk_radius_ <= intersect_tuning::kKrawczykLargestRadius) {
    out_.stats.method = input.method;
  }

  SearchOutput run() {
    Box first;
    first.t = in_.t_range;
    first.s = in_.s_range;
    stack_.push(first);
    while (!stack_.empty() && !stopped_) {
      const Box box = stack_.pop();
      process(box);
    }
    return std::move(out_);
  }

 private:
  [[nodiscard]] bool t_done(const Box& b) const noexcept {
    return in_.t_free || b.t.width() <= in_.width;
  }
  [[nodiscard]] bool s_done(const Box& b) const noexcept {
    return in_.s_free || b.s.width() <= in_.width;
  }

  void emit(const Box& b, bool resolved) {
    budget_.charge(kCandidateCost);
    out_.candidates.push_back({b.t, b.s, resolved && t_done(b) && s_done(b)});
    ++out_.stats.candidate_boxes;
  }

  /// Halves the chosen intervals and pushes the children (2 or 4 boxes).
  void split(const Box& b, bool split_t, bool split_s) {
    const Halves ts = split_t ? halves(b.t) : Halves{{b.t, b.t}, 1};
    const Halves ss = split_s ? halves(b.s) : Halves{{b.s, b.s}, 1};
    if (ts.count * ss.count == 1) {
      emit(b, false);  // nothing left to split in doubles
      return;
    }
    ++out_.stats.subdivisions;
    for (int i = ts.count - 1; i >= 0; --i) {
      for (int j = ss.count - 1; j >= 0; --j) {
        Box child = b;
        child.t = ts.parts[i];
        child.s = ss.parts[j];
        child.depth = b.depth + 1;
        child.along = false;
        stack_.push(child);
      }
    }
  }

  void make_pieces(const Box& b) {
    if (!b.compensated) {
      if (!f_ok_) {
        fast_piece_into(*in_.f, b.t.lo, b.t.hi, f_piece_);
        f_compensated_.reset();
      }
      if (!g_ok_) {
        fast_piece_into(*in_.g, b.s.lo, b.s.hi, g_piece_);
        g_compensated_.reset();
      }
    } else {
      // A frame centred near the box, so the rounded local coordinates are as small as
      // the pieces themselves; both pieces must share it. A compensated piece depends only
      // on its interval and the centre, so one still in place for the same ones is kept
      // (a clip of the other interval, or a sibling box on the same interval).
      const Point2 center = evaluate_with_tangent(*in_.f, b.t.lo).point;
      const CompensatedKey f_key{b.t.lo, b.t.hi, center};
      const CompensatedKey g_key{b.s.lo, b.s.hi, center};
      if (!(f_compensated_ && *f_compensated_ == f_key)) {
        f_piece_ = compensated_piece(*in_.f, b.t.lo, b.t.hi, center);
        f_compensated_ = f_key;
      }
      if (!(g_compensated_ && *g_compensated_ == g_key)) {
        g_piece_ = compensated_piece(*in_.g, b.s.lo, b.s.hi, center);
        g_compensated_ = g_key;
      }
    }
    f_ok_ = g_ok_ = true;
  }

  /// The degree-2 fits of f's (of_f) or g's pieces for implicit_clip, built on first use:
  /// most searches never need them.
  const FatCurveOperator& fit2(bool of_f) {
    std::optional<FatCurveOperator>& op = of_f ? f_fit2_ : g_fit2_;
    if (!op) op = fat_curve_operator((of_f ? in_.f : in_.g)->degree, 2);
    return *op;
  }

  [[nodiscard]] bool covered(const Box& b) const {
    const CommonArc* tested = nullptr;  // the overlaps of one arc share one test
    for (const OverlapFinding& o : in_.overlaps) {
      if (o.arc) {
        if (o.arc.get() == tested) continue;
        tested = o.arc.get();
        if (covered_by_arc(*o.arc, b.t, b.s)) return true;
      } else if (covered_by_overlap(*in_.f, o, b.t, b.s)) {
        return true;
      }
    }
    return false;
  }

  /// The box lies in an overlap or in a certified contact's isolating box: nothing else there.
  [[nodiscard]] bool excluded(const Box& b) const {
    return (!in_.overlaps.empty() && covered(b)) ||
           (in_.contacts != nullptr && in_.contacts->isolates(b.t, b.s));
  }

  /// try_box on the contact finder, charged; a certified contact starts the exclusions.
  void propose_contact(const Box& b) {
    budget_.charge(in_.contacts->try_box(b.t, b.s, budget_.remaining()));
    if (!in_.contacts->contacts().empty()) excluding_ = true;
  }

  /// coincide_at_precision on the box, charged by the evaluations it made.
  bool coincides(const Box& b) {
    const CoincidenceTest test = coincide_at_precision(
        *in_.f, *in_.g, b.t, b.s, evaluate_with_tangent(*in_.f, b.t.lo).point);
    budget_.charge(coincidence_test_cost(in_.f->degree, in_.g->degree, test.evaluations));
    return test.coincide;
  }

  /// What a step leaves: the box is finished (dropped, reported or split), or it goes round
  /// again as the step changed it (pieces switched to compensated, a clip direction tried).
  enum class Next { finished, again };

  /// The clips a box has tried without shrinking enough since it last shrank.
  struct Tried {
    bool other_direction = false;  ///< the line along a point-like piece
    bool other_curve = false;      ///< clipping the other curve's interval
  };

  /// Steps on one box until it is finished or the work budget runs out.
  void process(Box box) {
    f_ok_ = g_ok_ = false;
    Tried tried;
    while (charge_step(box) && step(box, tried) == Next::again) {
    }
  }

  /// Charges one step on the box to the budget; false (and the search stopped, the budget
  /// exhausted) when what is left does not cover it.
  bool charge_step(const Box& box) {
    const std::int64_t cost = step_cost(in_.f->degree, in_.g->degree, box.compensated);
    if (!budget_.reserve(cost)) {
      stopped_ = true;
      return false;
    }
    ++out_.stats.iterations;
    budget_.charge(cost);
    out_.stats.max_depth = std::max(out_.stats.max_depth, box.depth);
    return true;
  }

  /// One step: drop the box when an overlap covers it or its pieces are apart, report it when
  /// it is narrow enough, otherwise let the method shrink or split it.
  Next step(Box& box, Tried& tried) {
    const bool td = t_done(box), sd = s_done(box);
    if (excluding_ && excluded(box)) return Next::finished;
    make_pieces(box);
    if (box.compensated) ++out_.stats.compensated_steps;
    if (bounding_boxes_disjoint(f_piece_, g_piece_)) return Next::finished;
    if (td && sd) return report(box);
    if (use_krawczyk_ && !box.compensated && krawczyk_decides(box)) return Next::finished;
    if (in_.method == IntersectMethod::subdivision) return separate_or_subdivide(box, td, sd);
    return clip(box, tried, td, sd);
  }

  /// The compensated retry: when rounding decides a test on fast pieces, the box goes round
  /// again on compensated ones. False when its pieces are compensated already.
  bool retry_compensated(Box& box) {
    if (box.compensated) return false;
    // Where rounding decides on nearly parallel pieces, a high-order contact may be the
    // reason: certified, it drops this box (the step's first test) when its isolating box
    // holds it.
    if (in_.contacts != nullptr && in_.contacts->worth_trying(box.t, box.s) &&
        nearly_parallel(f_piece_, g_piece_))
      propose_contact(box);
    box.compensated = true;
    f_ok_ = g_ok_ = false;
    return true;
  }

  /// Both intervals at most the floor width: below it, noise that even compensated pieces
  /// cannot resolve is the precision floor, not an overlap along a stretch (kFloorWidth).
  [[nodiscard]] static bool within_floor(const Box& b) noexcept {
    return b.t.width() <= kFloorWidth && b.s.width() <= kFloorWidth;
  }

  /// The floor test: a compensated box within the floor width, not yet narrow in either
  /// interval, on which the curves agree to within rounding (a high-order contact), is
  /// reported unresolved instead of being split further.
  bool coincides_at_floor(const Box& box, bool td, bool sd) {
    return box.compensated && !td && !sd && within_floor(box) && coincides(box);
  }

  /// A box narrow in t and s: a clip shrinks a box onto where the pieces may meet, but only
  /// the next test shows whether they do, so test once more before reporting.
  Next report(Box& box) {
    const Separation sep = separation(f_piece_, g_piece_);
    if (sep.separated) return Next::finished;
    // When rounding decides, the compensated pieces have their say. So they do at an end of
    // either curve, even when only one side's test was noisy: there a root of the curves'
    // extensions a few ulps beyond the end stays within the fast pieces' rounding (about
    // 1e-15 of the working scale) however narrow the box gets
    // (Search.ACurveEndingBesideAnotherDoesNotMeetItThere). Inside, the fast test stands:
    // retesting every box there would cost Bézier clipping more work than it saves.
    const bool at_end = box.t.lo == 0.0 || box.t.hi == 1.0 || box.s.lo == 0.0 || box.s.hi == 1.0;
    if ((sep.noisy || at_end) && retry_compensated(box)) return Next::again;
    emit(box, true);
    return Next::finished;
  }

  /// The Krawczyk test on a narrow enough box: true when it proved the box empty or holding
  /// exactly one crossing (then reported); false when the box goes on to be clipped.
  bool krawczyk_decides(Box& box) {
    const double w = std::max(box.t.width(), box.s.width());
    if (!(w <= kKrawczykWidth && w <= box.krawczyk_failed_at / 2)) return false;
    const KrawczykResult k =
        krawczyk(*in_.f, *in_.g, f_piece_, g_piece_, box.t, box.s, krawczyk_radius_);
    if (k.verdict == KrawczykResult::Verdict::no_root) return true;
    if (k.verdict == KrawczykResult::Verdict::one_root) {
      Box root = box;
      root.t = k.t;
      root.s = k.s;
      emit(root, true);
      return true;
    }
    box.krawczyk_failed_at = w;
    return false;
  }

  /// The subdivision method's step: drop the box when its pieces are separated (bounding
  /// boxes, fat lines, and the implicit clip when they run nearly parallel), else halve it.
  Next separate_or_subdivide(Box& box, bool td, bool sd) {
    budget_.charge(subdivision_test_cost(in_.f->degree, in_.g->degree));
    const Separation sep = separation(f_piece_, g_piece_);
    if (sep.separated) return Next::finished;
    if (nearly_parallel(f_piece_, g_piece_)) {
      budget_.charge(implicit_clip_cost(in_.f->degree) + implicit_clip_cost(in_.g->degree));
      if (!implicit_clip(f_piece_, g_piece_, fit2(false)).kept ||
          !implicit_clip(g_piece_, f_piece_, fit2(true)).kept)
        return Next::finished;
      // Halving alone reaches rounding late on a high-order contact's stretch: propose here.
      if (in_.contacts != nullptr && in_.contacts->worth_trying(box.t, box.s)) {
        propose_contact(box);
        if (in_.contacts->isolates(box.t, box.s)) return Next::finished;
      }
    }
    if (sep.noisy) {
      if (retry_compensated(box)) return Next::again;
      if (within_floor(box)) {
        emit(box, false);  // precision floor
        return Next::finished;
      }
    }
    if (coincides_at_floor(box, td, sd)) {
      emit(box, false);
      return Next::finished;
    }
    return subdivide(box, td, sd);
  }

  /// The clipping methods' step: clip one interval against the other piece's fat line (with
  /// the implicit clip when the pieces run nearly parallel). A clip that removes enough keeps
  /// the box going; otherwise the box tries the other direction and the other curve, then the
  /// floor test, then is split.
  Next clip(Box& box, Tried& tried, bool td, bool sd) {
    const bool clip_s = td ? true : (sd ? false : box.clip_s);
    const Piece& x = clip_s ? g_piece_ : f_piece_;
    const Piece& other = clip_s ? f_piece_ : g_piece_;
    const PointLineDirection direction =
        box.along ? PointLineDirection::along_other : PointLineDirection::across_other;
    Clip clip = in_.method == IntersectMethod::hybrid
                    ? hybrid_clip(x, other, clip_s ? *in_.op_g : *in_.op_f, direction)
                    : bezier_clip(x, other, direction);
    ++out_.stats.clipping_steps;
    if (!clip.kept) return Next::finished;
    const double threshold =
        in_.method == IntersectMethod::hybrid ? kHybridKeptFraction : kBezierClipKeptFraction;
    if (clip.kept->width() > threshold &&
        (in_.method != IntersectMethod::hybrid ||
         std::max(box.t.width(), box.s.width()) <= kImplicitClipWidth) &&
        nearly_parallel(x, other)) {
      const Clip fine = implicit_clip(x, other, fit2(clip_s));
      ++out_.stats.clipping_steps;
      budget_.charge(implicit_clip_cost(x.degree()));
      clip.kept = intersect_kept(clip.kept, fine.kept);
      if (!clip.kept) return Next::finished;
      // The finer test decides whether rounding is what keeps the pieces together.
      if (fine.informative) clip.noisy = fine.noisy;
      // Cubics that run closer than the parabola's cubic term: the cubic's own equation.
      const double w = std::max(box.t.width(), box.s.width());
      if (other.degree() == 3 && fine.kept && fine.kept->width() >= kCubicClipAfterParabolaKept &&
          w <= kImplicitClipWidth && w <= box.cubic_clip_failed_at * kCubicClipRetryWidth) {
        const Clip exact = implicit_cubic_clip(x, other);
        ++out_.stats.clipping_steps;
        budget_.charge(implicit_cubic_clip_cost(x.degree()));
        clip.kept = intersect_kept(clip.kept, exact.kept);
        if (!clip.kept) return Next::finished;
        // Its `noisy` is left out: this band is all rounding, so it would call the boxes of
        // crossings at tiny angles noisy and stop them unresolved at the floor; the parabola's
        // judgement stands.
        if (exact.kept->width() >= kCubicClipAfterParabolaKept) box.cubic_clip_failed_at = w;
      }
    }
    if (clip.noisy && retry_compensated(box)) return Next::again;
    const ParamInterval domain = clip_s ? box.s : box.t;
    const ParamInterval next = map_to_domain(domain, *clip.kept);
    // Kept more than the threshold's fraction of the domain? (A product, not the quotient: the
    // division's latency would hold up this hard-to-predict branch.)
    const bool kept_too_much = next.width() > threshold * domain.width();
    if (!kept_too_much) {
      tried = {};
      shrink(box, clip_s, next);
      box.clip_s = !clip_s;
      ++box.depth;
      return Next::again;
    }
    // Keep what the clip removed (it is sound), then decide how to go on.
    if (next.width() < domain.width()) shrink(box, clip_s, next);
    if (!tried.other_direction && is_point_like(other)) {
      // A point-like piece defines no line: try the other direction through it.
      tried.other_direction = true;
      box.along = !box.along;
      return Next::again;
    }
    if (coincides_at_floor(box, td, sd)) {
      emit(box, false);  // the curves agree to within rounding here: a high-order contact
      return Next::finished;
    }
    if (!tried.other_curve && !td && !sd) {
      // The other curve's clip may still succeed: try it before halving.
      tried.other_curve = true;
      box.clip_s = !clip_s;
      return Next::again;
    }
    if (clip.noisy) {
      // Rounding decides, even in compensated pieces. When one piece is much longer than the
      // other, halving it still helps (its fat line was the blunt one); a wide box is halved
      // too (the pieces may coincide along a stretch: an improper overlap); otherwise this is
      // the precision floor.
      const double ef = extent(f_piece_.x, f_piece_.y), eg = extent(g_piece_.x, g_piece_.y);
      if (!td && !sd && (ef > kUnevenPieces * eg || eg > kUnevenPieces * ef)) {
        split(box, ef > eg, eg >= ef);
        return Next::finished;
      }
      if (within_floor(box)) {
        emit(box, false);
        return Next::finished;
      }
    }
    return subdivide(box, td, sd);
  }

  /// Narrows the clipped interval to next; the pieces that changed are rebuilt on the next
  /// step (both when compensated: they share a frame centred on the box).
  void shrink(Box& box, bool clip_s, ParamInterval next) {
    (clip_s ? box.s : box.t) = next;
    if (box.compensated)
      f_ok_ = g_ok_ = false;
    else if (clip_s)
      g_ok_ = false;
    else
      f_ok_ = false;
  }

  /// Splits a box its method could not shrink: both intervals not yet narrow (hybrid,
  /// subdivision), or the wider one (Bézier clipping, Sederberg & Nishita 1990, §4).
  Next subdivide(const Box& box, bool td, bool sd) {
    if (in_.method != IntersectMethod::bezier_clipping) {
      split(box, !td, !sd);
    } else {
      const bool split_t = !td && (sd || box.t.width() >= box.s.width());
      split(box, split_t, !split_t);
    }
    return Next::finished;
  }

  const SearchInput& in_;
  WorkBudget& budget_;
  bool stopped_ = false;  ///< a step was not covered by the budget
  /// Half-width of the boxes the Krawczyk test reports: a power of two, so that they are
  /// exact around a parameter on the 2^-52 grid, and at most half the search width.
  double krawczyk_radius_;
  bool use_krawczyk_;
  /// Some boxes are excluded: there are overlaps, or a certified contact (one test per step).
  bool excluding_ = !in_.overlaps.empty();
  SearchOutput out_;
  BoxStack stack_;
  /// The interval and centre of a compensated piece (compensated_piece's arguments), compared
  /// bit for bit (a zero's sign included): the same doubles give the same piece.
  struct CompensatedKey {
    double lo, hi;
    Point2 center;
    bool operator==(const CompensatedKey& o) const noexcept {
      const auto same = [](double a, double b) {
        return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
      };
      return same(lo, o.lo) && same(hi, o.hi) && same(center.x, o.center.x) &&
             same(center.y, o.center.y);
    }
  };

  Piece f_piece_, g_piece_;
  bool f_ok_ = false, g_ok_ = false;
  /// What f_piece_ / g_piece_ hold when they are compensated pieces; empty when they are fast
  /// ones.
  std::optional<CompensatedKey> f_compensated_, g_compensated_;
  std::optional<FatCurveOperator> f_fit2_, g_fit2_;
};

}  // namespace

SearchOutput search(const SearchInput& input, WorkBudget& budget) {
  assert(input.f != nullptr && input.g != nullptr);
  assert(input.method == IntersectMethod::subdivision ||
         (input.op_f != nullptr && input.op_g != nullptr));
  return Searcher(input, budget).run();
}

}  // namespace bezier::core
