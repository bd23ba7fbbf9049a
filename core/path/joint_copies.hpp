#pragma once

#include <vector>

#include "core/path/path.hpp"
#include "core/path/path_contact.hpp"

namespace bezier::path {

/// Removes the copies of a contact that the segment pairs around a joint each report.
///
/// A contact at the joint where segment p ends and its successor q starts is found on both:
/// at t = 1 of p and t = 0 of q (and again on the other side when it is also a joint
/// there). Each end of a contact is located canonically: an interval containing 0 on a
/// segment with a predecessor, or containing 1 on a segment with a successor, is that
/// joint (joints separated only by zero-length segments are one joint); any other end is
/// its segment with its interval. Two contacts are copies when their ends are at the same
/// joints or on the same segments with overlapping intervals (with `one_path`, in either
/// order); of a group of copies the one with the lowest (segment_t, segment_s) stays.
/// With `one_path`, a contact whose two ends are the same joint is the joint itself (two
/// consecutive segments meeting where one ends and the next begins, or a closed subpath's
/// start meeting its end) and is removed too. The order of what stays is kept.
/// `path_t` holds segment_t, `path_s` holds segment_s (the same path with one_path).
[[nodiscard]] std::vector<PathContact> without_joint_copies(std::vector<PathContact> contacts,
                                                            const Path& path_t,
                                                            const Path& path_s, bool one_path);

}  // namespace bezier::path
