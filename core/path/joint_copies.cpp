#include "core/path/joint_copies.hpp"

#include <map>
#include <optional>
#include <utility>

namespace bezier::path {

namespace {

/// The segment whose end point `segment` starts at, inside its subpath (see next_segment).
std::optional<std::size_t> previous_segment(const Path& path, std::size_t segment) {
  const Subpath& sub = subpath_of(path, segment);
  if (segment > sub.first_segment) return segment - 1;
  if (sub.closed && sub.segment_count > 1) return sub.first_segment + sub.segment_count - 1;
  return std::nullopt;
}

/// The joint after segment p, moved forward over zero-length segments that are themselves
/// followed by a segment: all of those joints are one point of the path.
std::size_t canonical_joint(const Path& path, std::size_t p) {
  const std::size_t count = subpath_of(path, p).segment_count;
  for (std::size_t step = 0; step < count; ++step) {
    const auto q = next_segment(path, p);
    if (!q || !core::is_point(path.segments[*q]) || !next_segment(path, *q)) break;
    p = *q;
  }
  return p;
}

/// Where one end of a contact is: a joint (id: the canonical segment it follows) or the
/// inside of a segment (id: that segment, with the interval).
struct End {
  bool joint = false;
  std::size_t id = 0;
  core::ParamInterval interval;
};

End end_of(const Path& path, std::size_t segment, core::ParamInterval interval) {
  if (interval.lo <= 0.0) {
    if (const auto p = previous_segment(path, segment)) return {true, canonical_joint(path, *p), interval};
  }
  if (interval.hi >= 1.0 && next_segment(path, segment)) {
    return {true, canonical_joint(path, segment), interval};
  }
  return {false, segment, interval};
}

bool same_place(const End& a, const End& b) {
  if (a.joint != b.joint || a.id != b.id) return false;
  return a.joint || (a.interval.lo <= b.interval.hi && b.interval.lo <= a.interval.hi);
}

}  // namespace

std::vector<PathContact> without_joint_copies(std::vector<PathContact> contacts,
                                              const Path& path_t, const Path& path_s,
                                              bool one_path) {
  const std::size_t n = contacts.size();
  std::vector<End> end_t(n), end_s(n);
  for (std::size_t k = 0; k < n; ++k) {
    end_t[k] = end_of(path_t, contacts[k].segment_t, contacts[k].intersection.t_interval);
    end_s[k] = end_of(path_s, contacts[k].segment_s, contacts[k].intersection.s_interval);
  }
  std::vector<bool> dropped(n, false);
  const auto copies = [&](std::size_t a, std::size_t b) {
    return (same_place(end_t[a], end_t[b]) && same_place(end_s[a], end_s[b])) ||
           (one_path && same_place(end_t[a], end_s[b]) && same_place(end_s[a], end_t[b]));
  };
  const auto key = [&](std::size_t k) {
    return std::pair{contacts[k].segment_t, contacts[k].segment_s};
  };
  // Contacts with an end at a joint, by that joint (side 0: path_t's joints, side 1:
  // path_s's; one side for one path).
  std::map<std::pair<int, std::size_t>, std::vector<std::size_t>> at_joint;
  for (std::size_t k = 0; k < n; ++k) {
    if (one_path && end_t[k].joint && end_s[k].joint && end_t[k].id == end_s[k].id) {
      dropped[k] = true;
      continue;
    }
    std::vector<std::pair<int, std::size_t>> joints;
    if (end_t[k].joint) joints.emplace_back(0, end_t[k].id);
    if (end_s[k].joint) joints.emplace_back(one_path ? 0 : 1, end_s[k].id);
    for (const auto& joint : joints) {
      for (const std::size_t c : at_joint[joint]) {
        if (dropped[c] || dropped[k] || !copies(c, k)) continue;
        dropped[key(k) < key(c) ? c : k] = true;
      }
    }
    if (dropped[k]) continue;
    for (const auto& joint : joints) at_joint[joint].push_back(k);
  }
  std::vector<PathContact> kept;
  kept.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (!dropped[k]) kept.push_back(std::move(contacts[k]));
  }
  return kept;
}

}  // namespace bezier::path
