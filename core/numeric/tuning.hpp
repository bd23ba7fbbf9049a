#pragma once

#include <cstddef>

// The tuning constant of the numeric layer, with the reason for its value.

namespace bezier::core::numeric_tuning {

/// Entries held inline by the short rows of coefficients (SmallArray, CasteljauRow), and
/// one more than the largest degree evaluated in rows on the stack (compensated_point.cpp,
/// krawczyk.cpp): degree 23, above the API's default degree limit of 20, so the requests it
/// accepts by default allocate nothing per piece or evaluation (an allocation costs more
/// than the compensated arithmetic of a cubic). Every row and piece carries this much
/// storage, so a larger value costs stack and cache for all degrees.
inline constexpr std::size_t kInlineEntries = 24;

}  // namespace bezier::core::numeric_tuning
