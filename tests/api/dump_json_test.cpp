// api::dump_json against nlohmann's dump as the oracle: the same text for documents of
// every kind, numbers that read back to the same double, and invalid UTF-8 replaced (byte by
// byte; nlohmann sometimes folds a sequence into one U+FFFD).

#include "api/dump_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>

#include "tests/support/mulberry32.hpp"

namespace {

using bezier::api::dump_json;
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

}  // namespace
