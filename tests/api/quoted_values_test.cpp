// A problem quotes at most a short excerpt of what the request sent: a megabyte of digits or
// a member name of any length is not echoed back (once in `detail`, again in `errors`).

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "api/handler.hpp"

namespace bezier::api {
namespace {

using nlohmann::json;

constexpr std::string_view kEllipsis = "\xE2\x80\xA6";

TEST(QuotedValues, AHugeNumberInAPathIsQuotedShort) {
  const std::string digits(100000, '9');
  const Reply reply = handle("/bounds", R"({"path":"M0 0 L)" + digits + R"( 0"})", Limits{});
  ASSERT_EQ(reply.status, 422) << reply.body.substr(0, 300);
  EXPECT_LT(reply.body.size(), 1000u) << reply.body.substr(0, 300);
  const json problem = json::parse(reply.body);
  const std::string message = problem["errors"][0]["message"];
  EXPECT_NE(message.find("the number " + std::string(64, '9') + std::string(kEllipsis) + " is beyond"),
            std::string::npos)
      << message;
  EXPECT_EQ(problem["errors"][0]["pointer"], "/path");
}

TEST(QuotedValues, ALongMemberNameIsWholeInErrorsAndShortInTheDetail) {
  const std::string name(5000, 'x');
  const Reply reply = handle("/evaluate", R"({"points":[[0,0],[1,1]],"t":0.5,")" + name + R"(":1})", Limits{});
  ASSERT_EQ(reply.status, 422);
  const json problem = json::parse(reply.body);
  // The pointer a client matches stays whole.
  EXPECT_EQ(problem["errors"][0]["pointer"], "/" + name);
  EXPECT_EQ(problem["detail"], "'/" + std::string(63, 'x') + std::string(kEllipsis) + "': unknown field");
}

TEST(QuotedValues, ACutNeverSplitsACharacter) {
  // 'é' is two bytes: the 64-byte cut falls inside one and backs off to its start.
  std::string name = "xx";
  for (int i = 0; i < 40; ++i) name += "\xC3\xA9";
  const Reply reply = handle("/evaluate", R"({"points":[[0,0],[1,1]],"t":0.5,")" + name + R"(":1})", Limits{});
  ASSERT_EQ(reply.status, 422);
  const json problem = json::parse(reply.body);
  std::string expected = "'/xx";
  for (int i = 0; i < 30; ++i) expected += "\xC3\xA9";
  EXPECT_EQ(problem["detail"], expected + std::string(kEllipsis) + "': unknown field");
}

}  // namespace
}  // namespace bezier::api
