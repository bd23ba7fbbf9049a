// EnumNames (enum_names.hpp) on an enumeration of its own, and the names of the kernel's
// enumerations against their spelling in the API contract (api/openapi.yaml), one value
// at a time, so a table listed out of its enumeration's order fails.

#include "core/base/enum_names.hpp"

#include <gtest/gtest.h>

#include "core/cubic/cubic_type.hpp"
#include "core/intersect/result.hpp"
#include "core/self_intersect/self_intersection.hpp"

namespace bezier::core {
namespace {

enum class Colour { red, green, blue };
constexpr EnumNames<Colour::blue> kColourNames{"red", "green", "blue"};

TEST(EnumNames, NamesEachEnumeratorByItsPosition) {
  EXPECT_EQ(kColourNames(Colour::red), "red");
  EXPECT_EQ(kColourNames(Colour::green), "green");
  EXPECT_EQ(kColourNames(Colour::blue), "blue");
  static_assert(EnumNames<Colour::blue>::kCount == 3);
}

TEST(EnumNames, CubicTypeIsSpelledAsTheContractSays) {
  EXPECT_EQ(to_string(CubicType::point), "point");
  EXPECT_EQ(to_string(CubicType::line), "line");
  EXPECT_EQ(to_string(CubicType::quadratic), "quadratic");
  EXPECT_EQ(to_string(CubicType::cusp), "cusp");
  EXPECT_EQ(to_string(CubicType::loop), "loop");
  EXPECT_EQ(to_string(CubicType::loop_at_start), "loop-at-start");
  EXPECT_EQ(to_string(CubicType::loop_at_end), "loop-at-end");
  EXPECT_EQ(to_string(CubicType::double_inflection), "double-inflection");
  EXPECT_EQ(to_string(CubicType::single_inflection), "single-inflection");
  EXPECT_EQ(to_string(CubicType::arch), "arch");
}

TEST(EnumNames, LoopBlinnClassIsSpelledAsTheContractSays) {
  EXPECT_EQ(to_string(LoopBlinnClass::serpentine), "serpentine");
  EXPECT_EQ(to_string(LoopBlinnClass::cusp), "cusp");
  EXPECT_EQ(to_string(LoopBlinnClass::loop), "loop");
  EXPECT_EQ(to_string(LoopBlinnClass::quadratic), "quadratic");
  EXPECT_EQ(to_string(LoopBlinnClass::line), "line");
  EXPECT_EQ(to_string(LoopBlinnClass::point), "point");
}

TEST(EnumNames, IntersectionVocabularyIsSpelledAsTheContractSays) {
  EXPECT_EQ(to_string(IntersectionKind::transversal), "transversal");
  EXPECT_EQ(to_string(IntersectionKind::tangent), "tangent");
  EXPECT_EQ(to_string(IntersectionKind::degenerate), "degenerate");
  EXPECT_EQ(to_string(IntersectMethod::hybrid), "hybrid");
  EXPECT_EQ(to_string(IntersectMethod::bezier_clipping), "bezier-clipping");
  EXPECT_EQ(to_string(IntersectMethod::subdivision), "subdivision");
}

TEST(EnumNames, SelfIntersectionMethodIsSpelledAsTheContractSays) {
  EXPECT_EQ(to_string(SelfIntersectionMethod::closed_form_cubic), "closed-form-cubic");
  EXPECT_EQ(to_string(SelfIntersectionMethod::subdivision), "subdivision");
  EXPECT_EQ(to_string(SelfIntersectionMethod::collinear), "collinear");
}

}  // namespace
}  // namespace bezier::core
