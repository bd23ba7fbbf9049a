// WorkBudget (work_budget.hpp): reserve judges before a step, spend after it, charge only
// counts; running out is one sticky flag with its first reason; memory has its own limit.

#include "core/base/work_budget.hpp"

#include <gtest/gtest.h>

namespace bezier::core {
namespace {

TEST(WorkBudget, ReserveAcceptsExactlyWhatIsLeftAndNoMore) {
  WorkBudget budget(10);
  EXPECT_TRUE(budget.reserve(10));
  EXPECT_EQ(budget.spent(), 0);  // reserving spends nothing
  budget.charge(4);
  EXPECT_EQ(budget.remaining(), 6);
  EXPECT_TRUE(budget.reserve(6));
  EXPECT_FALSE(budget.exhausted());
  EXPECT_FALSE(budget.reserve(7));
  EXPECT_TRUE(budget.exhausted());
  EXPECT_EQ(budget.exhaustion(), Exhaustion::work);
  EXPECT_EQ(budget.spent(), 4);
}

TEST(WorkBudget, SpendCountsTheUnitsAndJudgesTheTotal) {
  WorkBudget budget(10);
  EXPECT_TRUE(budget.spend(10));
  EXPECT_FALSE(budget.exhausted());
  EXPECT_FALSE(budget.spend(1));
  EXPECT_EQ(budget.spent(), 11);
  EXPECT_EQ(budget.remaining(), -1);
  EXPECT_TRUE(budget.exhausted());
}

TEST(WorkBudget, ChargeCountsWithoutJudging) {
  WorkBudget budget(10);
  budget.charge(25);
  EXPECT_EQ(budget.spent(), 25);
  EXPECT_FALSE(budget.exhausted());
  EXPECT_FALSE(budget.reserve(0));  // nothing is left, not even for a free step
  EXPECT_TRUE(budget.exhausted());
}

TEST(WorkBudget, ExhaustionStaysSetWithItsFirstReason) {
  WorkBudget budget(100, 64);
  EXPECT_TRUE(budget.charge_memory(64));
  EXPECT_FALSE(budget.charge_memory(1));
  EXPECT_EQ(budget.memory(), 65);
  EXPECT_EQ(budget.exhaustion(), Exhaustion::memory);
  EXPECT_FALSE(budget.reserve(101));
  EXPECT_EQ(budget.exhaustion(), Exhaustion::memory);
  EXPECT_TRUE(budget.reserve(100));  // the arithmetic goes on: a caller may still ask
  EXPECT_TRUE(budget.exhausted());
}

TEST(WorkBudget, TheDefaultHasNoLimit) {
  WorkBudget budget;
  EXPECT_TRUE(budget.spend(WorkBudget::kUnlimited / 2));
  EXPECT_TRUE(budget.reserve(WorkBudget::kUnlimited / 2));
  EXPECT_TRUE(budget.charge_memory(std::int64_t{1} << 60));
  EXPECT_FALSE(budget.exhausted());
  EXPECT_EQ(budget.exhaustion(), Exhaustion::none);
}

TEST(WorkBudget, APartSpendsWhatIsLeftAndSettlesBack) {
  WorkBudget budget(100, 50);
  budget.charge(30);
  EXPECT_TRUE(budget.charge_memory(20));
  WorkBudget part = budget.share();
  EXPECT_EQ(part.remaining(), 70);
  EXPECT_EQ(part.memory_limit(), 30);
  EXPECT_FALSE(part.reserve(71));
  budget.settle(part);
  EXPECT_EQ(budget.exhaustion(), Exhaustion::work);
  WorkBudget next = budget.share();  // a later part starts unexhausted with what is left
  EXPECT_FALSE(next.exhausted());
  EXPECT_TRUE(next.spend(70));
  EXPECT_TRUE(next.charge_memory(30));
  budget.settle(next);
  EXPECT_EQ(budget.spent(), 100);
  EXPECT_EQ(budget.memory(), 50);
  EXPECT_EQ(budget.remaining(), 0);
}

}  // namespace
}  // namespace bezier::core
