// Merging the search's boxes into contacts (merge.hpp): a high-order contact at an end,
// whose boxes at the precision floor leave holes, is one contact at the exact root.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "core/base/curve.hpp"
#include "core/curve/evaluate.hpp"
#include "core/intersect/intersect.hpp"
#include "tests/support/exact.hpp"
#include "tests/support/intersection_checks.hpp"

namespace bezier::core {
namespace {

using test::covered;
using test::exact_point;
using test::expect_intersection_contract;
using test::expect_no_common_point;
using test::expect_one_exact_end_root;
using test::for_every_option;
using test::on_parabola;
using test::RationalPoint;

// The curve g touches the segment f at f's end with third-order
// contact (P0, P1, P2 of g on the line y = 1, so g's y is 1 − s^3): one contact, f(1) = g(0)
// exactly, where f' = (−2, 0) and g'(0) = 3 (P1 − P0) are parallel and nonzero (tangent). The
// curves agree to within rounding along a stretch next to it, where the search leaves boxes at
// the precision floor with holes between them: two (unresolved) contacts 7e-6 apart, placed
// differently in the two orders. The answer: one contact, at the exact root, in both orders.
TEST(Merge, HighOrderContactIsReportedOnce) {
  const Curve f({{1.0, 1.0}, {-1.0, 1.0}});
  const Curve g({{-1.0, 1.0}, {0x1.fc38p+6, 1.0}, {-1.0, 1.0}, {0.0, 0.0}});
  expect_one_exact_end_root(f, g, 1.0, 0.0, IntersectionKind::tangent);
}

}  // namespace
}  // namespace bezier::core
