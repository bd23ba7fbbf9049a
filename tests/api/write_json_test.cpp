// api/write_json: dump_json against nlohmann's dump as the oracle (the same text for
// documents of every kind, numbers that read back to the same double, invalid UTF-8
// replaced byte by byte where nlohmann sometimes folds a sequence into one U+FFFD), and
// JsonWriter's text of a nested answer held to dump_json's text of the same document,
// separators included, a non-finite number marking the answer as not sendable.

#include "api/write_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "tests/support/mulberry32.hpp"

namespace {

using bezier::api::dump_json;
using bezier::api::JsonWriter;
using nlohmann::json;

std::string nlohmann_dump(const json& value) {
  return value.dump(-1, ' ', false, json::error_handler_t::replace);
}

TEST(DumpJson, DocumentsAreWrittenAsNlohmannWritesThem) {
  const json documents[] = {
      json::parse(R"({"b":[1,-2,3.5,true,false,null],"a":{"":"x","k":[[],{}]}})"),
      json::parse(R"("\" \\ / \b \f \n \r \t \u0001 \u001f \u007f é € 😀")"),
      json(std::numeric_limits<std::int64_t>::min()), json(std::numeric_limits<std::uint64_t>::max()),
      json::array({1.0, 100.0, 0.5, 0.001, 0.0001, 0.00001, 1e15, 1e16, 123456.789, 1.5e20, -2.5e-300,
                   0.0, -0.0, 4.9e-324, 1.7976931348623157e308, 1e21, 1e-7, 0.1, 1.0 / 3.0}),
      json::array({std::nan(""), HUGE_VAL, -HUGE_VAL}),
  };
  for (const json& d : documents) EXPECT_EQ(dump_json(d), nlohmann_dump(d));
}

TEST(DumpJson, EveryDoubleReadsBackToItselfInNlohmannsLayout) {
  bezier::test::Mulberry32 random(11);
  int same_text = 0, total = 0;
  for (int i = 0; i < 50000; ++i) {
    const std::uint64_t bits = (static_cast<std::uint64_t>(random.next() * 4294967296.0) << 32) |
                               static_cast<std::uint64_t>(random.next() * 4294967296.0);
    double d = 0.0;
    std::memcpy(&d, &bits, sizeof d);
    // Alternate the raw bit patterns (all magnitudes) with values of ordinary size.
    if (i % 2 == 1) d = std::ldexp(random.next() - 0.5, static_cast<int>(random.next() * 60) - 30);
    if (!std::isfinite(d)) continue;
    const std::string ours = dump_json(json(d));
    EXPECT_EQ(json::parse(ours).get<double>(), d) << ours;
    const std::string theirs = nlohmann_dump(json(d));
    // Both are shortest round-trip digit strings (grisu2 is shortest in nearly every case):
    // never longer than nlohmann's.
    EXPECT_LE(ours.size(), theirs.size()) << ours << " vs " << theirs;
    same_text += ours == theirs ? 1 : 0;
    ++total;
  }
  EXPECT_GE(same_text, total * 99 / 100);
}

TEST(DumpJson, InvalidUtf8IsReplacedAndValidUtf8Kept) {
  const std::string valid = "caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80";
  EXPECT_EQ(dump_json(json(valid)), "\"" + valid + "\"");
  const std::string invalid[] = {"\x80", "a\xFFz", "\xC0\x80", "\xED\xA0\x80", "\xE2\x82", "\xF5\x80\x80\x80"};
  for (const std::string& s : invalid) {
    const std::string ours = dump_json(json(s));
    const json back = json::parse(ours);  // throws on invalid UTF-8
    EXPECT_NE(back.get<std::string>().find("\xEF\xBF\xBD"), std::string::npos) << ours;
  }
  EXPECT_EQ(dump_json(json("a\xFFz")), "\"a\xEF\xBF\xBDz\"");
}

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
  EXPECT_EQ(text, dump_json(expected));
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

TEST(JsonWriter, PointsAreArraysOfTheirCoordinates) {
  const std::vector<bezier::core::Point2> plane = {{0.0, 1.5}, {-2.0, 1e-300}};
  const std::vector<bezier::core::Point3> space = {{1.0, 2.0, 3.0}};
  JsonWriter w;
  w.begin_array();
  bezier::api::write_points(w, std::span<const bezier::core::Point2>(plane));
  bezier::api::write_points(w, std::span<const bezier::core::Point3>(space));
  bezier::api::write_point(w, bezier::core::Point2{4.0, -0.25});
  w.end_array();
  const json expected = json::array({json::array({json::array({0.0, 1.5}), json::array({-2.0, 1e-300})}),
                                     json::array({json::array({1.0, 2.0, 3.0})}), json::array({4.0, -0.25})});
  EXPECT_EQ(std::move(w).take(), dump_json(expected));
}

}  // namespace
