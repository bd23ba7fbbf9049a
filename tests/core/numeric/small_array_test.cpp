#include "core/numeric/small_array.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <span>
#include <utility>
#include <vector>

#include "core/base/point.hpp"
#include "core/numeric/error_free.hpp"

namespace bezier::core {
namespace {

using Array = SmallArray<double>;
constexpr std::size_t kInline = Array::kInline;

// Whether the entries live inside the object (inline) rather than on the heap.
template <class T>
bool stored_inline(const SmallArray<T>& a) {
  const auto begin = reinterpret_cast<std::uintptr_t>(&a);
  const auto d = reinterpret_cast<std::uintptr_t>(a.data());
  return d >= begin && d < begin + sizeof(a);
}

Array iota(std::size_t n, double first) {
  Array a(n);
  for (std::size_t i = 0; i < n; ++i) a[i] = first + static_cast<double>(i);
  return a;
}

void expect_iota(const Array& a, std::size_t n, double first) {
  ASSERT_EQ(a.size(), n);
  for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(a[i], first + static_cast<double>(i)) << i;
}

TEST(SmallArray, InlineCapacityIsTheTuningConstant) {
  static_assert(kInline == numeric_tuning::kInlineEntries);
}

TEST(SmallArray, SwitchesToTheHeapAboveKInline) {
  const Array at(kInline, 1.5), above(kInline + 1, 2.5), empty;
  EXPECT_TRUE(stored_inline(at));
  EXPECT_FALSE(stored_inline(above));
  EXPECT_TRUE(empty.empty());
  EXPECT_EQ(empty.size(), 0u);
  for (const double v : at) EXPECT_EQ(v, 1.5);
  for (const double v : above) EXPECT_EQ(v, 2.5);
  EXPECT_EQ(at.end() - at.begin(), static_cast<std::ptrdiff_t>(kInline));
  EXPECT_EQ(above.end() - above.begin(), static_cast<std::ptrdiff_t>(kInline + 1));
}

TEST(SmallArray, ResizeFillsEveryEntryAcrossTheSwitch) {
  Array a(3, 1.0);
  a.resize(kInline + 4, 2.0);
  EXPECT_FALSE(stored_inline(a));
  for (const double v : a) EXPECT_EQ(v, 2.0);
  a.resize(kInline, 3.0);
  EXPECT_TRUE(stored_inline(a));
  ASSERT_EQ(a.size(), kInline);
  for (const double v : a) EXPECT_EQ(v, 3.0);
  a.resize(0);
  EXPECT_TRUE(a.empty());
}

TEST(SmallArray, UninitializedHeapEntriesAreValueInitialised) {
  const Array a(kInline + 7, Array::Uninitialized{});
  ASSERT_EQ(a.size(), kInline + 7);
  for (const double v : a) EXPECT_EQ(v, 0.0);
}

TEST(SmallArray, UninitializedEntriesHoldWhatIsWritten) {
  for (const std::size_t n : {std::size_t{1}, kInline, kInline + 1, 3 * kInline}) {
    Array a(n, Array::Uninitialized{});
    for (std::size_t i = 0; i < n; ++i) a[i] = static_cast<double>(i) * 0.5;
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(a[i], static_cast<double>(i) * 0.5);
    EXPECT_EQ(a.back(), static_cast<double>(n - 1) * 0.5);
  }
  // Entries whose type has default member initialisers (Point2 is {0, 0}) are not
  // written by an Uninitialized array, but hold what is stored in them.
  SmallArray<TwoTerm<Point2>> p(5, SmallArray<TwoTerm<Point2>>::Uninitialized{});
  for (std::size_t i = 0; i < 5; ++i) p[i] = {{1.0 * i, 2.0}, {3.0, 4.0 * i}};
  EXPECT_EQ(p[4].hi.x, 4.0);
  EXPECT_EQ(p[4].lo.y, 16.0);
}

TEST(SmallArray, SpanConstructionAndConversion) {
  for (const std::size_t n : {std::size_t{0}, std::size_t{3}, kInline, kInline + 9}) {
    std::vector<double> v(n);
    std::iota(v.begin(), v.end(), 10.0);
    const Array a{std::span<const double>(v)};
    expect_iota(a, n, 10.0);
    const std::span<const double> s = a;
    EXPECT_EQ(s.data(), a.data());
    EXPECT_EQ(s.size(), n);
  }
  Array m = iota(4, 0.0);
  for (double& x : m.span()) x *= 2;
  EXPECT_EQ(m[3], 6.0);
}

TEST(SmallArray, CopiesAreDeepOnBothSidesOfTheSwitch) {
  for (const std::size_t n : {std::size_t{5}, kInline + 5}) {
    const Array original = iota(n, 1.0);
    Array copy(original);
    copy[0] = -1.0;
    expect_iota(original, n, 1.0);
    EXPECT_EQ(copy[0], -1.0);
    EXPECT_NE(copy.data(), original.data());
    EXPECT_EQ(copy[n - 1], original[n - 1]);
  }
}

TEST(SmallArray, CopyAssignmentBetweenInlineAndHeapSizes) {
  const Array small = iota(4, 100.0), large = iota(kInline + 3, 200.0);
  Array a = iota(kInline + 10, 0.0);  // heap-sized, then assigned a short array
  a = small;
  expect_iota(a, 4, 100.0);
  EXPECT_TRUE(stored_inline(a));
  a = large;  // and back to the heap
  expect_iota(a, kInline + 3, 200.0);
  EXPECT_FALSE(stored_inline(a));
  a[0] = 0.0;
  EXPECT_EQ(large[0], 200.0);
  Array& self = a;
  a = self;  // self-assignment keeps the entries
  EXPECT_EQ(a[1], 201.0);
  EXPECT_EQ(a.size(), kInline + 3);
}

TEST(SmallArray, MovesCarryTheEntries) {
  for (const std::size_t n : {std::size_t{6}, kInline + 6}) {
    Array source = iota(n, 7.0);
    const double* heap_data = source.data();
    Array moved(std::move(source));
    expect_iota(moved, n, 7.0);
    // The source is left empty, not claiming entries it no longer owns.
    EXPECT_TRUE(source.empty());  // NOLINT(bugprone-use-after-move): the state after a move
    EXPECT_EQ(source.begin(), source.end());  // NOLINT(bugprone-use-after-move)
    if (n > kInline) {
      EXPECT_EQ(moved.data(), heap_data);  // the heap block changes owner
    }
    Array target = iota(2, 0.0);
    target = std::move(moved);
    expect_iota(target, n, 7.0);
    EXPECT_TRUE(moved.empty());  // NOLINT(bugprone-use-after-move): the state after a move
    // A moved-from array can be assigned again and used.
    moved = iota(3, 1.0);
    expect_iota(moved, 3, 1.0);
  }
}

}  // namespace
}  // namespace bezier::core
