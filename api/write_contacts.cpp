#include "api/write_contacts.hpp"

#include <cstdint>

namespace bezier::api {

void write_segments(JsonWriter& w, SegmentPair segments) {
  w.key("segments").begin_array();
  w.value(static_cast<std::int64_t>(segments.t)).value(static_cast<std::int64_t>(segments.s));
  w.end_array();
}

void write_overlap(JsonWriter& w, const core::Overlap& overlap, OverlapDirection direction,
                   std::optional<SegmentPair> segments) {
  w.begin_object();
  if (direction == OverlapDirection::written) w.key("reversed").value(overlap.reversed);
  w.key("s_interval").pair(overlap.s_interval.lo, overlap.s_interval.hi);
  if (segments) write_segments(w, *segments);
  w.key("t_interval").pair(overlap.t_interval.lo, overlap.t_interval.hi);
  w.end_object();
}

void write_path_overlaps(JsonWriter& w, const std::vector<path::PathOverlap>& between,
                              const std::vector<path::SegmentSelfIntersections>& within,
                              OverlapDirection direction) {
  for (const path::PathOverlap& o : between) {
    write_overlap(w, o.overlap, direction, SegmentPair{o.segment_t, o.segment_s});
  }
  for (const path::SegmentSelfIntersections& segment : within) {
    for (const core::Overlap& o : segment.result.overlaps) {
      write_overlap(w, o, direction, SegmentPair{segment.segment, segment.segment});
    }
  }
}

}  // namespace bezier::api
