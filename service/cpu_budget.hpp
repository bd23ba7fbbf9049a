#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace bezier::service {

/// How many CPUs the process may keep busy, which sizes the event loops when
/// --io-threads is 0. Two things bound it, and the machine's core count is neither: the
/// CPUs of the affinity mask (taskset, cpusets, Kubernetes' static CPU manager) and the
/// CFS bandwidth quota of cgroup v2 (`cpu.max`, a container's CPU limit), which lets a
/// 1-CPU pod run on any of a 64-core node's cores but only for one CPU's worth of time.
/// Parsing takes text, so tests give it the files' contents.

/// The CPUs a cgroup v2 `cpu.max` allows: "200000 100000" (quota and period, in µs) is
/// 2, "150000 100000" 1.5; "max 100000" (no quota) and text that is not of that form
/// give nullopt (no bound known).
[[nodiscard]] std::optional<double> parse_cpu_max(std::string_view text) noexcept;

/// The cgroup v2 path of the process from /proc/self/cgroup's text (its "0::/path"
/// line), e.g. "/kubepods/pod1/abc"; nullopt when there is none (cgroup v1 only).
[[nodiscard]] std::optional<std::string> parse_cgroup_v2_path(std::string_view proc_self_cgroup);

/// Event loops for `affinity_cpus` CPUs in the mask under a quota of `quota_cpus`: the
/// whole CPUs of the quota (rounded down, so the loops alone never exceed it and the
/// compute pool keeps the fraction) and no more than the mask, at least 1.
[[nodiscard]] int usable_cpus(int affinity_cpus, std::optional<double> quota_cpus) noexcept;

/// usable_cpus() of this process: sched_getaffinity's count, and the smallest quota of
/// `cpu.max` in its cgroup and every ancestor up to the root of /sys/fs/cgroup (a limit
/// set on a parent bounds its children).
[[nodiscard]] int usable_cpus_of_this_process();

}  // namespace bezier::service
