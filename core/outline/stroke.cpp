#include "core/outline/stroke.hpp"

#include <algorithm>
#include <optional>

#include "core/outline/segment_cover.hpp"
#include "core/outline/stroke_shapes.hpp"
#include "core/outline/tangent_limits.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

bool is_point(const core::Curve& curve) {
  return std::all_of(curve.points().begin(), curve.points().end(),
                     [&](Point2 p) { return p == curve.front(); });
}

/// The segments of one subpath that draw something (stroke.hpp: zero-length ones are left out).
std::vector<std::size_t> drawn_segments(const path::Path& path, const path::Subpath& sub) {
  std::vector<std::size_t> out;
  for (std::size_t k = sub.first_segment; k < sub.first_segment + sub.segment_count; ++k) {
    if (!is_point(path.segments[k])) out.push_back(k);
  }
  return out;
}

}  // namespace

StrokeOutline stroke(const path::Path& path, const StrokeStyle& style, double tolerance,
                     std::int64_t max_work, std::size_t max_segments) {
  OutlineSink sink(max_work, max_segments);
  const double r = style.width / 2.0;
  CoverSizes sizes;
  sizes.radius = r;
  sizes.reach = r + tolerance / 2.0;
  sizes.fit_tolerance = 0.49 * tolerance;
  sizes.snap = 0.01 * tolerance;
  sizes.disk_radius = sizes.reach + 0.005 * tolerance;
  sizes.circle_pieces = circle_pieces(sizes.disk_radius, 0.485 * tolerance);
  const bool round_join = style.join == LineJoin::round;

  // The joins', caps' and dots' segments, counted before anything is built.
  std::size_t fixed = 0;
  for (const path::Subpath& sub : path.subpaths) {
    const std::size_t drawn = drawn_segments(path, sub).size();
    const std::size_t cap_size = style.cap == LineCap::round    ? sizes.circle_pieces
                                 : style.cap == LineCap::square ? 4
                                                                : 0;
    if (drawn == 0) {
      fixed += 2 * cap_size;
      continue;
    }
    const std::size_t joints = sub.closed ? drawn : drawn - 1;
    fixed += joints * (round_join ? sizes.circle_pieces : 4);
    if (!sub.closed) fixed += 2 * cap_size;
  }
  if (!sink.reserve(fixed)) return {sink.status(), {}, 0, sink.work()};

  auto add_cap = [&](Point2 point, Point2 outward) {
    if (style.cap == LineCap::round) {
      sink.add(circle(point, sizes.disk_radius, sizes.circle_pieces));
    } else if (style.cap == LineCap::square) {
      sink.add(square_cap(point, outward, r));
    }
  };
  auto add_join = [&](const core::Curve& in, const core::Curve& out) {
    const Point2 point = out.front();
    if (round_join) {
      sink.add(circle(point, sizes.disk_radius, sizes.circle_pieces));
      return;
    }
    const std::optional<Contour> polygon =
        join_polygon(point, end_tangent(in.points(), false), end_tangent(out.points(), true), r,
                     style.join == LineJoin::miter, style.miter_limit);
    if (polygon) sink.add(*polygon);
  };

  for (const path::Subpath& sub : path.subpaths) {
    const std::vector<std::size_t> drawn = drawn_segments(path, sub);
    if (!sink.charge(static_cast<std::int64_t>(sub.segment_count) * 16)) break;
    if (drawn.empty()) {
      const Point2 point = path.segments[sub.first_segment].front();
      add_cap(point, {-1.0, 0.0});
      add_cap(point, {1.0, 0.0});
      continue;
    }
    for (const std::size_t k : drawn) {
      cover_segment(path.segments[k], sizes, sink);
      if (!sink.ok()) break;
    }
    for (std::size_t i = 0; i + 1 < drawn.size(); ++i) {
      add_join(path.segments[drawn[i]], path.segments[drawn[i + 1]]);
    }
    const core::Curve& first = path.segments[drawn.front()];
    const core::Curve& last = path.segments[drawn.back()];
    if (sub.closed) {
      add_join(last, first);
    } else {
      add_cap(first.front(), -end_tangent(first.points(), true));
      add_cap(last.back(), end_tangent(last.points(), false));
    }
    if (!sink.ok()) break;
  }
  if (!sink.ok()) return {sink.status(), {}, 0, sink.work()};
  StrokeOutline result;
  result.segment_count = sink.segment_count();
  result.work = sink.work();
  result.contours = sink.take_contours();
  return result;
}

}  // namespace bezier::outline
