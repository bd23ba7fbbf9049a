#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/base/curve.hpp"
#include "core/base/work_budget.hpp"

namespace bezier::outline {

/// A closed contour of an outline: segments each starting exactly (bit for bit) where the one
/// before it ends, the last ending where the first starts.
using Contour = std::vector<core::Curve>;

enum class StrokeStatus {
  ok,
  work_cap_reached,   ///< the work budget ran out; no outline
  too_many_segments,  ///< the outline needs more segments than the caller's limit; no outline
};

/// Where the stroke's parts collect their contours: it charges their work to the caller's
/// budget (core/base/work_budget.hpp) and counts their segments against one limit, and stops
/// taking either once one is passed (the status says which).
class OutlineSink {
 public:
  OutlineSink(core::WorkBudget& budget, std::size_t max_segments)
      : budget_(budget), max_segments_(max_segments) {}

  /// Charges `units` of work; false (status work_cap_reached) once the budget is spent.
  bool charge(std::int64_t units) {
    if (status_ != StrokeStatus::ok) return false;
    if (!budget_.spend(units)) status_ = StrokeStatus::work_cap_reached;
    return status_ == StrokeStatus::ok;
  }

  /// Stops the stroke as out of work: a step that cannot finish within any budget (a fit or
  /// a halving that reached its depth limit), or a part that found the budget exhausted.
  void fail_work() {
    budget_.exhaust();
    if (status_ == StrokeStatus::ok) status_ = StrokeStatus::work_cap_reached;
  }

  /// Whether `count` more segments still fit (status too_many_segments when not), before
  /// they are built.
  bool reserve(std::size_t count) {
    if (status_ != StrokeStatus::ok) return false;
    if (count > max_segments_ - std::min(segments_, max_segments_)) {
      status_ = StrokeStatus::too_many_segments;
    }
    return status_ == StrokeStatus::ok;
  }

  /// Takes a closed contour (counted against the limit); false when it does not fit.
  bool add(Contour contour) {
    if (!reserve(contour.size())) return false;
    segments_ += contour.size();
    contours_.push_back(std::move(contour));
    return true;
  }

  [[nodiscard]] bool ok() const noexcept { return status_ == StrokeStatus::ok; }
  [[nodiscard]] StrokeStatus status() const noexcept { return status_; }
  /// The budget, for the parts that charge it themselves (the offset fits).
  [[nodiscard]] core::WorkBudget& budget() noexcept { return budget_; }
  [[nodiscard]] std::size_t segment_count() const noexcept { return segments_; }
  [[nodiscard]] std::vector<Contour> take_contours() { return std::move(contours_); }

 private:
  core::WorkBudget& budget_;
  std::size_t max_segments_;
  std::size_t segments_ = 0;
  StrokeStatus status_ = StrokeStatus::ok;
  std::vector<Contour> contours_;
};

/// Appends `curve` to an open chain: its first control point is set to the chain's end when
/// they differ by rounding only (at most `snap` apart), and a line joins them otherwise.
inline void append_to_chain(Contour& chain, core::Curve curve, double snap) {
  if (!chain.empty() && !(chain.back().back() == curve.front())) {
    const core::Point2 end = chain.back().back();
    const core::Point2 gap = curve.front() - end;
    if (gap.x * gap.x + gap.y * gap.y <= snap * snap) {
      core::Curve::Points points = std::move(curve).take_point_sequence();
      points.front() = end;
      curve = core::Curve(std::move(points));
    } else {
      chain.push_back(core::Curve({end, curve.front()}));
    }
  }
  chain.push_back(std::move(curve));
}

/// Closes a chain built by append_to_chain: a line back to its start when its end is
/// elsewhere (beyond `snap`), else its last end point set to its first start.
inline void close_chain(Contour& chain, double snap) {
  if (chain.empty()) return;
  const core::Point2 start = chain.front().front();
  if (chain.back().back() == start) return;
  const core::Point2 gap = chain.back().back() - start;
  if (gap.x * gap.x + gap.y * gap.y <= snap * snap && chain.back().degree() > 1) {
    core::Curve::Points points = std::move(chain.back()).take_point_sequence();
    points.back() = start;
    chain.back() = core::Curve(std::move(points));
  } else {
    chain.push_back(core::Curve({chain.back().back(), start}));
  }
}

}  // namespace bezier::outline
