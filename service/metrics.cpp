#include "service/metrics.hpp"

#include <cmath>
#include <cstdio>

namespace bezier::service {

std::size_t Metrics::route_index(std::string_view route) noexcept {
  for (std::size_t i = 0; i + 1 < kRoutes.size(); ++i) {
    if (kRoutes[i] == route) return i;
  }
  return kRoutes.size() - 1;
}

std::size_t Metrics::status_index(int status) noexcept {
  for (std::size_t i = 0; i + 1 < kStatuses.size(); ++i) {
    if (kStatuses[i] == status) return i;
  }
  return kStatuses.size() - 1;
}

void Metrics::request_finished(std::string_view route, int status, double seconds) noexcept {
  in_flight_.fetch_sub(1, std::memory_order_relaxed);
  const std::size_t r = route_index(route);
  requests_[r][status_index(status)].fetch_add(1, std::memory_order_relaxed);
  std::size_t b = 0;
  while (b < kBuckets.size() && seconds > kBuckets[b]) ++b;
  buckets_[r][b].fetch_add(1, std::memory_order_relaxed);
  count_[r].fetch_add(1, std::memory_order_relaxed);
  sum_ns_[r].fetch_add(static_cast<std::uint64_t>(std::llround(seconds * 1e9)),
                       std::memory_order_relaxed);
}

std::string Metrics::render() const {
  std::string out;
  char line[256];
  out += "# HELP bezier_requests_total HTTP requests answered, by route and status.\n";
  out += "# TYPE bezier_requests_total counter\n";
  for (std::size_t r = 0; r < kRoutes.size(); ++r) {
    for (std::size_t s = 0; s < kStatuses.size(); ++s) {
      const auto n = requests_[r][s].load(std::memory_order_relaxed);
      if (n == 0) continue;
      const std::string status = kStatuses[s] == 0 ? "other" : std::to_string(kStatuses[s]);
      std::snprintf(line, sizeof line, "bezier_requests_total{route=\"%.*s\",status=\"%s\"} %llu\n",
                    static_cast<int>(kRoutes[r].size()), kRoutes[r].data(), status.c_str(),
                    static_cast<unsigned long long>(n));
      out += line;
    }
  }
  out += "# HELP bezier_request_duration_seconds Time from request parsed to answer ready.\n";
  out += "# TYPE bezier_request_duration_seconds histogram\n";
  for (std::size_t r = 0; r < kRoutes.size(); ++r) {
    const auto count = count_[r].load(std::memory_order_relaxed);
    if (count == 0) continue;
    const auto route = kRoutes[r];
    std::uint64_t cumulative = 0;
    for (std::size_t b = 0; b <= kBuckets.size(); ++b) {
      cumulative += buckets_[r][b].load(std::memory_order_relaxed);
      if (b < kBuckets.size()) {
        std::snprintf(line, sizeof line,
                      "bezier_request_duration_seconds_bucket{route=\"%.*s\",le=\"%g\"} %llu\n",
                      static_cast<int>(route.size()), route.data(), kBuckets[b],
                      static_cast<unsigned long long>(cumulative));
      } else {
        std::snprintf(line, sizeof line,
                      "bezier_request_duration_seconds_bucket{route=\"%.*s\",le=\"+Inf\"} %llu\n",
                      static_cast<int>(route.size()), route.data(),
                      static_cast<unsigned long long>(cumulative));
      }
      out += line;
    }
    std::snprintf(line, sizeof line, "bezier_request_duration_seconds_sum{route=\"%.*s\"} %.9f\n",
                  static_cast<int>(route.size()), route.data(),
                  static_cast<double>(sum_ns_[r].load(std::memory_order_relaxed)) * 1e-9);
    out += line;
    std::snprintf(line, sizeof line, "bezier_request_duration_seconds_count{route=\"%.*s\"} %llu\n",
                  static_cast<int>(route.size()), route.data(), static_cast<unsigned long long>(count));
    out += line;
  }
  out += "# HELP bezier_requests_in_flight Requests being processed now.\n";
  out += "# TYPE bezier_requests_in_flight gauge\n";
  out += "bezier_requests_in_flight " + std::to_string(in_flight_.load(std::memory_order_relaxed)) + "\n";
  return out;
}

}  // namespace bezier::service
