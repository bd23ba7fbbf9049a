// GET /metrics beyond the request counters: Prometheus' standard process metrics, checked
// against what /proc says of the service process; the build's version; the counters of
// work-cap answers and of 503s for want of capacity.
#include <dirent.h>
#include <spawn.h>
#include <sys/wait.h>

#include <ctime>
#include <string>

#include <gtest/gtest.h>

#include "tests/integration/costly_request.hpp"
#include "tests/support/raw_http.hpp"
#include "tests/support/service_process.hpp"

namespace bezier::test {
namespace {

int entries_of(const std::string& directory) {
  DIR* dir = opendir(directory.c_str());
  if (dir == nullptr) return -1;
  int count = 0;
  while (const dirent* entry = readdir(dir)) {
    const std::string name = entry->d_name;
    if (name != "." && name != "..") ++count;
  }
  closedir(dir);
  return count;
}

// What `bezier-service --version` prints, without its trailing newline.
std::string version_output() {
  int out[2];
  if (pipe(out) != 0) return {};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, out[0]);
  std::string binary = BEZIER_SERVICE_BINARY;
  std::string flag = "--version";
  char* argv[] = {binary.data(), flag.data(), nullptr};
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  close(out[1]);
  std::string text;
  char buffer[256];
  for (ssize_t n; rc == 0 && (n = read(out[0], buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
  close(out[0]);
  if (rc == 0) waitpid(pid, nullptr, 0);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text;
}

TEST(Metrics, ProcessMetricsAgreeWithProc) {
  const double spawned_after = static_cast<double>(std::time(nullptr));
  ServiceProcess service({"--io-threads", "1"});
  const double started_before = static_cast<double>(std::time(nullptr)) + 1;

  const double cpu_before = cpu_seconds(service.pid());
  const auto rss = metric(service.port(), "process_resident_memory_bytes");
  const std::int64_t vm_rss = resident_bytes(service.pid());
  const auto cpu = metric(service.port(), "process_cpu_seconds_total");
  const double cpu_after = cpu_seconds(service.pid());
  ASSERT_TRUE(rss && cpu);
  EXPECT_GT(*rss, vm_rss / 2.0);
  EXPECT_LT(*rss, vm_rss * 2.0);
  // /proc/<pid>/stat counts clock ticks, charged to whichever thread a tick finds
  // running; getrusage adds up the threads' own times: they agree to a few ticks.
  const double slack = 5.0 / static_cast<double>(sysconf(_SC_CLK_TCK));
  EXPECT_GE(*cpu, cpu_before - slack);
  EXPECT_LE(*cpu, cpu_after + slack);

  const auto virtual_bytes = metric(service.port(), "process_virtual_memory_bytes");
  ASSERT_TRUE(virtual_bytes);
  EXPECT_GE(*virtual_bytes, *rss);

  // The descriptors: the listener, the epoll and event fds, the log pipe... and the
  // connection of the metrics request itself. /proc/<pid>/fd seen from outside lacks the
  // directory the service opens to count, and may differ by a connection being closed.
  const auto fds = metric(service.port(), "process_open_fds");
  ASSERT_TRUE(fds);
  const int seen = entries_of("/proc/" + std::to_string(service.pid()) + "/fd");
  EXPECT_GE(*fds, seen - 2);
  EXPECT_LE(*fds, seen + 2);
  const auto max_fds = metric(service.port(), "process_max_fds");
  ASSERT_TRUE(max_fds);
  EXPECT_GE(*max_fds, *fds);

  // Start time: Unix seconds, between the spawn and the listening line (boot time in
  // /proc/stat is whole seconds, hence a second either way).
  const auto start = metric(service.port(), "process_start_time_seconds");
  ASSERT_TRUE(start);
  EXPECT_GE(*start, spawned_after - 1);
  EXPECT_LE(*start, started_before + 1);
}

TEST(Metrics, BuildInfoCarriesTheVersion) {
  ServiceProcess service;
  const std::string version = version_output();  // "bezier-service X.Y.Z"
  const std::size_t space = version.rfind(' ');
  ASSERT_NE(space, std::string::npos) << version;
  EXPECT_EQ(metric(service.port(), R"(bezier_build_info{version=")" + version.substr(space + 1) + R"("})"), 1);
}

TEST(Metrics, EachSpecRouteHasItsOwnLabel) {
  ServiceProcess service;
  const std::string json_200 = R"(bezier_requests_total{route="/openapi.json",status="200"})";
  const std::string yaml_200 = R"(bezier_requests_total{route="/openapi.yaml",status="200"})";
  const std::string segments_200 = R"(bezier_requests_total{route="/segments",status="200"})";
  EXPECT_EQ(metric(service.port(), json_200).value_or(0), 0);  // a series appears at its first count
  EXPECT_EQ(status_of(round_trip(service.port(), get_request("/openapi.json"))), 200);
  EXPECT_EQ(status_of(round_trip(service.port(), post_request("/segments", R"({"path":"M0 0 L1 1"})"))), 200);
  EXPECT_EQ(metric(service.port(), json_200), 1);
  EXPECT_EQ(metric(service.port(), yaml_200).value_or(0), 0);
  EXPECT_EQ(metric(service.port(), segments_200), 1);
}

TEST(Metrics, WorkCapHitsCountOnlyAnswersTheWorkCapDecided) {
  ServiceProcess service({"--threads", "1"});
  EXPECT_EQ(metric(service.port(), "bezier_work_cap_hits_total"), 0);
  const std::string capped = round_trip(service.port(), post_request("/intersections", work_cap_bound_intersections()));
  ASSERT_EQ(status_of(capped), 422) << capped;
  EXPECT_EQ(metric(service.port(), "bezier_work_cap_hits_total"), 1);
  // A degree above --max-degree is refused by a limit too, but not by the work cap; and
  // requests the inline try could not finish but the full limits did are not counted.
  std::string degree_21 = R"({"points":[)";
  for (int i = 0; i <= 21; ++i) degree_21 += (i == 0 ? "[" : ",[") + std::to_string(i) + ",0]";
  degree_21 += R"(],"t":0.5})";
  EXPECT_EQ(status_of(round_trip(service.port(), post_request("/evaluate", degree_21))), 422);
  std::string degree_9 = R"({"points":[)";
  for (int i = 0; i <= 9; ++i) degree_9 += (i == 0 ? "[" : ",[") + std::to_string(i) + ",0]";
  degree_9 += R"(],"t":0.5})";
  EXPECT_EQ(status_of(round_trip(service.port(), post_request("/evaluate", degree_9))), 200);
  EXPECT_EQ(metric(service.port(), "bezier_work_cap_hits_total"), 1);
}

TEST(Metrics, ConnectionsBeyondTheLimitAreCountedAsOverload) {
  ServiceProcess service({"--max-connections", "2", "--io-threads", "1"});
  Connection held(service.port());
  ASSERT_TRUE(held.send_all(get_request("/healthz")));
  ASSERT_EQ(held.responses(1).size(), 1u);
  // The metrics request is the second connection; a third one, made while it is open, is refused.
  Connection metrics_connection(service.port());
  Connection refused(service.port());
  const auto answers = refused.responses(1);
  ASSERT_EQ(answers.size(), 1u);
  expect_problem(answers[0], 503);
  ASSERT_TRUE(metrics_connection.send_all(get_request("/metrics")));
  const auto metrics = metrics_connection.responses(1);
  ASSERT_EQ(metrics.size(), 1u);
  EXPECT_NE(body_of(metrics[0]).find("\nbezier_overload_responses_total{reason=\"connections\"} 1\n"),
            std::string::npos)
      << body_of(metrics[0]);
}

}  // namespace
}  // namespace bezier::test
