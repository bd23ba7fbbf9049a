#include "core/path/segment_boxes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "tests/support/mulberry32.hpp"

namespace bezier::path {
namespace {

bool meet(const core::Rect& p, const core::Rect& q) {
  return p.min.x <= q.max.x && q.min.x <= p.max.x && p.min.y <= q.max.y && q.min.y <= p.max.y;
}

/// Random boxes on a coarse grid, so that shared and touching edges are common.
std::vector<core::Rect> random_boxes(test::Mulberry32& rng, std::size_t n) {
  std::vector<core::Rect> boxes;
  for (std::size_t k = 0; k < n; ++k) {
    const double x = std::floor(rng.uniform(0, 40)), y = std::floor(rng.uniform(0, 40));
    boxes.push_back({{x, y}, {x + std::floor(rng.uniform(0, 8)), y + std::floor(rng.uniform(0, 8))}});
  }
  return boxes;
}

TEST(SegmentBoxes, ControlBoxHoldsEveryControlPoint) {
  const core::Rect b = control_box(core::Curve({{1, 5}, {-2, 3}, {4, -1}, {0, 0}}));
  EXPECT_EQ(b.min.x, -2.0);
  EXPECT_EQ(b.max.x, 4.0);
  EXPECT_EQ(b.min.y, -1.0);
  EXPECT_EQ(b.max.y, 5.0);
}

TEST(SegmentBoxes, TwoSetsGiveExactlyThePairsThatMeet) {
  test::Mulberry32 rng(5);
  for (int round = 0; round < 50; ++round) {
    const auto a = random_boxes(rng, 1 + static_cast<std::size_t>(rng.next() * 60));
    const auto b = random_boxes(rng, 1 + static_cast<std::size_t>(rng.next() * 60));
    std::vector<std::pair<std::size_t, std::size_t>> expected;
    for (std::size_t i = 0; i < a.size(); ++i) {
      for (std::size_t j = 0; j < b.size(); ++j) {
        if (meet(a[i], b[j])) expected.emplace_back(i, j);
      }
    }
    core::WorkBudget budget;
    const MeetingBoxes found = meeting_boxes(a, b, budget);
    EXPECT_FALSE(budget.exhausted());
    EXPECT_EQ(found.pairs, expected) << "round " << round;
  }
}

TEST(SegmentBoxes, OneSetGivesEachMeetingPairOnce) {
  test::Mulberry32 rng(6);
  for (int round = 0; round < 50; ++round) {
    const auto boxes = random_boxes(rng, 1 + static_cast<std::size_t>(rng.next() * 80));
    std::vector<std::pair<std::size_t, std::size_t>> expected;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      for (std::size_t j = i + 1; j < boxes.size(); ++j) {
        if (meet(boxes[i], boxes[j])) expected.emplace_back(i, j);
      }
    }
    core::WorkBudget budget;
    EXPECT_EQ(meeting_boxes(boxes, budget).pairs, expected) << "round " << round;
  }
}

TEST(SegmentBoxes, StopsAtItsWorkLimit) {
  // 100 equal boxes: every pair meets, 4950 pairs reported one after another. Capped at
  // 3000 units the sweep stops within one box's query of the cap: its entries (at most
  // 2 x 100), its pairs (at most 100, 2 log2 N = 14 units each) and its tree path.
  std::vector<core::Rect> boxes(100, core::Rect{{0, 0}, {1, 1}});
  core::WorkBudget capped(3000);
  (void)meeting_boxes(boxes, capped);
  EXPECT_EQ(capped.exhaustion(), core::Exhaustion::work);
  EXPECT_LE(capped.spent(), 3000 + 2 * 100 + 100 * 14 + 64);
  core::WorkBudget small(500);
  (void)meeting_boxes(boxes, small);
  EXPECT_TRUE(small.exhausted());
  core::WorkBudget unlimited;
  const MeetingBoxes full = meeting_boxes(boxes, unlimited);
  EXPECT_FALSE(unlimited.exhausted());
  EXPECT_EQ(full.pairs.size(), 100u * 99 / 2);
  EXPECT_EQ(unlimited.memory(), static_cast<std::int64_t>(full.pairs.size()) * kStoredPairBytes);
}

TEST(SegmentBoxes, ChargesTheSameWhetherTheBudgetJustCoversItOrNot) {
  // The plain sweep charges its sums at once when the budget covers them and box by box
  // otherwise: limits of exactly the work and memory an unlimited run spends are met without
  // running out, with the same pairs and charges; a memory limit one byte short runs out
  // (its last pair refused, box by box).
  test::Mulberry32 rng(21);
  for (int round = 0; round < 40; ++round) {
    const auto boxes = random_boxes(rng, 2 + static_cast<std::size_t>(rng.next() * 60));
    core::WorkBudget unlimited;
    const MeetingBoxes full = meeting_boxes(boxes, unlimited);
    ASSERT_FALSE(unlimited.exhausted());
    core::WorkBudget exact(unlimited.spent(), unlimited.memory());
    EXPECT_EQ(meeting_boxes(boxes, exact).pairs, full.pairs) << round;
    EXPECT_FALSE(exact.exhausted()) << round;
    EXPECT_EQ(exact.spent(), unlimited.spent()) << round;
    EXPECT_EQ(exact.memory(), unlimited.memory()) << round;
    if (!full.pairs.empty()) {
      core::WorkBudget short_of_memory(core::WorkBudget::kUnlimited, unlimited.memory() - 1);
      (void)meeting_boxes(boxes, short_of_memory);
      EXPECT_EQ(short_of_memory.exhaustion(), core::Exhaustion::memory) << round;
    }
  }
}

TEST(SegmentBoxes, StopsBeforeStoringPastItsMemoryLimit) {
  // The same 4950 pairs against a limit of 1000 pairs' bytes: exactly 1000 are stored, the
  // 1001st is charged and refused, whichever sweep runs (the plain one for 100 boxes, the
  // tree's for 1000).
  for (const std::size_t n : {std::size_t{100}, std::size_t{1000}}) {
    std::vector<core::Rect> boxes(n, core::Rect{{0, 0}, {1, 1}});
    core::WorkBudget budget(core::WorkBudget::kUnlimited, 1000 * kStoredPairBytes);
    const MeetingBoxes found = meeting_boxes(boxes, budget);
    EXPECT_EQ(budget.exhaustion(), core::Exhaustion::memory) << n;
    EXPECT_EQ(found.pairs.size(), 1000u) << n;
    EXPECT_EQ(budget.memory(), 1001 * kStoredPairBytes) << n;
  }
}

TEST(SegmentBoxes, AMemoryLimitPartlyUsedBeforeTheSweepStopsItWhereItsRestRunsOut) {
  // 60 equal boxes (1770 pairs, the plain sweep): with 100 pairs' bytes plus 7 bytes left
  // of the limit, 100 pairs fit and the 101st is charged and refused.
  std::vector<core::Rect> boxes(60, core::Rect{{0, 0}, {1, 1}});
  const std::int64_t used = 1000;
  core::WorkBudget budget(core::WorkBudget::kUnlimited, used + 100 * kStoredPairBytes + 7);
  ASSERT_TRUE(budget.charge_memory(used));
  const MeetingBoxes found = meeting_boxes(boxes, budget);
  EXPECT_EQ(budget.exhaustion(), core::Exhaustion::memory);
  EXPECT_EQ(found.pairs.size(), 100u);
  EXPECT_EQ(budget.memory(), used + 101 * kStoredPairBytes);
  // Already past its limit: nothing is stored.
  core::WorkBudget spent(core::WorkBudget::kUnlimited, 10);
  (void)spent.charge_memory(11);
  EXPECT_TRUE(meeting_boxes(boxes, spent).pairs.empty());
}

TEST(SegmentBoxes, WorkGrowsWithThePairsThatMeetNotWithTheirXOverlaps) {
  // 200 thin horizontal boxes spanning the same x range at distinct heights: all overlap in
  // x, none meets another. The work stays below the 19900 x-overlapping pairs a sweep over
  // x alone would compare (the tree's sweep runs).
  std::vector<core::Rect> boxes;
  for (int k = 0; k < 200; ++k) boxes.push_back({{0, 2.0 * k}, {1, 2.0 * k + 1}});
  core::WorkBudget budget;
  const MeetingBoxes found = meeting_boxes(boxes, budget);
  EXPECT_TRUE(found.pairs.empty());
  EXPECT_LT(budget.spent(), 19900);
}

/// Random boxes that all span most of one x range, on a coarse grid in y: every pair
/// overlaps in x, so the sweep takes its tree.
std::vector<core::Rect> wide_boxes(test::Mulberry32& rng, std::size_t n) {
  std::vector<core::Rect> boxes;
  for (std::size_t k = 0; k < n; ++k) {
    const double y = std::floor(rng.uniform(0, 400));
    boxes.push_back({{std::floor(rng.uniform(0, 4)), y},
                     {36 + std::floor(rng.uniform(0, 4)), y + std::floor(rng.uniform(0, 8))}});
  }
  return boxes;
}

TEST(SegmentBoxes, TreeSweepGivesExactlyThePairsThatMeet) {
  test::Mulberry32 rng(8);
  for (int round = 0; round < 10; ++round) {
    const auto a = wide_boxes(rng, 200), b = wide_boxes(rng, 200);
    std::vector<std::pair<std::size_t, std::size_t>> expected, expected_one;
    for (std::size_t i = 0; i < a.size(); ++i) {
      for (std::size_t j = 0; j < b.size(); ++j) {
        if (meet(a[i], b[j])) expected.emplace_back(i, j);
      }
      for (std::size_t j = i + 1; j < a.size(); ++j) {
        if (meet(a[i], a[j])) expected_one.emplace_back(i, j);
      }
    }
    core::WorkBudget budget;
    const MeetingBoxes two = meeting_boxes(a, b, budget);
    EXPECT_EQ(two.pairs, expected) << "round " << round;
    EXPECT_EQ(meeting_boxes(a, budget).pairs, expected_one) << "round " << round;
    EXPECT_FALSE(budget.exhausted());
  }
}

}  // namespace
}  // namespace bezier::path
