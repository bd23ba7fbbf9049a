// The CPU count that sizes the event loops: cgroup v2 files parsed from given text, and
// the rule that combines the affinity mask with the quota.
#include "service/cpu_budget.hpp"

#include <sched.h>

#include <gtest/gtest.h>

namespace bezier::service {
namespace {

TEST(ParseCpuMax, QuotaOverPeriodIsTheNumberOfCpus) {
  EXPECT_EQ(parse_cpu_max("200000 100000\n"), std::optional<double>(2.0));
  EXPECT_EQ(parse_cpu_max("100000 100000"), std::optional<double>(1.0));
  EXPECT_EQ(parse_cpu_max("150000 100000\n"), std::optional<double>(1.5));
  EXPECT_EQ(parse_cpu_max("50000 100000\n"), std::optional<double>(0.5));
  EXPECT_EQ(parse_cpu_max("250000 1000000\n"), std::optional<double>(0.25));
}

TEST(ParseCpuMax, NoQuotaOrMalformedTextIsNoBound) {
  EXPECT_EQ(parse_cpu_max("max 100000\n"), std::nullopt);
  EXPECT_EQ(parse_cpu_max(""), std::nullopt);  // no such file (cgroup v1, or the root)
  EXPECT_EQ(parse_cpu_max("200000\n"), std::nullopt);
  EXPECT_EQ(parse_cpu_max("0 100000\n"), std::nullopt);
  EXPECT_EQ(parse_cpu_max("200000 0\n"), std::nullopt);
  EXPECT_EQ(parse_cpu_max("-100000 100000\n"), std::nullopt);
  EXPECT_EQ(parse_cpu_max("200000 100000 7\n"), std::nullopt);
  EXPECT_EQ(parse_cpu_max("99999999999999999999 100000\n"), std::nullopt);
}

TEST(ParseCgroupV2Path, TheUnifiedHierarchyLine) {
  EXPECT_EQ(parse_cgroup_v2_path("0::/\n"), std::optional<std::string>("/"));
  EXPECT_EQ(parse_cgroup_v2_path("0::/kubepods/burstable/pod1/abc\n"),
            std::optional<std::string>("/kubepods/burstable/pod1/abc"));
  // A hybrid system lists the v1 hierarchies too; only "0::" is v2.
  EXPECT_EQ(parse_cgroup_v2_path("12:cpu,cpuacct:/docker/x\n1:name=systemd:/docker/x\n0::/docker/x\n"),
            std::optional<std::string>("/docker/x"));
  EXPECT_EQ(parse_cgroup_v2_path("12:cpu,cpuacct:/docker/x\n"), std::nullopt);
  EXPECT_EQ(parse_cgroup_v2_path(""), std::nullopt);
  EXPECT_EQ(parse_cgroup_v2_path("10::/not-v2\n"), std::nullopt);
}

TEST(UsableCpus, TheQuotaBoundsTheMaskInWholeCpus) {
  // A 1-CPU pod on a 64-core node: one loop, not 64.
  EXPECT_EQ(usable_cpus(64, 1.0), 1);
  EXPECT_EQ(usable_cpus(64, 2.0), 2);
  // A fraction is left to the compute pool: 1.5 CPUs is 1 loop, 2.9 is 2.
  EXPECT_EQ(usable_cpus(64, 1.5), 1);
  EXPECT_EQ(usable_cpus(64, 2.9), 2);
  // Under one CPU there is still one loop.
  EXPECT_EQ(usable_cpus(64, 0.25), 1);
  // The mask bounds a larger quota, and without a quota the mask is the answer.
  EXPECT_EQ(usable_cpus(2, 8.0), 2);
  EXPECT_EQ(usable_cpus(3, std::nullopt), 3);
  EXPECT_EQ(usable_cpus(4, 1e12), 4);
  EXPECT_EQ(usable_cpus(0, std::nullopt), 1);
}

TEST(UsableCpus, ThisProcessIsBoundedByItsAffinityMask) {
  cpu_set_t all;
  CPU_ZERO(&all);
  ASSERT_EQ(sched_getaffinity(0, sizeof all, &all), 0);
  const int usable = usable_cpus_of_this_process();
  EXPECT_GE(usable, 1);
  EXPECT_LE(usable, CPU_COUNT(&all));
  // Pinned to one CPU (as taskset -c would), whatever the machine's core count.
  int first = 0;
  while (!CPU_ISSET(first, &all)) ++first;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
  EXPECT_EQ(usable_cpus_of_this_process(), 1);
  ASSERT_EQ(sched_setaffinity(0, sizeof all, &all), 0);
}

}  // namespace
}  // namespace bezier::service
