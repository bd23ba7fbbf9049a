#include "core/outline/stroke.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/base/curve.hpp"
#include "core/outline/control_points.hpp"
#include "core/outline/segment_cover.hpp"
#include "core/outline/stroke_shapes.hpp"
#include "core/outline/tangent_limits.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

/// The segments of one subpath that draw something (stroke.hpp: zero-length ones are left out),
/// into `out`.
void drawn_segments(const path::Path& path, const path::Subpath& sub,
                    std::vector<std::size_t>& out) {
  out.clear();
  for (std::size_t k = sub.first_segment; k < sub.first_segment + sub.segment_count; ++k) {
    if (!core::is_point(path.segments[k])) out.push_back(k);
  }
}

/// Whether B' at the curve's start (at_start) or end is zero to end_tangent's threshold
/// (tangent_limits.hpp), so that the direction there is a higher derivative's.
bool stationary_end(const core::Curve& curve, bool at_start) {
  const auto p = curve.points();
  const std::size_t n = p.size() - 1;
  const Point2 v = static_cast<double>(n) * (at_start ? p[1] - p[0] : p[n] - p[n - 1]);
  const double scale = largest_abs_coordinate(p, std::numeric_limits<double>::min());
  const double threshold = 1e-12 * scale * static_cast<double>(p.size());
  // |v| >= its largest coordinate (and so does its computed length, rounded from above it):
  // where that coordinate passes the threshold, so does the length, without computing it.
  if (std::max(std::fabs(v.x), std::fabs(v.y)) > threshold) return false;
  return !(core::length(v) > threshold);
}

/// Extends an open chain by a line to `point` when its end is farther than `snap` from it.
void pass_through(Contour& chain, Point2 point, double snap) {
  if (chain.empty() || core::length(chain.back().back() - point) <= snap) return;
  chain.push_back(core::Curve({chain.back().back(), point}));
}

/// The edges of consecutive stretches (stroke.hpp's run) joined into one contour.
class Run {
 public:
  explicit Run(double snap) : snap_(snap) {}

  [[nodiscard]] bool empty() const noexcept { return right_.empty(); }

  /// Room for a run whose stretches have `right` and `left` edge curves in all, and the few
  /// lines its contours may add, so that they are built without growing.
  void reserve(std::size_t right, std::size_t left) {
    right_.reserve(right + left + 4);
    left_.reserve(left + 2);
  }

  /// `at_zero_of_derivative`: the stretch starts at a zero of B' inside its segment (the run
  /// starts there too).
  void add(StretchEdges& stretch, bool at_zero_of_derivative) {
    if (right_.empty()) {
      start_ = stretch.start;
      start_at_zero_ = at_zero_of_derivative;
    }
    for (core::Curve& c : stretch.right) append_to_chain(right_, std::move(c), snap_);
    for (core::Curve& c : stretch.left) append_to_chain(left_, std::move(c), snap_);
    end_ = stretch.end;
  }

  /// The run's contour: the right edge forward, the normal segment at its end, the left edge
  /// backward, the normal segment at its start; a normal segment at a zero of B' inside a
  /// segment passes through B there, so that it is exactly the line the neighbouring run's
  /// runs back along (two lines meeting at one double).
  Contour open_contour(bool end_at_zero_of_derivative) {
    Contour contour = std::move(right_);
    if (end_at_zero_of_derivative) pass_through(contour, end_, snap_);
    for (auto it = left_.rbegin(); it != left_.rend(); ++it) {
      append_to_chain(contour, core::reversed(std::move(*it)), snap_);
    }
    if (start_at_zero_) pass_through(contour, start_, snap_);
    close_chain(contour, snap_);
    clear();
    return contour;
  }

  /// The two contours of a run that goes round a whole closed subpath: the right edge
  /// forward, and the left edge backward.
  std::pair<Contour, Contour> closed_contours() {
    Contour right = std::move(right_);
    close_chain(right, snap_);
    close_chain(left_, snap_);
    Contour left;
    left.reserve(left_.size());
    for (auto it = left_.rbegin(); it != left_.rend(); ++it) {
      left.push_back(core::reversed(std::move(*it)));
    }
    clear();
    return {std::move(right), std::move(left)};
  }

 private:
  void clear() {
    right_.clear();
    left_.clear();
  }

  double snap_;
  Contour right_, left_;
  Point2 start_{0, 0}, end_{0, 0};
  bool start_at_zero_ = false;
};

}  // namespace

StrokeOutline stroke(const path::Path& path, const StrokeStyle& style, double tolerance,
                     core::WorkBudget& budget, std::size_t max_segments) {
  OutlineSink sink(budget, max_segments);
  const double r = style.width / 2.0;
  const CoverSizes sizes = cover_sizes(r, tolerance);
  const bool round_join = style.join == LineJoin::round;

  // The covers of the drawn segments, each segment's once (a closed subpath's first segment
  // is needed again at its closing joint). One buffer per thread, kept from stroke to stroke
  // with the room of its stretches' chains (cover_segment reuses them), up to a size.
  thread_local std::vector<SegmentCover> cover_buffer;
  constexpr std::size_t kKeptCovers = 4096;
  if (cover_buffer.size() < path.segments.size()) cover_buffer.resize(path.segments.size());
  struct Trim {
    ~Trim() {
      if (cover_buffer.size() > kKeptCovers) {
        cover_buffer.resize(kKeptCovers);
        cover_buffer.shrink_to_fit();
      }
    }
  } trim;
  std::vector<SegmentCover>& covers = cover_buffer;

  // Whether the joint from segment `in` to segment `out` is smooth (stroke.hpp): the
  // directions there agree to within the snap's angle, B' does not vanish at either side,
  // and no parallel curve has a cusp there.
  auto smooth_joint = [&](std::size_t in, std::size_t out) {
    const core::Curve& a = path.segments[in];
    const core::Curve& b = path.segments[out];
    if (covers[in].cusp_at_end || covers[out].cusp_at_start) return false;
    if (stationary_end(a, false) || stationary_end(b, true)) return false;
    const Point2 t0 = end_tangent(a.points(), false), t1 = end_tangent(b.points(), true);
    return core::dot(t0, t1) > 0.0 && sizes.reach * std::fabs(core::cross(t0, t1)) <= 0.25 * sizes.snap;
  };

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
  const std::size_t cap_size = style.cap == LineCap::round    ? sizes.circle_pieces
                               : style.cap == LineCap::square ? 4
                                                              : 0;

  // Per subpath, reused from one to the next.
  std::vector<std::size_t> drawn;
  std::vector<char> smooth;
  for (const path::Subpath& sub : path.subpaths) {
    drawn_segments(path, sub, drawn);
    if (!sink.charge(static_cast<std::int64_t>(sub.segment_count) * 16)) break;
    if (drawn.empty()) {
      if (!sink.reserve(2 * cap_size)) break;
      const Point2 point = path.segments[sub.first_segment].front();
      add_cap(point, {-1.0, 0.0});
      add_cap(point, {1.0, 0.0});
      continue;
    }
    for (const std::size_t k : drawn) {
      if (!cover_segment(path.segments[k], sizes, sink, covers[k])) break;
    }
    if (!sink.ok()) break;

    // Joint j is before drawn[j]; joint 0 is the closing joint of a closed subpath.
    const std::size_t m = drawn.size();
    smooth.assign(m, 0);
    std::size_t joins = 0;
    for (std::size_t j = 0; j < m; ++j) {
      if (j == 0 && !sub.closed) continue;
      smooth[j] = smooth_joint(drawn[(j + m - 1) % m], drawn[j]) ? 1 : 0;
      if (!smooth[j]) ++joins;
    }
    if (!sink.reserve(joins * (round_join ? sizes.circle_pieces : 4) +
                      (sub.closed ? 0 : 2 * cap_size))) {
      break;
    }

    // The runs: stretches joined across smooth joints, broken at the other joints, at zeros
    // of B' and at the ends of an open subpath. A closed subpath is walked from a break, if
    // it has one.
    struct Step {
      StretchEdges* stretch;
      bool break_before;  // a run starts here
      bool at_zero;       // ... at a zero of B' inside the segment
      // The edge curves of the stretches from this one to the end of its run.
      std::size_t right_to_end = 0, left_to_end = 0;
    };
    std::vector<Step> steps;
    std::size_t stretch_count = 0;
    for (std::size_t j = 0; j < m; ++j) stretch_count += covers[drawn[j]].stretches.size();
    steps.reserve(stretch_count);
    for (std::size_t j = 0; j < m; ++j) {
      std::vector<StretchEdges>& stretches = covers[drawn[j]].stretches;
      for (std::size_t i = 0; i < stretches.size(); ++i) {
        const bool joint_break = j == 0 ? !sub.closed || !smooth[0] : !smooth[j];
        steps.push_back({&stretches[i], i > 0 || joint_break, i > 0});
      }
    }
    const auto first_break =
        std::find_if(steps.begin(), steps.end(), [](const Step& st) { return st.break_before; });
    const bool any_break = first_break != steps.end();
    std::rotate(steps.begin(), any_break ? first_break : steps.begin(), steps.end());
    for (std::size_t i = steps.size(); i-- > 0;) {
      const bool last = i + 1 == steps.size() || steps[i + 1].break_before;
      steps[i].right_to_end = steps[i].stretch->right.size() + (last ? 0 : steps[i + 1].right_to_end);
      steps[i].left_to_end = steps[i].stretch->left.size() + (last ? 0 : steps[i + 1].left_to_end);
    }
    Run run(sizes.snap);
    for (const Step& st : steps) {
      if (st.break_before && !run.empty() && !sink.add(run.open_contour(st.at_zero))) break;
      if (run.empty()) run.reserve(st.right_to_end, st.left_to_end);
      run.add(*st.stretch, st.at_zero);
    }
    if (!sink.ok()) break;
    if (!any_break) {
      auto [right, left] = run.closed_contours();
      if (!sink.add(std::move(right)) || !sink.add(std::move(left))) break;
    } else if (!sink.add(run.open_contour(sub.closed && steps.front().at_zero))) {
      break;
    }

    for (std::size_t j = 0; j < m; ++j) {
      if (j == 0 && !sub.closed) continue;
      if (!smooth[j]) add_join(path.segments[drawn[(j + m - 1) % m]], path.segments[drawn[j]]);
    }
    if (!sub.closed) {
      const core::Curve& first_segment = path.segments[drawn.front()];
      const core::Curve& last_segment = path.segments[drawn.back()];
      add_cap(first_segment.front(), -end_tangent(first_segment.points(), true));
      add_cap(last_segment.back(), end_tangent(last_segment.points(), false));
    }
    if (!sink.ok()) break;
  }
  if (!sink.ok()) return {sink.status(), {}, 0};
  StrokeOutline result;
  result.segment_count = sink.segment_count();
  result.contours = sink.take_contours();
  return result;
}

}  // namespace bezier::outline
