#pragma once

#include <cstdint>
#include <limits>

namespace bezier::core {

/// Why a WorkBudget ran out.
enum class Exhaustion {
  none,    ///< it did not
  work,    ///< a step needed more work units than were left
  memory,  ///< what the call stores passed the memory limit
};

/// What one call of the kernel may spend, passed by reference through every function that
/// does iterative work, so that the phases of a call (and the calls one request composes:
/// path segments, self-intersections and their certification) share one budget instead of
/// each computing what is left of a cap.
///
/// Work is counted in work units (core/intersect/work_cost.hpp: about one coordinate update
/// of de Casteljau's algorithm in doubles); memory in bytes of what a call stores in
/// proportion to its input's structure (the candidate pairs of a path's sweep and the
/// copies made of them), not the fixed-size state of each step.
///
/// Three operations:
///  - charge(units): work done whose cost was known only after it ran; always counted.
///  - reserve(units): asked before a step of known cost; false when it does not fit in what
///    is left, and the budget is then exhausted (the step is not taken).
///  - spend(units): charged, then judged; false when the spent work passed the limit.
/// The one way to say the budget ran out is exhausted() (and exhaustion(), which says
/// why): it stays set once set. Nothing else stops the caller: a phase that finds the
/// budget exhausted returns what it has, and the caller reports the result incomplete
/// (the api answers 422).
class WorkBudget {
 public:
  static constexpr std::int64_t kUnlimited = std::numeric_limits<std::int64_t>::max();

  /// No limit on either: for tests and tools that run a call to its end.
  constexpr WorkBudget() noexcept = default;

  /// At most `work_limit` work units and `memory_limit` bytes.
  constexpr explicit WorkBudget(std::int64_t work_limit,
                                std::int64_t memory_limit = kUnlimited) noexcept
      : work_limit_(work_limit), memory_limit_(memory_limit) {}

  constexpr void charge(std::int64_t units) noexcept { spent_ += units; }

  [[nodiscard]] constexpr bool reserve(std::int64_t units) noexcept {
    if (units > work_limit_ - spent_) {
      run_out(Exhaustion::work);
      return false;
    }
    return true;
  }

  constexpr bool spend(std::int64_t units) noexcept {
    spent_ += units;
    if (spent_ > work_limit_) {
      run_out(Exhaustion::work);
      return false;
    }
    return true;
  }

  /// Says the budget ran out, for a phase that measured in advance what is left against
  /// steps it charges only afterwards (the clustering of the self-intersection search's
  /// contact boxes, charged per 64 comparisons) and hit it.
  constexpr void exhaust(Exhaustion why = Exhaustion::work) noexcept { run_out(why); }

  /// Counts `bytes` more stored; false (exhausted, Exhaustion::memory) when the total
  /// passes the memory limit: the caller then stops before storing more.
  constexpr bool charge_memory(std::int64_t bytes) noexcept {
    memory_ += bytes;
    if (memory_ > memory_limit_) {
      run_out(Exhaustion::memory);
      return false;
    }
    return true;
  }

  /// A budget for one part of the call whose running out the caller must tell apart from
  /// the other parts' (a pair certified after another ran out may still finish): what is
  /// left of this one, work and memory. Its spending comes back with settle().
  [[nodiscard]] constexpr WorkBudget share() const noexcept {
    WorkBudget part(remaining(), memory_limit_ - memory_);
    return part;
  }

  /// Counts what `part` (from share()) spent and stored, and its running out.
  constexpr void settle(const WorkBudget& part) noexcept {
    spent_ += part.spent_;
    memory_ += part.memory_;
    if (part.exhausted()) run_out(part.why_);
  }

  /// Work units left (negative once charge() went past the limit).
  [[nodiscard]] constexpr std::int64_t remaining() const noexcept { return work_limit_ - spent_; }
  [[nodiscard]] constexpr std::int64_t spent() const noexcept { return spent_; }
  [[nodiscard]] constexpr std::int64_t work_limit() const noexcept { return work_limit_; }
  [[nodiscard]] constexpr std::int64_t memory() const noexcept { return memory_; }
  [[nodiscard]] constexpr std::int64_t memory_limit() const noexcept { return memory_limit_; }

  [[nodiscard]] constexpr bool exhausted() const noexcept { return why_ != Exhaustion::none; }
  /// The first reason the budget ran out.
  [[nodiscard]] constexpr Exhaustion exhaustion() const noexcept { return why_; }

 private:
  constexpr void run_out(Exhaustion why) noexcept {
    if (why_ == Exhaustion::none) why_ = why;
  }

  std::int64_t work_limit_ = kUnlimited;
  std::int64_t memory_limit_ = kUnlimited;
  std::int64_t spent_ = 0;
  std::int64_t memory_ = 0;
  Exhaustion why_ = Exhaustion::none;
};

}  // namespace bezier::core
