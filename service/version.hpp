#pragma once

#include <string_view>

namespace bezier::service {

/// The service's version: the project version of the top-level CMakeLists.txt, passed
/// by service/CMakeLists.txt as BEZIER_VERSION.
inline constexpr std::string_view kServiceVersion = BEZIER_VERSION;

}  // namespace bezier::service
