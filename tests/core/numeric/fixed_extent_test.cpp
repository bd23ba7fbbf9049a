// with_fixed_extent: the sizes of lines, quadratics and cubics become compile-time constants,
// every other size takes the dynamic extent (the generic path), and the span it builds views
// the same values. (That the fixed-extent bodies compute bit for bit what the generic ones
// did is checked on the shared benchmark's 20000 pairs by dumping every result with
// bezier_intersection_dump; here, what the dispatch itself promises.)

#include "core/numeric/fixed_extent.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <span>

namespace bezier::core {
namespace {

TEST(FixedExtent, SizesTwoToFourAreCompileTimeConstants) {
  for (std::size_t size = 2; size <= 4; ++size) {
    const std::size_t extent = with_fixed_extent(size, [](auto e) { return decltype(e)::value; });
    EXPECT_EQ(extent, size);
  }
}

TEST(FixedExtent, OtherSizesAreDynamic) {
  for (const std::size_t size : {0u, 1u, 5u, 8u, 24u, 25u}) {
    const std::size_t extent = with_fixed_extent(size, [](auto e) { return decltype(e)::value; });
    EXPECT_EQ(extent, std::dynamic_extent) << size;
  }
}

TEST(FixedExtent, SpanViewsTheSameValues) {
  const std::array<double, 4> values = {0.5, -0.25, 0.125, 1.0};
  for (std::size_t size = 1; size <= values.size(); ++size) {
    const double sum = with_fixed_extent(size, [&](auto e) {
      const std::span<const double, decltype(e)::value> s =
          fixed_span<decltype(e)::value>(values.data(), size);
      EXPECT_EQ(s.size(), size);
      EXPECT_EQ(s.data(), values.data());
      double total = 0.0;
      for (const double v : s) total += v;
      return total;
    });
    double expected = 0.0;
    for (std::size_t i = 0; i < size; ++i) expected += values[i];
    EXPECT_EQ(sum, expected) << size;
  }
}

}  // namespace
}  // namespace bezier::core
