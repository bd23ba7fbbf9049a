#include "core/evaluate.hpp"

#include <gtest/gtest.h>

namespace bezier::core {
namespace {

TEST(Evaluate, EndPointsExact) {
  const Curve c({{0.1, 0.2}, {1.3, 2.7}, {3.3, -0.7}});
  EXPECT_EQ(evaluate(c, 0.0), (Point2{0.1, 0.2}));
  EXPECT_EQ(evaluate(c, 1.0), (Point2{3.3, -0.7}));
}

}  // namespace
}  // namespace bezier::core
