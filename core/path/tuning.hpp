#pragma once

// The tuning constants of the path layer's pair filters (joint_separation.hpp,
// hull_separation.hpp), each with the reason for its value. None of them changes what is
// certified: a filter that declines a pair hands it to the two-curve search.

namespace bezier::path::path_tuning {

/// How clearly two segments must be apart for a filter to decide their pair without the
/// two-curve search, relative to the size of what is compared: 2^-16 (an angle of about
/// 1.5e-5 radians at a joint; a gap of 2^-16 of the control points' spread between hulls).
/// Far above rounding (2^-51) and above the search's coincidence tolerance (2^-42 of the
/// curves' scale, core/intersect/overlap.hpp), so that a pair the search would call
/// touching or overlapping within its tolerance is always left to it; small enough that
/// the joints of smooth outlines and segments a visible distance apart pass.
inline constexpr double kSeparationMargin = 0x1p-16;

}  // namespace bezier::path::path_tuning
