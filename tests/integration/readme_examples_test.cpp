// Every `curl` example in README.md is sent to the real service, and its answer must be
// the JSON the README shows, so the documentation cannot drift from the service; each
// exchange must also conform to api/openapi.yaml.
#include "tests/support/openapi_validator.hpp"  // first: see there

#include <httplib.h>

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "api/handler.hpp"
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
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].rfind("curl -s localhost:8080", 0) != 0) continue;
    Example ex;
    std::size_t j = i;
    ex.command = lines[j];
    while (!ex.command.empty() && ex.command.back() == '\\' && j + 1 < lines.size()) {
      ex.command.pop_back();
      ex.command += lines[++j];
    }
    // `curl -s localhost:8080/PATH ... -d 'BODY'` (std::regex is avoided: GCC 12 warns
    // inside it under the sanitizers, and the shape is simple).
    const std::string host = "localhost:8080";
    const std::size_t path_at = ex.command.find(host) + host.size();
    const std::size_t body_at = ex.command.find("-d '");
    if (body_at == std::string::npos) continue;
    ex.path = ex.command.substr(path_at, ex.command.find(' ', path_at) - path_at);
    ex.body = ex.command.substr(body_at + 4, ex.command.find('\'', body_at + 4) - body_at - 4);
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
    expect_conforms("POST", ex.path, "application/json", ex.body, r);
    // The whole answer, `stats` included: the kernel rounds every operation the same way
    // on every x86-64 processor (core/base/multiversion.hpp), so its counts are the same
    // wherever it runs.
    EXPECT_EQ(nlohmann::json::parse(r->body), nlohmann::json::parse(ex.expected));
  }
}

TEST(ReadmeExamples, TheRouteTableNamesEveryPostRouteInOrder) {
  // The first screen's table: one line "| `POST /route` | what it answers |" per route.
  std::ifstream file(std::string(BEZIER_SOURCE_DIR) + "/README.md");
  std::vector<std::string> listed;
  const std::string prefix = "| `POST ";
  for (std::string line; std::getline(file, line);) {
    if (line.rfind(prefix, 0) != 0) continue;
    listed.push_back(line.substr(prefix.size(), line.find('`', prefix.size()) - prefix.size()));
  }
  const auto routes = api::post_routes();
  EXPECT_EQ(listed, std::vector<std::string>(routes.begin(), routes.end()));
}

}  // namespace
}  // namespace bezier::test
