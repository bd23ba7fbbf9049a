#include "service/metrics.hpp"

#include <cmath>
#include <cstdio>

#include "service/process_metrics.hpp"

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
  out += "# HELP bezier_batch_items_total Items of POST /batch answered, by the item's route and status.\n";
  out += "# TYPE bezier_batch_items_total counter\n";
  for (std::size_t r = 0; r < kRoutes.size(); ++r) {
    for (std::size_t s = 0; s < kStatuses.size(); ++s) {
      const auto n = batch_items_[r][s].load(std::memory_order_relaxed);
      if (n == 0) continue;
      const std::string status = kStatuses[s] == 0 ? "other" : std::to_string(kStatuses[s]);
      std::snprintf(line, sizeof line, "bezier_batch_items_total{route=\"%.*s\",status=\"%s\"} %llu\n",
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
  out += "# HELP bezier_compute_queue_depth Requests waiting for a compute thread.\n";
  out += "# TYPE bezier_compute_queue_depth gauge\n";
  out += "bezier_compute_queue_depth " +
         std::to_string(compute_queue_depth_.load(std::memory_order_relaxed)) + "\n";
  out += "# HELP bezier_work_cap_hits_total Answers the per-request work cap decided (422 work-cap, or an "
         "answer it cut short).\n";
  out += "# TYPE bezier_work_cap_hits_total counter\n";
  out += "bezier_work_cap_hits_total " + std::to_string(work_cap_hits_.load(std::memory_order_relaxed)) + "\n";
  out += "# HELP bezier_overload_responses_total 503 answers for want of capacity, by reason.\n";
  out += "# TYPE bezier_overload_responses_total counter\n";
  constexpr std::array<std::string_view, 3> kReasons = {"connections", "queue_full", "queue_deadline"};
  for (std::size_t i = 0; i < kReasons.size(); ++i) {
    out += "bezier_overload_responses_total{reason=\"";
    out += kReasons[i];
    out += "\"} " + std::to_string(overloaded_[i].load(std::memory_order_relaxed)) + "\n";
  }
  out += "# HELP bezier_requests_dropped_total Requests not answered because their connection closed while "
         "they waited for a compute thread.\n";
  out += "# TYPE bezier_requests_dropped_total counter\n";
  out += "bezier_requests_dropped_total " + std::to_string(dropped_.load(std::memory_order_relaxed)) + "\n";
  out += "# HELP bezier_build_info The service's version; the value is always 1.\n";
  out += "# TYPE bezier_build_info gauge\n";
  out += "bezier_build_info{version=\"" BEZIER_VERSION "\"} 1\n";
  out += render_process_metrics();
  return out;
}

}  // namespace bezier::service
