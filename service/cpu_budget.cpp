#include "service/cpu_budget.hpp"

#include <sched.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace bezier::service {

namespace {

// The leading decimal integer of `text` (after spaces), advancing `text` past it;
// nullopt if there is none or it overflows.
std::optional<long long> take_integer(std::string_view& text) noexcept {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end == text.data()) return std::nullopt;
  text.remove_prefix(static_cast<std::size_t>(end - text.data()));
  return value;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

int affinity_cpu_count() noexcept {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return 1;
  return std::max(1, CPU_COUNT(&set));
}

// The smallest cpu.max quota from the process's cgroup up to the root of the mount.
std::optional<double> cgroup_quota_cpus() {
  const std::string root = "/sys/fs/cgroup";
  std::optional<double> smallest;
  const auto consider = [&](const std::string& directory) {
    const auto quota = parse_cpu_max(read_file(directory + "/cpu.max"));
    if (quota && (!smallest || *quota < *smallest)) smallest = quota;
  };
  if (const auto path = parse_cgroup_v2_path(read_file("/proc/self/cgroup"))) {
    // In a container with its own cgroup namespace the path is "/" and the mount's
    // root is the container's cgroup; on a host the path names it below the root.
    std::string relative = *path;
    while (!relative.empty() && relative != "/") {
      consider(root + relative);
      relative.resize(relative.rfind('/'));
    }
  }
  consider(root);
  return smallest;
}

}  // namespace

std::optional<double> parse_cpu_max(std::string_view text) noexcept {
  // cgroup v2: "$MAX $PERIOD", MAX being "max" or a quota in µs per PERIOD µs.
  const auto quota = take_integer(text);
  if (!quota || *quota <= 0) return std::nullopt;
  const auto period = take_integer(text);
  if (!period || *period <= 0) return std::nullopt;
  while (!text.empty() && (text.front() == ' ' || text.front() == '\n')) text.remove_prefix(1);
  if (!text.empty()) return std::nullopt;
  return static_cast<double>(*quota) / static_cast<double>(*period);
}

std::optional<std::string> parse_cgroup_v2_path(std::string_view proc_self_cgroup) {
  // Lines "hierarchy-ID:controllers:path"; cgroup v2's unified hierarchy is "0::path".
  constexpr std::string_view kUnified = "0::";
  while (!proc_self_cgroup.empty()) {
    const std::size_t end = proc_self_cgroup.find('\n');
    const std::string_view line = proc_self_cgroup.substr(0, end);
    if (line.substr(0, kUnified.size()) == kUnified && line.size() > kUnified.size() &&
        line[kUnified.size()] == '/') {
      return std::string(line.substr(kUnified.size()));
    }
    if (end == std::string_view::npos) break;
    proc_self_cgroup.remove_prefix(end + 1);
  }
  return std::nullopt;
}

int usable_cpus(int affinity_cpus, std::optional<double> quota_cpus) noexcept {
  int cpus = std::max(1, affinity_cpus);
  if (quota_cpus && *quota_cpus < cpus) cpus = static_cast<int>(std::floor(*quota_cpus));
  return std::max(1, cpus);
}

int usable_cpus_of_this_process() { return usable_cpus(affinity_cpu_count(), cgroup_quota_cpus()); }

}  // namespace bezier::service
