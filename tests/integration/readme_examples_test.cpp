// Every `curl` example in README.md is sent to the real service, and its answer must be
// the JSON the README shows, so the documentation cannot drift from the service.
#include <httplib.h>

#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/service_process.hpp"

namespace bezier::test {
namespace {

struct Example {
  std::string command;   // the curl command, continuation lines joined
  std::string path;      // e.g. /evaluate
  std::string body;      // the -d argument
  std::string expected;  // the ```json block that follows
};

std::vector<Example> readme_examples() {
  std::ifstream file(std::string(BEZIER_SOURCE_DIR) + "/README.md");
  std::vector<std::string> lines;
  for (std::string line; std::getline(file, line);) lines.push_back(line);
  std::vector<Example> examples;
  const std::regex curl_re(R"(curl -s localhost:8080(/[a-z-]*) .*-d '([^']*)')");
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind("curl -s localhost:8080", 0) != 0) continue;
    Example ex;
    std::size_t j = i;
    ex.command = lines[j];
    while (!ex.command.empty() && ex.command.back() == '\\' && j + 1 < lines.size()) {
      ex.command.pop_back();
      ex.command += lines[++j];
    }
    std::smatch m;
    if (!std::regex_search(ex.command, m, curl_re)) continue;
    ex.path = m[1];
    ex.body = m[2];
    // The answer block: ``` then ```json on the following lines.
    if (j + 2 < lines.size() && lines[j + 1] == "```" && lines[j + 2] == "```json") {
      for (std::size_t k = j + 3; k < lines.size() && lines[k] != "```"; ++k) ex.expected += lines[k] + "\n";
    }
    examples.push_back(ex);
  }
  return examples;
}

TEST(ReadmeExamples, EveryCurlExampleGivesTheDocumentedAnswer) {
  const auto examples = readme_examples();
  ASSERT_GE(examples.size(), 3u) << "README examples not found";
  ServiceProcess service;
  httplib::Client client("127.0.0.1", service.port());
  for (const auto& ex : examples) {
    SCOPED_TRACE(ex.command);
    ASSERT_FALSE(ex.expected.empty()) << "no ```json answer after the example";
    const auto r = client.Post(ex.path.c_str(), ex.body, "application/json");
    ASSERT_TRUE(r);
    EXPECT_EQ(nlohmann::json::parse(r->body), nlohmann::json::parse(ex.expected));
  }
}

}  // namespace
}  // namespace bezier::test
