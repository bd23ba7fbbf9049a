// api::JsonWriter: the text of a nested answer is dump_json's text of the same document,
// separators included, and a non-finite number marks the answer as not sendable.

#include "api/json_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>

#include "api/dump_json.hpp"

namespace {

using bezier::api::JsonWriter;
using nlohmann::json;

TEST(JsonWriter, WritesTheTextOfTheSameDocument) {
  JsonWriter w;
  w.begin_object();
  w.key("a").begin_array().end_array();
  w.key("b").begin_array();
  for (int i = 0; i < 3; ++i) w.begin_object().key("k").value(i).key("p").pair(0.1 * i, -1e-300).end_object();
  w.end_array();
  w.key("c").begin_object().end_object();
  w.key("d \"quoted\"").value("caf\xC3\xA9\n");
  w.key("e").value(true).key("f").value(std::int64_t{-9007199254740993});
  w.key("g").begin_array().begin_array().value(1.0).end_array().value(false).end_array();
  w.end_object();
  ASSERT_TRUE(w.all_finite());
  const std::string text = std::move(w).take();
  const json expected = {
      {"a", json::array()},
      {"b", {{{"k", 0}, {"p", {0.0, -1e-300}}}, {{"k", 1}, {"p", {0.1, -1e-300}}}, {{"k", 2}, {"p", {0.2, -1e-300}}}}},
      {"c", json::object()},
      {"d \"quoted\"", "caf\xC3\xA9\n"},
      {"e", true},
      {"f", std::int64_t{-9007199254740993}},
      {"g", {{1.0}, false}},
  };
  EXPECT_EQ(text, bezier::api::dump_json(expected));
  EXPECT_EQ(json::parse(text), expected);
}

TEST(JsonWriter, NonFiniteNumbersMarkTheAnswer) {
  for (const double bad : {HUGE_VAL, -HUGE_VAL, std::nan("")}) {
    JsonWriter w;
    w.begin_array().value(1.0).value(bad).end_array();
    EXPECT_FALSE(w.all_finite());
    EXPECT_EQ(w.first_non_finite_pointer(), "/1");
    EXPECT_EQ(std::move(w).take(), "[1.0,null]");
  }
}

TEST(JsonWriter, PointerOfTheFirstNonFiniteNumber) {
  // Closed containers before it, strings holding brackets, commas, colons and quotes, and
  // a second non-finite number after it do not move the pointer.
  JsonWriter w;
  w.begin_object();
  w.key("a").begin_array().value(1.0).begin_object().key("x").value(2.0).end_object().end_array();
  w.key("b \"[,:").value("],{\"");
  w.key("c").begin_array();
  w.begin_object().key("p").pair(0.0, 1.0).end_object();
  w.begin_object().key("d").begin_array().end_array().key("p").pair(2.0, HUGE_VAL).end_object();
  w.end_array();
  w.key("e").value(std::nan(""));
  w.end_object();
  ASSERT_FALSE(w.all_finite());
  EXPECT_EQ(w.first_non_finite_pointer(), "/c/1/p/1");
  JsonWriter bare;
  bare.value(-HUGE_VAL);
  EXPECT_EQ(bare.first_non_finite_pointer(), "");
  JsonWriter member;
  member.begin_object().key("k").value(1.0).key("m").value(HUGE_VAL).end_object();
  EXPECT_EQ(member.first_non_finite_pointer(), "/m");
}

}  // namespace
