// api::parse_json against nlohmann::json::parse as the oracle: the same document for every
// text both accept (compared by nlohmann's own dump, which tells 1 from 1.0), the same
// verdict on every text, except literals beyond the double range, which nlohmann refuses
// as a whole and parse_json keeps as infinities for the field reader to report.

#include "api/parse_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "tests/support/mulberry32.hpp"

namespace {

using bezier::api::parse_json;
using nlohmann::json;

enum class Verdict { accepted, refused, out_of_range };

Verdict nlohmann_verdict(const std::string& text, json& out) {
  try {
    out = json::parse(text);
    return Verdict::accepted;
  } catch (const json::out_of_range&) {
    return Verdict::out_of_range;
  } catch (const json::exception&) {
    return Verdict::refused;
  }
}

// The two parsers agree on `text`; returns whether it was accepted.
bool expect_same_as_nlohmann(const std::string& text) {
  json expected;
  const Verdict verdict = nlohmann_verdict(text, expected);
  const auto ours = parse_json(text);
  if (verdict == Verdict::out_of_range) {
    // nlohmann stops at the literal; whether the rest is valid is unknown to it. Numbers
    // beyond the range are checked in LiteralsBeyondTheDoubleRange... below.
    return ours.ok;
  }
  EXPECT_EQ(ours.ok, verdict == Verdict::accepted) << "text: " << text << "\nour error: " << ours.error;
  if (ours.ok && verdict == Verdict::accepted) {
    EXPECT_EQ(ours.value.dump(), expected.dump()) << "text: " << text;
  }
  return ours.ok;
}

TEST(ParseJson, ValidDocumentsMatchNlohmann) {
  const std::vector<std::string> texts = {
      R"({"points":[[0,0],[1,2.5],[-3e-7,4E+2]],"t":0.5})",
      " \t\r\n[ 1 , -2 , 3.25 , -0 , -0.0 , 0e0 , 1E-2 ] \n",
      R"("plain")", "true", "false", "null", "0", "-1", "12345678901234567890", "18446744073709551615",
      "18446744073709551616", "-9223372036854775808", "-9223372036854775809", "1.7976931348623157e308",
      "4.9e-324", "2.4703282292062327e-324", "0.1", "123456789012345678901234567890.5",
      R"({"a":1,"a":2})", R"({"":{"":[]}})", "[[],[{}],{}]", R"({"b":1,"a":[true,false,null]})",
      R"("\" \\ \/ \b \f \n \r \t \u0000 \u00e9 \u20AC \ud83d\ude00")", "\"caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80\"",
      "\xEF\xBB\xBF{\"bom\":1}", "\"\x7F\"",
  };
  for (const auto& text : texts) EXPECT_TRUE(expect_same_as_nlohmann(text)) << text;
}

TEST(ParseJson, InvalidDocumentsAreRefusedLikeNlohmann) {
  const std::vector<std::string> texts = {
      "", " ", "{", "}", "[1,]", R"({"a":1,})", "[1 2]", R"({"a" 1})", R"({a:1})", "{'a':1}", "01", "-",
      "1.", ".5", "+1", "1e", "1e+", "-01", "0x10", "NaN", "Infinity", "-Infinity", "nul", "tru", "[1]x",
      "[1] [2]", "/* c */ 1", "\"a", "\"\\x\"", "\"\\u12\"", "\"\\u12G4\"", "\"\\ud800\"", "\"\\ud800\\u0041\"",
      "\"\\udc00\"", std::string("\"a\x01\""), "\"\xC0\x80\"", "\"\xC1\xBF\"", "\"\xED\xA0\x80\"",
      "\"\xF5\x80\x80\x80\"", "\"\xF4\x90\x80\x80\"", "\"\xE2\x82\"", "\"\x80\"", "\"\xFF\"", "[1,,2]",
      std::string("[1\x00]", 4), "\"\t\"",
  };
  for (const auto& text : texts) EXPECT_FALSE(expect_same_as_nlohmann(text)) << text;
}

// nlohmann's lexer reads a NUL byte as the end of the text (for C strings), so it accepts
// "{}" followed by NUL and anything; RFC 8259 allows only blanks after the value.
TEST(ParseJson, BytesAfterANulAreStillText) {
  const std::string text("{\"t\":1}\0\0garbage", 15);
  EXPECT_TRUE(json::parse(text, nullptr, /*allow_exceptions=*/false).is_object());
  const auto ours = parse_json(text);
  EXPECT_FALSE(ours.ok);
  EXPECT_EQ(ours.error_offset, 7u);
}

TEST(ParseJson, LiteralsBeyondTheDoubleRangeBecomeSignedInfinityOrZero) {
  const auto big = parse_json(R"([1e999,-1e999,1e-999,-1e-999,123456789e400])");
  ASSERT_TRUE(big.ok);
  EXPECT_EQ(big.value[0].get<double>(), HUGE_VAL);
  EXPECT_EQ(big.value[1].get<double>(), -HUGE_VAL);
  EXPECT_EQ(big.value[2].get<double>(), 0.0);
  EXPECT_FALSE(std::signbit(big.value[2].get<double>()));
  EXPECT_TRUE(std::signbit(big.value[3].get<double>()));
  EXPECT_EQ(big.value[4].get<double>(), HUGE_VAL);
}

TEST(ParseJson, NestingIsBounded) {
  const int max = bezier::api::kMaxJsonDepth;
  EXPECT_TRUE(parse_json(std::string(static_cast<std::size_t>(max), '[') + std::string(static_cast<std::size_t>(max), ']')).ok);
  const auto deep = parse_json(std::string(static_cast<std::size_t>(max) + 1, '[') + std::string(static_cast<std::size_t>(max) + 1, ']'));
  EXPECT_FALSE(deep.ok);
  EXPECT_TRUE(deep.too_deep);
  EXPECT_FALSE(deep.root_is_object);
  EXPECT_TRUE(parse_json(" {\"a\":" + std::string(200, '[')).root_is_object);
  EXPECT_EQ(deep.error_offset, static_cast<std::size_t>(max));
  // A megabyte of brackets (a body at the size limit) is refused without recursing that deep.
  EXPECT_FALSE(parse_json(std::string(1 << 20, '[')).ok);
}

TEST(ParseJson, ReportsTheOffsetOfTheFirstOffendingByte) {
  const auto missing = parse_json(R"({"a":})");
  EXPECT_FALSE(missing.ok);
  EXPECT_EQ(missing.error_offset, 5u);
  EXPECT_FALSE(missing.error.empty());
  const auto trailing = parse_json("[1] x");
  EXPECT_EQ(trailing.error_offset, 4u);
}

TEST(ParseJson, NumbersRoundTheWayStrtodDoes) {
  // Correctly rounded conversion: every double written with 17 significant digits reads
  // back to itself, including subnormals and the largest finite value.
  bezier::test::Mulberry32 random(7);
  for (int i = 0; i < 20000; ++i) {
    const std::uint64_t bits = (static_cast<std::uint64_t>(random.next() * 4294967296.0) << 32) |
                               static_cast<std::uint64_t>(random.next() * 4294967296.0);
    double d = 0.0;
    std::memcpy(&d, &bits, sizeof d);
    if (!std::isfinite(d)) continue;
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", d);
    const auto parsed = parse_json(text);
    ASSERT_TRUE(parsed.ok) << text;
    EXPECT_EQ(parsed.value.get<double>(), d) << text;
  }
}

// Random texts over JSON's own alphabet: mostly invalid, some valid, many nearly valid.
TEST(ParseJson, RandomTextsGetNlohmannsVerdict) {
  static constexpr std::string_view kAlphabet = "{}[]\",:0123456789.eE+- \ntrufalsn\\u/bA\xC3\xA9\xE2\x82";
  bezier::test::Mulberry32 random(20261201);
  int accepted = 0;
  for (int i = 0; i < 60000; ++i) {
    const int length = 1 + static_cast<int>(random.next() * 12);
    std::string text;
    for (int k = 0; k < length; ++k) text += kAlphabet[static_cast<std::size_t>(random.next() * kAlphabet.size())];
    accepted += expect_same_as_nlohmann(text) ? 1 : 0;
  }
  EXPECT_GT(accepted, 100);  // the comparison exercised the accepting paths too
}

}  // namespace
