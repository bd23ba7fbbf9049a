#include "service/process_metrics.hpp"

#include <dirent.h>
#include <sys/resource.h>
#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>

namespace bezier::service {

namespace {

struct Memory {
  double resident_bytes;
  double virtual_bytes;
};

// /proc/self/statm: "size resident shared text lib data dt", in pages.
std::optional<Memory> memory() {
  std::ifstream statm("/proc/self/statm");
  double size_pages = 0;
  double resident_pages = 0;
  if (!(statm >> size_pages >> resident_pages)) return std::nullopt;
  const auto page = static_cast<double>(sysconf(_SC_PAGESIZE));
  return Memory{resident_pages * page, size_pages * page};
}

std::optional<double> cpu_seconds() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return std::nullopt;
  const auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + t.tv_usec * 1e-6; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// The entries of /proc/self/fd (the directory's own descriptor among them, as the
// official clients count it).
std::optional<double> open_fds() {
  DIR* dir = opendir("/proc/self/fd");
  if (dir == nullptr) return std::nullopt;
  double count = 0;
  while (const dirent* entry = readdir(dir)) {
    const std::string_view name = entry->d_name;
    if (name != "." && name != "..") ++count;
  }
  closedir(dir);
  return count;
}

std::optional<double> max_fds() {
  rlimit limit{};
  if (getrlimit(RLIMIT_NOFILE, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
  return static_cast<double>(limit.rlim_cur);
}

// Field 22 of /proc/self/stat (clock ticks after boot) plus the boot time of
// /proc/stat's "btime" line (Unix seconds).
std::optional<double> start_time_seconds() {
  std::ifstream stat_file("/proc/self/stat");
  std::string stat((std::istreambuf_iterator<char>(stat_file)), std::istreambuf_iterator<char>());
  // The command name (field 2) is in parentheses and may hold spaces: count after it.
  const std::size_t name_end = stat.rfind(')');
  if (name_end == std::string::npos) return std::nullopt;
  std::istringstream fields(stat.substr(name_end + 1));
  std::string field;
  for (int i = 3; i <= 22; ++i) {
    if (!(fields >> field)) return std::nullopt;
  }
  const double start_ticks = std::strtod(field.c_str(), nullptr);
  std::ifstream proc_stat("/proc/stat");
  std::string key;
  double boot_time = -1;
  while (proc_stat >> key) {
    if (key == "btime") {
      proc_stat >> boot_time;
      break;
    }
    proc_stat.ignore(1 << 20, '\n');
  }
  if (boot_time < 0) return std::nullopt;
  return boot_time + start_ticks / static_cast<double>(sysconf(_SC_CLK_TCK));
}

void append(std::string& out, const char* name, const char* type, const char* help, std::optional<double> value) {
  if (!value) return;
  char line[256];
  std::snprintf(line, sizeof line, "# HELP %s %s\n# TYPE %s %s\n%s ", name, help, name, type, name);
  out += line;
  // The shortest text that reads back to the same double.
  char number[32];
  out.append(number, std::to_chars(number, number + sizeof number, *value).ptr);
  out += '\n';
}

}  // namespace

std::string render_process_metrics() {
  std::string out;
  append(out, "process_cpu_seconds_total", "counter", "Total user and system CPU time spent in seconds.",
         cpu_seconds());
  const auto bytes = memory();
  append(out, "process_resident_memory_bytes", "gauge", "Resident memory size in bytes.",
         bytes ? std::optional(bytes->resident_bytes) : std::nullopt);
  append(out, "process_virtual_memory_bytes", "gauge", "Virtual memory size in bytes.",
         bytes ? std::optional(bytes->virtual_bytes) : std::nullopt);
  append(out, "process_open_fds", "gauge", "Number of open file descriptors.", open_fds());
  append(out, "process_max_fds", "gauge", "Maximum number of open file descriptors.", max_fds());
  append(out, "process_start_time_seconds", "gauge", "Start time of the process since unix epoch in seconds.",
         start_time_seconds());
  return out;
}

}  // namespace bezier::service
