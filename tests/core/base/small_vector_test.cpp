// SmallVector (small_vector.hpp): the same sequence of values whether they are inline (at
// most N) or on the heap, across growth past N and shrinking back, deep copies, moves that
// leave the source empty, and take_vector handing the values over in order.

#include "core/base/small_vector.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "core/base/point.hpp"

namespace bezier::core {
namespace {

using Small = SmallVector<int, 3>;

std::vector<int> values_of(const Small& s) { return std::vector<int>(s.begin(), s.end()); }

std::vector<int> first_n(int n) {
  std::vector<int> out;
  for (int i = 0; i < n; ++i) out.push_back(10 * i + 1);
  return out;
}

TEST(SmallVector, PushBackKeepsEveryValueInOrderAcrossTheInlineLimit) {
  Small s;
  EXPECT_TRUE(s.empty());
  for (int n = 1; n <= 7; ++n) {
    s.push_back(10 * (n - 1) + 1);
    ASSERT_EQ(s.size(), static_cast<std::size_t>(n));
    EXPECT_EQ(values_of(s), first_n(n));
    EXPECT_EQ(s.front(), 1);
    EXPECT_EQ(s.back(), 10 * (n - 1) + 1);
  }
}

TEST(SmallVector, BuiltFromASpanAListOrAVectorOfAnySize) {
  for (int n = 0; n <= 6; ++n) {
    const std::vector<int> v = first_n(n);
    EXPECT_EQ(values_of(Small(std::span<const int>(v))), v);
    EXPECT_EQ(values_of(Small(std::vector<int>(v))), v);
  }
  EXPECT_EQ(values_of(Small{4, 5}), (std::vector<int>{4, 5}));
  EXPECT_EQ(values_of(Small{4, 5, 6, 7, 8}), (std::vector<int>{4, 5, 6, 7, 8}));
}

TEST(SmallVector, SizedIsValueInitialisedAndResizeKeepsThePrefix) {
  Small s(5);
  EXPECT_EQ(values_of(s), std::vector<int>(5, 0));
  for (std::size_t i = 0; i < s.size(); ++i) s[i] = static_cast<int>(i) + 1;
  s.resize(2);  // back inline
  EXPECT_EQ(values_of(s), (std::vector<int>{1, 2}));
  s.resize(4);  // onto the heap again: the new entries are zero
  EXPECT_EQ(values_of(s), (std::vector<int>{1, 2, 0, 0}));
  s.resize(3);
  EXPECT_EQ(values_of(s), (std::vector<int>{1, 2, 0}));
}

TEST(SmallVector, CopiesAreDeepWhereverTheValuesAre) {
  for (int n : {2, 5}) {
    const std::vector<int> v = first_n(n);
    Small a{std::span<const int>(v)};
    Small b = a;
    b[0] = -1;
    EXPECT_EQ(values_of(a), first_n(n));
    Small c{9};
    c = a;
    EXPECT_EQ(c, a);
    c[1] = -2;
    EXPECT_EQ(values_of(a), first_n(n));
    EXPECT_FALSE(c == a);
  }
  // Assigning a short sequence over a long one, and a long one over a short one.
  Small longer{1, 2, 3, 4, 5}, shorter{7};
  Small x = longer;
  x = shorter;
  EXPECT_EQ(values_of(x), (std::vector<int>{7}));
  x = longer;
  EXPECT_EQ(values_of(x), (std::vector<int>{1, 2, 3, 4, 5}));
}

TEST(SmallVector, MovesHandTheValuesOverAndLeaveTheSourceEmpty) {
  for (int n : {2, 3, 4, 6}) {
    const std::vector<int> v = first_n(n);
    Small a{std::span<const int>(v)};
    Small b = std::move(a);
    EXPECT_EQ(values_of(b), first_n(n));
    EXPECT_TRUE(a.empty());  // NOLINT(bugprone-use-after-move): the documented state
    Small c{8, 8, 8, 8, 8, 8};
    c = std::move(b);
    EXPECT_EQ(values_of(c), first_n(n));
    EXPECT_TRUE(b.empty());  // NOLINT(bugprone-use-after-move)
    b.push_back(3);          // usable again
    EXPECT_EQ(values_of(b), (std::vector<int>{3}));
  }
}

TEST(SmallVector, TakeVectorGivesTheValuesInOrder) {
  for (int n = 0; n <= 6; ++n) {
    const std::vector<int> v = first_n(n);
    Small s{std::span<const int>(v)};
    EXPECT_EQ(std::move(s).take_vector(), first_n(n));
    EXPECT_TRUE(s.empty());  // NOLINT(bugprone-use-after-move)
  }
}

TEST(SmallVector, EqualityComparesTheValuesOnly) {
  EXPECT_EQ(Small({1, 2}), Small(std::vector<int>{1, 2}));
  EXPECT_FALSE(Small({1, 2}) == Small({1, 2, 3}));
  EXPECT_EQ(Small({1, 2, 3, 4}), Small(std::vector<int>{1, 2, 3, 4}));
  Small shrunk{1, 2, 3, 4, 5};
  shrunk.resize(2);
  EXPECT_EQ(shrunk, Small({1, 2}));
}

TEST(SmallVector, SpacePoints) {
  SmallVector<Point3, 2> s{{1, 2, 3}, {4, 5, 6}};
  s.push_back({7, 8, 9});
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[2], (Point3{7, 8, 9}));
  EXPECT_EQ(s.span().front(), (Point3{1, 2, 3}));
}

}  // namespace
}  // namespace bezier::core
