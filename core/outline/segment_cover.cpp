#include "core/outline/segment_cover.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/base/multiversion.hpp"
#include "core/curve/evaluate.hpp"
#include "core/measure/frame.hpp"
#include "core/outline/offset.hpp"
#include "core/numeric/power_of_two.hpp"
#include "core/outline/control_points.hpp"
#include "core/outline/loose_curve.hpp"
#include "core/outline/offset_cusps.hpp"
#include "core/outline/stroke_shapes.hpp"
#include "core/outline/tangent_limits.hpp"
#include "core/outline/tight_side_cover.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

/// The piece [a, b] of the segment itself as a tight side's edge, its ends B(a), B(b) as
/// the loose pieces' ends are computed (from the whole curve): its control points when it is
/// at most a cubic, else its fit at distance 0.
bool curve_edge(const core::Curve& segment, double a, double b, const CoverSizes& sizes,
                OutlineSink& sink, Contour& chain) {
  if (segment.degree() <= 3) {
    ControlPoints q;
    piece_into(segment.points(), a, b, q);
    q[0] = point_at(segment.points(), a);
    q[q.size() - 1] = point_at(segment.points(), b);
    append_to_chain(chain, core::Curve(std::vector<Point2>(q.begin(), q.end())), sizes.snap);
    return true;
  }
  std::vector<OffsetCubic> fit;
  if (!offset_interval(segment, a, b, 0.0, sizes.fit_tolerance, sink.budget(), fit)) {
    sink.fail_work();
    return false;
  }
  for (const OffsetCubic& c : fit) {
    append_to_chain(chain, core::Curve({c.points[0], c.points[1], c.points[2], c.points[3]}),
                    sizes.snap);
  }
  return true;
}

/// The signed curvature at t from the whole curve's first and second hodographs (0 where
/// B'(t) = 0).
double curvature_at(const ControlPoints& h1, const ControlPoints& h2, double t) {
  if (h2.empty()) return 0.0;
  const Point2 v = point_at(h1, t), a = point_at(h2, t);
  const double speed_squared = squared_length(v);
  if (!(speed_squared > 0.0)) return 0.0;
  return core::cross(v, a) / (speed_squared * std::sqrt(speed_squared));
}

}  // namespace

CoverSizes cover_sizes(double half_width, double tolerance) {
  CoverSizes sizes;
  sizes.radius = half_width;
  sizes.reach = half_width + tolerance / 2.0;
  sizes.fit_tolerance = 0.49 * tolerance;
  sizes.snap = 0.01 * tolerance;
  sizes.disk_radius = sizes.reach + 0.005 * tolerance;
  sizes.circle_pieces = circle_pieces(sizes.disk_radius, 0.485 * tolerance);
  return sizes;
}

BEZIER_FMA_CLONES bool cover_segment(const core::Curve& segment, const CoverSizes& sizes,
                                     OutlineSink& sink, SegmentCover& out) {
  const auto n = static_cast<std::int64_t>(segment.degree());
  out.cusp_at_start = out.cusp_at_end = false;
  if (!sink.charge(16 * (n + 1) * (n + 1))) return false;
  // The hodographs of the segment scaled by a power of two (exact): the loose bound's
  // squares stay normal doubles.
  const double size = std::max(largest_abs_coordinate(segment.points()), sizes.reach);
  const int e = -core::exponent_of(size);
  const core::PowerOfTwo factor(e);
  ControlPoints scaled(segment.points()), h1, h2;
  for (Point2& p : scaled) p = factor.times(p);
  hodograph_into(scaled, h1);
  hodograph_into(h1, h2);

  std::vector<double> cusps[2];  // left (+R), right (-R)
  std::vector<double> stationary;
  std::int64_t loose_work = 0;
  const bool loose = loose_everywhere(h1, h2, factor.times(sizes.reach), &loose_work);
  if (!sink.charge(loose_work)) return false;
  if (!loose) {
    if (!sink.charge(64 * n * n * n)) return false;
    std::int64_t cusp_work = 0;
    cusps[0] = offset_cusps(segment, sizes.reach, &cusp_work);
    cusps[1] = offset_cusps(segment, -sizes.reach, &cusp_work);
    if (!sink.charge(cusp_work)) return false;
    stationary = stationary_points(segment);
  }
  for (const std::vector<double>& side : cusps) {
    for (const double t : side) {
      if (t == 0.0) out.cusp_at_start = true;
      if (t == 1.0) out.cusp_at_end = true;
    }
  }

  std::vector<Point2> centres;
  for (const double t : stationary) {
    if (!sink.charge(16 * static_cast<std::int64_t>(sizes.circle_pieces))) return false;
    centres.push_back(core::evaluate(segment, t));
    if (!sink.add(circle(centres.back(), sizes.disk_radius, sizes.circle_pieces))) return false;
  }

  // The stretches' ends: 0, the zeros of B', 1.
  const std::size_t stretch_count = stationary.size() + 1;
  auto stretch_end = [&](std::size_t k) {
    return k == 0 ? 0.0 : k == stretch_count ? 1.0 : stationary[k - 1];
  };
  std::size_t used = 0;  // the entries of out.stretches filled
  thread_local std::vector<OffsetCubic> cubics;
  core::Coeffs cuts;
  for (std::size_t k = 0; k < stretch_count; ++k) {
    const double a = stretch_end(k), b = stretch_end(k + 1);
    if (!(b > a)) continue;
    // out's entries are reused with the room of their chains (stroke.cpp keeps its covers
    // from one stroke to the next).
    if (used == out.stretches.size()) out.stretches.emplace_back();
    StretchEdges& stretch = out.stretches[used++];
    stretch.left.clear();
    stretch.right.clear();
    stretch.start = point_at(segment.points(), a);
    stretch.end = point_at(segment.points(), b);
    // Where neither side has a cusp in (a, b) and neither is tight, both sides are the
    // parallel curves at ±R on the whole stretch: fitted together (offset_interval_sides,
    // the same cubics as one offset_interval per side).
    auto inside_count = [&](const std::vector<double>& side) {
      return std::count_if(side.begin(), side.end(), [&](double t) { return t > a && t < b; });
    };
    const double reach = factor.times(sizes.reach);
    const double middle_curvature = curvature_at(h1, h2, 0.5 * (a + b));
    if (inside_count(cusps[0]) == 0 && inside_count(cusps[1]) == 0 &&
        !(middle_curvature * reach > 1.0) && !(-middle_curvature * reach > 1.0)) {
      cubics.clear();
      thread_local std::vector<OffsetCubic> other_side;
      other_side.clear();
      if (!offset_interval_sides(segment, a, b, sizes.reach, sizes.fit_tolerance, sink.budget(),
                                 cubics, other_side)) {
        sink.fail_work();
        return false;
      }
      for (int side = 0; side < 2; ++side) {
        Contour& chain = side == 0 ? stretch.left : stretch.right;
        for (const OffsetCubic& c : side == 0 ? cubics : other_side) {
          append_to_chain(chain,
                          core::Curve({c.points[0], c.points[1], c.points[2], c.points[3]}),
                          sizes.snap);
        }
      }
      continue;
    }
    for (int side = 0; side < 2; ++side) {
      const double sign = side == 0 ? 1.0 : -1.0;
      Contour& chain = side == 0 ? stretch.left : stretch.right;
      // The side's cuts in (a, b): its cusps there (ascending, offset_cusps.hpp).
      std::size_t inside = 0;
      for (const double t : cusps[side])
        if (t > a && t < b) ++inside;
      cuts.resize(inside + 2, core::Coeffs::Uninitialized{});
      cuts[0] = a;
      std::size_t next = 1;
      for (const double t : cusps[side])
        if (t > a && t < b) cuts[next++] = t;
      cuts[next] = b;
      for (std::size_t j = 0; j + 1 < cuts.size(); ++j) {
        const double c0 = cuts[j], c1 = cuts[j + 1];
        if (!(c1 > c0)) continue;
        const bool tight =
            sign * curvature_at(h1, h2, 0.5 * (c0 + c1)) * factor.times(sizes.reach) > 1.0;
        if (!tight) {
          cubics.clear();
          if (!offset_interval(segment, c0, c1, sign * sizes.reach, sizes.fit_tolerance,
                               sink.budget(), cubics)) {
            sink.fail_work();
            return false;
          }
          for (const OffsetCubic& c : cubics) {
            append_to_chain(chain,
                            core::Curve({c.points[0], c.points[1], c.points[2], c.points[3]}),
                            sizes.snap);
          }
          continue;
        }
        if (!curve_edge(segment, c0, c1, sizes, sink, chain)) return false;
        cover_tight_side(segment, c0, c1, sign, sizes, sink, centres);
        if (!sink.ok()) return false;
      }
    }
  }
  out.stretches.resize(used);
  return sink.ok();
}

}  // namespace bezier::outline
