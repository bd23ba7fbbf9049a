#pragma once

// What one work unit costs in CPU time on this machine, for the fuzz targets that compare a
// request's CPU time with its budget (work_bound_fuzzer, request_cost_fuzzer).

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "api/handler.hpp"
#include "api/limits.hpp"

namespace bezier::fuzz {

/// CPU time of the calling thread, in seconds.
inline double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// CPU seconds per work unit on a request that spends its budget in plain search steps: a
/// parabola 1e14 tall against a steep line, by subdivision (every box at the search width
/// along the crossing stays undecided in doubles, so the search runs into the cap). The
/// largest of seven runs: they differ by up to half as the allocator's state decides how
/// many pages the search's memory first touches (each a page fault, dear on a virtual
/// machine); an input pays them too, so the unit includes them. Measured once; `target`
/// names the caller in the line it prints and in the message it aborts with.
inline double seconds_per_unit(std::string_view target) {
  static const double unit = [target] {
    const nlohmann::json body = {{"curves",
                                  {{{"points", {{2.0, -2.0}, {-1.0, 1e14}, {-1.0, -1.0}}}},
                                   {{"points", {{-0.5, 0.0}, {-2.0, 1e6}}}}}},
                                 {"method", "subdivision"}};
    api::Limits limits;
    limits.max_work = 2200000;
    const std::string text = body.dump();
    std::array<double, 7> per_unit{};
    for (double& t_unit : per_unit) {
      const double start = thread_cpu_seconds();
      const api::Reply reply = api::handle("/intersections", text, limits);
      const double cpu = thread_cpu_seconds() - start;
      if (reply.status != 422) {
        std::fprintf(stderr, "%.*s: the reference request did not reach the cap\n", static_cast<int>(target.size()),
                     target.data());
        std::abort();
      }
      t_unit = cpu / static_cast<double>(limits.max_work);
    }
    const double slowest = *std::max_element(per_unit.begin(), per_unit.end());
    std::fprintf(stderr, "%.*s: %.3g ns per work unit\n", static_cast<int>(target.size()), target.data(),
                 slowest * 1e9);
    return slowest;
  }();
  return unit;
}

}  // namespace bezier::fuzz
