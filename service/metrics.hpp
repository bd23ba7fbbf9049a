#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <string_view>

#include "api/route_table.hpp"

namespace bezier::service {

/// Why the service answered 503 to a request it could not take on.
enum class Overload {
  connections,     ///< --max-connections were open: the new connection was refused
  queue_full,      ///< --max-queued-requests were waiting for a compute thread
  queue_deadline,  ///< the request waited longer than --queue-deadline for a compute thread
};

/// Request counters, a latency histogram, the in-flight and compute queue gauges and the
/// counters of refused and dropped work, rendered in the Prometheus text exposition
/// format (version 0.0.4) together with the process metrics (service/process_metrics.hpp)
/// and the build's version. Lock-free: every update is a relaxed atomic add on a fixed
/// slot, so recording costs nothing measurable on the request path. Routes and statuses
/// outside the known sets share an "other" slot.
class Metrics {
 public:
  /// Called when a request starts and when its answer is ready.
  void request_started() noexcept { in_flight_.fetch_add(1, std::memory_order_relaxed); }
  void request_finished(std::string_view route, int status, double seconds) noexcept;
  /// Ends a started request that gets no answer (its connection closed while it waited).
  void request_dropped() noexcept {
    in_flight_.fetch_sub(1, std::memory_order_relaxed);
    dropped_.fetch_add(1, std::memory_order_relaxed);
  }
  /// One item of a /batch answered: counted by the item's route and status (the batch
  /// itself is one request of route /batch).
  void batch_item_finished(std::string_view route, int status) noexcept {
    batch_items_[route_index(route)][status_index(status)].fetch_add(1, std::memory_order_relaxed);
  }
  /// An answer the work cap decided (a 422 work-cap, or an answer it cut short).
  void work_cap_hit() noexcept { work_cap_hits_.fetch_add(1, std::memory_order_relaxed); }
  /// A 503 for want of capacity.
  void overloaded(Overload reason) noexcept {
    overloaded_[static_cast<std::size_t>(reason)].fetch_add(1, std::memory_order_relaxed);
  }
  /// A request entered, or left, the compute pool's queue.
  void compute_queued() noexcept { compute_queue_depth_.fetch_add(1, std::memory_order_relaxed); }
  void compute_dequeued() noexcept { compute_queue_depth_.fetch_sub(1, std::memory_order_relaxed); }

  /// The exposition text for GET /metrics.
  [[nodiscard]] std::string render() const;

  /// The route labels: the compute routes (api/route_table.hpp), /batch, the GET routes,
  /// the playground's page and "other" for every other path.
  static constexpr std::array<std::string_view, 7> kOtherRoutes = {
      "/batch", "/openapi.yaml", "/openapi.json", "/healthz", "/readyz", "/metrics", "/"};
  static constexpr std::array<std::string_view, api::kComputeRoutes.size() + kOtherRoutes.size() + 1> kRoutes =
      [] {
        std::array<std::string_view, api::kComputeRoutes.size() + kOtherRoutes.size() + 1> routes{};
        std::size_t i = 0;
        for (const api::ComputeRoute& route : api::kComputeRoutes) routes[i++] = route.path;
        for (const std::string_view route : kOtherRoutes) routes[i++] = route;
        routes[i] = "other";
        return routes;
      }();
  static constexpr std::array<int, 13> kStatuses = {200, 204, 400, 401, 404, 405, 408,
                                                    413, 415, 422, 500, 503, 0 /*other*/};
  /// Upper bounds of the latency buckets, in seconds (+Inf is implied).
  static constexpr std::array<double, 14> kBuckets = {0.00005, 0.0001, 0.00025, 0.0005, 0.001,
                                                      0.0025,  0.005,  0.01,    0.025,  0.05,
                                                      0.1,     0.25,   0.5,     1.0};

 private:
  static std::size_t route_index(std::string_view route) noexcept;
  static std::size_t status_index(int status) noexcept;

  std::atomic<std::int64_t> in_flight_{0};
  std::atomic<std::int64_t> compute_queue_depth_{0};
  std::atomic<std::uint64_t> dropped_{0};
  std::atomic<std::uint64_t> work_cap_hits_{0};
  std::array<std::atomic<std::uint64_t>, 3> overloaded_{};
  std::array<std::array<std::atomic<std::uint64_t>, kStatuses.size()>, kRoutes.size()> requests_{};
  std::array<std::array<std::atomic<std::uint64_t>, kStatuses.size()>, kRoutes.size()> batch_items_{};
  std::array<std::array<std::atomic<std::uint64_t>, kBuckets.size() + 1>, kRoutes.size()> buckets_{};
  std::array<std::atomic<std::uint64_t>, kRoutes.size()> count_{};
  // Sum of durations in nanoseconds, so it can be an integer atomic.
  std::array<std::atomic<std::uint64_t>, kRoutes.size()> sum_ns_{};
};

}  // namespace bezier::service
