#pragma once

#include <array>
#include <string_view>

#include <nlohmann/json.hpp>

#include "api/limits.hpp"
#include "api/problem.hpp"
#include "api/routes.hpp"

namespace bezier::api {

/// What bounds the cost of a compute route: the per-request work cap (its kernel charges a
/// work budget and answers 422 work-cap when it runs out), or the request's sizes alone
/// (the degree and t-value limits bound the work before it starts).
enum class CostBound {
  work_cap,
  request_size,
};

/// One compute route: its path, the function that answers it (api/routes.hpp) and what
/// bounds its cost.
struct ComputeRoute {
  std::string_view path;
  Reply (*answer)(const nlohmann::json& request, const Limits& limits);
  CostBound cost;
};

/// The compute routes, in the order the spec lists them: the one list from which the
/// handler dispatches (api/handler.cpp), /batch decides which items its work cap is charged
/// for (api/batch_route.cpp) and the service labels its metrics (service/metrics.hpp).
/// Adding a route is one line here.
inline constexpr std::array kComputeRoutes = {
    ComputeRoute{"/evaluate", &evaluate_route, CostBound::request_size},
    ComputeRoute{"/polar", &polar_route, CostBound::request_size},
    ComputeRoute{"/classify", &classify_route, CostBound::request_size},
    ComputeRoute{"/loop-area", &loop_area_route, CostBound::work_cap},
    ComputeRoute{"/intersections", &intersections_route, CostBound::work_cap},
    ComputeRoute{"/length", &length_route, CostBound::work_cap},
    ComputeRoute{"/bounds", &bounds_route, CostBound::request_size},
    ComputeRoute{"/nearest", &nearest_route, CostBound::work_cap},
    ComputeRoute{"/contains", &contains_route, CostBound::work_cap},
    ComputeRoute{"/boolean", &boolean_route, CostBound::work_cap},
    ComputeRoute{"/flatten", &flatten_route, CostBound::work_cap},
    ComputeRoute{"/offset", &offset_route, CostBound::work_cap},
    ComputeRoute{"/stroke", &stroke_route, CostBound::work_cap},
    ComputeRoute{"/segments", &segments_route, CostBound::request_size},
};

/// The compute route of `path`, or nullptr when there is none.
[[nodiscard]] constexpr const ComputeRoute* find_compute_route(std::string_view path) noexcept {
  for (const ComputeRoute& route : kComputeRoutes) {
    if (route.path == path) return &route;
  }
  return nullptr;
}

}  // namespace bezier::api
