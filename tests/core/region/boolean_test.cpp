#include "core/region/boolean.hpp"

#include <gtest/gtest.h>

#include <string>

#include "tests/support/exact.hpp"
#include "tests/support/exact_polynomial.hpp"
#include "tests/support/parsed_path.hpp"
#include "tests/support/region_checks.hpp"

namespace bezier::region {
namespace {

using test::parsed_path;

constexpr std::int64_t kWork = 100000000;

BooleanResult run(BooleanOperation op, const path::Path& a, const path::Path& b,
                  FillRule rule_a = FillRule::nonzero, FillRule rule_b = FillRule::nonzero) {
  BooleanResult r = boolean_operation(op, {&a, rule_a}, {&b, rule_b}, kWork);
  test::expect_clean(r, a, &b, 1e-9);
  return r;
}

TEST(Boolean, OverlappingSquares) {
  // [0,2]^2 and [1,3]^2: areas 4 and 4, the common square 1.
  const path::Path a = parsed_path("M0 0 H2 V2 H0 Z");
  const path::Path b = parsed_path("M1 1 H3 V3 H1 Z");
  EXPECT_EQ(run(BooleanOperation::union_, a, b).area, 7.0);
  EXPECT_EQ(run(BooleanOperation::intersection, a, b).area, 1.0);
  EXPECT_EQ(run(BooleanOperation::difference, a, b).area, 3.0);
  EXPECT_EQ(run(BooleanOperation::difference, b, a).area, 3.0);
  EXPECT_EQ(run(BooleanOperation::xor_, a, b).area, 6.0);
  EXPECT_EQ(run(BooleanOperation::union_, a, b).contours.size(), 1u);
  EXPECT_EQ(run(BooleanOperation::xor_, a, b).contours.size(), 2u);
}

}  // namespace
}  // namespace bezier::region
