// The log output of the binary: with --log-format json every line it writes (stdout and
// stderr) is one JSON object in valid UTF-8, whatever bytes clients send; the start-up
// line tells where it listens, its version and whether a token is required; access lines
// give the client's address and the bytes of each answer.
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/child_process.hpp"
#include "tests/support/raw_http.hpp"

namespace bezier::test {
namespace {

using nlohmann::json;

// The version of project() in the top-level CMakeLists.txt, read from the file.
std::string project_version() {
  std::ifstream in(std::string(BEZIER_SOURCE_DIR) + "/CMakeLists.txt");
  std::stringstream text;
  text << in.rdbuf();
  const std::string content = text.str();
  const std::string marker = " VERSION ";
  const auto project = content.find("project(");
  const auto start = content.find(marker, project);
  if (project == std::string::npos || start == std::string::npos) return "?";
  const auto begin = start + marker.size();
  return content.substr(begin, content.find_first_not_of("0123456789.", begin) - begin);
}

// The port of the "listening on http://127.0.0.1:PORT" text in the output.
int listening_port(const std::string& output) {
  const std::string prefix = "listening on http://127.0.0.1:";
  const auto start = output.find(prefix);
  if (start == std::string::npos) return -1;
  return std::stoi(output.substr(start + prefix.size()));
}

// The line of `output` that contains `text`, or "".
std::string line_with(const std::string& output, const std::string& text) {
  const auto at = output.find(text);
  if (at == std::string::npos) return {};
  const auto begin = output.rfind('\n', at);
  const auto start = begin == std::string::npos ? 0 : begin + 1;
  return output.substr(start, output.find('\n', at) - start);
}

std::vector<std::string> lines_of(const std::string& output) {
  std::vector<std::string> lines;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

struct Sent {
  std::string request;
  std::string answer;  ///< every byte the service sent back
};

// Runs the service with `args` and `env`, makes `requests` (each on its own connection,
// read to its end), stops it with SIGTERM; its whole output and what each request got.
struct Session {
  std::string output;
  std::optional<int> exit_code;
  int port = -1;
  std::vector<Sent> sent;
};

Session run_session(std::vector<std::string> args, std::vector<std::string> env,
                    const std::vector<std::string>& requests) {
  std::vector<std::string> command = {BEZIER_SERVICE_BINARY, "--host", "127.0.0.1", "--port", "0"};
  command.insert(command.end(), args.begin(), args.end());
  ChildProcess service(command, std::move(env));
  Session session;
  if (!service.wait_for_output("listening on")) return session;
  service.wait_for_output("\n");  // the whole line
  session.port = listening_port(service.output());
  for (const std::string& request : requests) session.sent.push_back({request, raw_exchange(session.port, request)});
  service.signal(SIGTERM);
  session.exit_code = service.wait_exit();
  session.output = service.output();
  return session;
}

const std::string kEvaluateBody = R"({"points":[[0,0],[1,1]],"t":0.5})";
const std::string kEvaluate = "POST /evaluate HTTP/1.1\r\nHost: x\r\nConnection: close\r\n"
                              "Content-Type: application/json\r\nContent-Length: " +
                              std::to_string(kEvaluateBody.size()) + "\r\n\r\n" + kEvaluateBody;
const std::string kNotFound = "GET /nope HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n";
// A request target that is not UTF-8: FF and FE never occur in UTF-8.
const std::string kNotUtf8 = "GET /\xff\xfe HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n";
// A truncated three-byte sequence and an overlong encoding of '/', then valid UTF-8.
const std::string kBadSequences = "GET /\xe2\x82-\xc0\xaf-\xc3\xa9 HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n";

TEST(ServiceLogs, JsonFormatIsOneValidUtf8JsonObjectPerLine) {
  const Session session = run_session({"--log-format", "json"}, {}, {kEvaluate, kNotFound, kNotUtf8, kBadSequences});
  ASSERT_GT(session.port, 0) << session.output;
  ASSERT_EQ(session.exit_code, std::optional<int>(0)) << session.output;
  std::vector<json> access;
  std::vector<json> entries;
  for (const std::string& line : lines_of(session.output)) {
    // nlohmann::json rejects invalid UTF-8 as well as invalid JSON.
    json entry;
    ASSERT_NO_THROW(entry = json::parse(line)) << line;
    ASSERT_TRUE(entry.is_object()) << line;
    EXPECT_TRUE(entry.contains("time") && entry.contains("level") && entry.contains("msg")) << line;
    if (entry["msg"] == "access") access.push_back(entry);
    entries.push_back(entry);
  }
  ASSERT_FALSE(entries.empty());

  const json& start = entries.front();
  EXPECT_EQ(start["level"], "info");
  EXPECT_EQ(start["msg"], "listening on http://127.0.0.1:" + std::to_string(session.port));
  EXPECT_EQ(start["version"], project_version());
  EXPECT_EQ(start["auth_token_required"], false);

  // One access line per request, in order (one connection at a time), each with the
  // client's address and exactly the bytes the client received.
  ASSERT_EQ(access.size(), session.sent.size()) << session.output;
  const std::vector<std::string> paths = {"/evaluate", "/nope", "/\\xff\\xfe", "/\\xe2\\x82-\\xc0\\xaf-\xc3\xa9"};
  for (std::size_t i = 0; i < access.size(); ++i) {
    EXPECT_EQ(access[i]["client"], "127.0.0.1") << access[i];
    EXPECT_EQ(access[i]["bytes_sent"], session.sent[i].answer.size()) << access[i];
    EXPECT_EQ(access[i]["path"], paths[i]) << access[i];
    EXPECT_EQ(std::to_string(access[i]["status"].get<int>()), session.sent[i].answer.substr(9, 3)) << access[i];
  }
  EXPECT_EQ(access[0]["status"], 200);
  EXPECT_EQ(access[1]["status"], 404);
}

TEST(ServiceLogs, StartUpLineSaysWhetherATokenIsRequired) {
  const Session session = run_session({"--log-format", "json"}, {"BEZIER_AUTH_TOKEN=s3cret-token"}, {});
  ASSERT_GT(session.port, 0) << session.output;
  const json start = json::parse(lines_of(session.output).front());
  EXPECT_EQ(start["auth_token_required"], true);
  EXPECT_EQ(session.output.find("s3cret-token"), std::string::npos) << "the token leaked into the log";
}

TEST(ServiceLogs, StartUpLineIsWrittenAtEveryLogLevel) {
  // Scripts read the port from it, also when the access log is off.
  const Session session = run_session({"--log-format", "json", "--log-level", "off"}, {}, {kNotFound});
  ASSERT_GT(session.port, 0) << session.output;
  const std::vector<std::string> lines = lines_of(session.output);
  ASSERT_EQ(lines.size(), 1u) << session.output;
  EXPECT_EQ(json::parse(lines.front())["version"], project_version());
}

TEST(ServiceLogs, TextAccessLinesGiveTheClientAndTheBytesSent) {
  const Session session = run_session({}, {}, {kNotFound});
  ASSERT_GT(session.port, 0) << session.output;
  // GET /nope 404 0.123ms id=0123abcd client=127.0.0.1 bytes=N
  const std::string access = line_with(session.output, " GET /nope 404 ");
  ASSERT_FALSE(access.empty()) << session.output;
  EXPECT_NE(access.find("ms id="), std::string::npos) << access;
  const std::string tail = " client=127.0.0.1 bytes=" + std::to_string(session.sent[0].answer.size());
  ASSERT_GE(access.size(), tail.size());
  EXPECT_EQ(access.substr(access.size() - tail.size()), tail) << access;
  const std::string start = line_with(session.output, "listening on");
  EXPECT_NE(start.find(" info listening on http://127.0.0.1:" + std::to_string(session.port) + " version=" +
                       project_version() + " auth_token_required=false"),
            std::string::npos)
      << start;
}

}  // namespace
}  // namespace bezier::test
