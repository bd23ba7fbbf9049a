// The listening socket: a second process on a port the service listens on fails at
// start-up, and every event loop takes connections from the one socket they share.
#include <string>

#include <gtest/gtest.h>

#include "tests/support/child_process.hpp"
#include "tests/support/raw_http.hpp"
#include "tests/support/service_process.hpp"

namespace bezier::test {
namespace {

bool healthy(int port) {
  return raw_exchange(port, "GET /healthz HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
             .rfind("HTTP/1.1 200 OK\r\n", 0) == 0;
}

TEST(Listener, ASecondProcessOnTheSamePortFailsAtStartUp) {
  ServiceProcess first({"--io-threads", "2"});
  const std::string port = std::to_string(first.port());
  // Bound by the first, the port must be refused to the second: were it admitted (a
  // reuseport group), the second would serve until killed at the limit.
  const ProgramRun second =
      run_program({BEZIER_SERVICE_BINARY, "--host", "127.0.0.1", "--port", port, "--io-threads", "2"}, {},
                  std::chrono::seconds(10));
  ASSERT_TRUE(second.exit_code.has_value()) << "the second process kept running:\n" << second.output;
  EXPECT_NE(*second.exit_code, 0);
  EXPECT_NE(second.output.find("cannot listen on 127.0.0.1:" + port + ": Address already in use"),
            std::string::npos)
      << second.output;
  EXPECT_EQ(second.output.find("listening on"), std::string::npos) << second.output;
  // The JSON format says it as one JSON line too.
  const ProgramRun second_json = run_program(
      {BEZIER_SERVICE_BINARY, "--host", "127.0.0.1", "--port", port, "--log-format", "json"}, {},
      std::chrono::seconds(10));
  ASSERT_TRUE(second_json.exit_code.has_value()) << second_json.output;
  EXPECT_NE(*second_json.exit_code, 0);
  EXPECT_NE(second_json.output.find(R"("level":"critical","msg":"cannot listen on 127.0.0.1:)" + port),
            std::string::npos)
      << second_json.output;
  // The first is unharmed.
  EXPECT_TRUE(healthy(first.port()));
}

TEST(Listener, EveryLoopServesFromTheSharedSocket) {
  // More loops than this test has connections open at once: each connection is served
  // by whichever loop accepted it, and none is lost between them.
  ServiceProcess service({"--io-threads", "4"});
  int answered = 0;
  for (int i = 0; i < 200; ++i) answered += healthy(service.port()) ? 1 : 0;
  EXPECT_EQ(answered, 200);
}

}  // namespace
}  // namespace bezier::test
