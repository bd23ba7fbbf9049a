#include "service/inline_policy.hpp"

#include <algorithm>

namespace bezier::service {

api::Limits InlinePolicy::limits(const api::Limits& full) noexcept {
  api::Limits small = full;
  small.max_work = std::max<std::int64_t>(1, full.max_work / kWorkDivisor);
  small.max_t_values = std::min(full.max_t_values, kMaxTValues);
  small.max_degree = std::min(full.max_degree, kMaxDegree);
  return small;
}

}  // namespace bezier::service
