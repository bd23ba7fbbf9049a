#pragma once

#include <array>
#include <string_view>

#include <nlohmann/json.hpp>

#include "api/limits.hpp"
#include "api/problem.hpp"
#include "api/route_cost.hpp"
#include "api/routes.hpp"

namespace bezier::api {

/// One compute route: its path, the function that answers it (api/routes.hpp), and its
/// cost model (api/route_cost.hpp): the most work units a request may spend, from its
/// sizes before it runs, which /batch charges each item. The routes whose kernels charge the
/// per-request work cap have work_capped_cost; the others a model of their own sizes.
struct ComputeRoute {
  std::string_view path;
  Reply (*answer)(const nlohmann::json& request, const Limits& limits);
  RouteCost work_bound;
};

/// The compute routes, in the order the spec lists them: the one list from which the
/// handler dispatches (api/handler.cpp), /batch charges each item its work cap
/// (api/batch_route.cpp) and the service labels its metrics (service/metrics.hpp).
/// Adding a route is one line here.
inline constexpr std::array kComputeRoutes = {
    ComputeRoute{"/evaluate", &evaluate_route, &evaluate_cost},
    ComputeRoute{"/polar", &polar_route, &polar_cost},
    ComputeRoute{"/classify", &classify_route, &classify_cost},
    ComputeRoute{"/loop-area", &loop_area_route, &work_capped_cost},
    ComputeRoute{"/intersections", &intersections_route, &work_capped_cost},
    ComputeRoute{"/length", &length_route, &work_capped_cost},
    ComputeRoute{"/bounds", &bounds_route, &bounds_cost},
    ComputeRoute{"/nearest", &nearest_route, &work_capped_cost},
    ComputeRoute{"/contains", &contains_route, &work_capped_cost},
    ComputeRoute{"/boolean", &boolean_route, &work_capped_cost},
    ComputeRoute{"/flatten", &flatten_route, &work_capped_cost},
    ComputeRoute{"/offset", &offset_route, &work_capped_cost},
    ComputeRoute{"/stroke", &stroke_route, &work_capped_cost},
    ComputeRoute{"/segments", &segments_route, &segments_cost},
};

/// The compute route of `path`, or nullptr when there is none.
[[nodiscard]] constexpr const ComputeRoute* find_compute_route(std::string_view path) noexcept {
  for (const ComputeRoute& route : kComputeRoutes) {
    if (route.path == path) return &route;
  }
  return nullptr;
}

}  // namespace bezier::api
