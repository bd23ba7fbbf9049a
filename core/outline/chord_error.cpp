#include "core/outline/chord_error.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <vector>

#include "core/outline/tuning.hpp"

namespace bezier::outline {

namespace {

using core::Point2;

/// The left (keep_left) or right part of the curve with control points `q` split at t by de
/// Casteljau's algorithm, in place.
void keep_part(std::vector<Point2>& q, double t, bool keep_left) {
  const std::size_t n = q.size() - 1;
  if (keep_left) {
    // L_k = b_0^k(t): after round k the first point is final; the rest of the row moves on.
    for (std::size_t k = 1; k <= n; ++k)
      for (std::size_t i = n; i >= k; --i) q[i] = core::lerp(q[i - 1], q[i], t);
  } else {
    for (std::size_t k = 1; k <= n; ++k)
      for (std::size_t i = 0; i + k <= n; ++i) q[i] = core::lerp(q[i], q[i + 1], t);
  }
}

/// A piece of the curve in the chord's frame: (e, d) = (along the chord from Q_0, across it).
struct Piece {
  std::vector<Point2> q;
  double bound = 0.0;  ///< max over q of dist(., chord)
};

/// Distance from (e, d) in the chord's frame to the chord [0, length] on the e axis.
double distance_to_chord(Point2 p, double length) {
  const double beyond = std::max({0.0, -p.x, p.x - length});
  return std::hypot(beyond, p.y);
}

double hull_bound(const std::vector<Point2>& q, double length) {
  double bound = 0.0;
  for (const Point2 p : q) bound = std::max(bound, distance_to_chord(p, length));
  return bound;
}

}  // namespace

ChordCheck check_chord(std::span<const Point2> points, double a, double b, double tolerance,
                       double margin) {
  assert(points.size() >= 2 && 0.0 <= a && a < b && b <= 1.0 && tolerance > 0.0);
  const auto n = static_cast<std::int64_t>(points.size()) - 1;
  const std::int64_t halving_cost = n * (n + 1) + 2 * (n + 1);
  ChordCheck check;
  check.work = outline_tuning::kChordCheckOverhead;

  // The piece on [a, b]: B on [0, b], then that on [a / b, 1].
  std::vector<Point2> q(points.begin(), points.end());
  if (b < 1.0) {
    keep_part(q, b, true);
    check.work += n * (n + 1);
  }
  if (a > 0.0) {
    keep_part(q, a / b, false);
    check.work += n * (n + 1);
  }

  // The chord's frame: origin Q_0, e along u, d across (counter-clockwise).
  const Point2 origin = q.front();
  const Point2 chord = q.back() - origin;
  const double length = core::length(chord);
  const Point2 u = length > 0.0 ? chord / length : Point2{1.0, 0.0};
  for (Point2& p : q) {
    const Point2 v = p - origin;
    p = {core::dot(v, u), core::cross(u, v)};
  }
  // The ends are on the curve and on the chord's line: exactly so in the frame.
  q.front() = {0.0, 0.0};
  q.back() = {length, 0.0};

  const double accept = tolerance - margin;
  const double resolution = outline_tuning::kChordResolution * tolerance;
  const auto by_bound = [](const Piece& x, const Piece& y) { return x.bound < y.bound; };
  std::vector<Piece> open;
  Piece whole{std::move(q), 0.0};
  whole.bound = hull_bound(whole.q, length);
  open.push_back(std::move(whole));
  // The heap's top bounds h from above; the curve points met bound it from below. Halve the
  // top until the two are within the resolution (or a point is beyond the tolerance by more
  // than it: the chord is then too long by a known factor, closely enough).
  for (int halvings = 0; halvings < outline_tuning::kChordBoundHalvings; ++halvings) {
    if (open.front().bound - check.lower <= resolution) break;
    std::pop_heap(open.begin(), open.end(), by_bound);
    Piece worst = std::move(open.back());
    open.pop_back();
    Piece right{worst.q, 0.0};
    keep_part(worst.q, 0.5, true);
    keep_part(right.q, 0.5, false);
    check.work += halving_cost;
    // The split point is a point of the curve: its distance is a lower bound of h.
    check.lower = std::max(check.lower, distance_to_chord(right.q.front(), length));
    for (Piece* half : {&worst, &right}) {
      half->bound = hull_bound(half->q, length);
      // A piece bounded below the lower bound cannot hold the largest distance.
      if (half->bound > check.lower) {
        open.push_back(std::move(*half));
        std::push_heap(open.begin(), open.end(), by_bound);
      }
    }
    if (open.empty()) break;
  }
  check.upper = open.empty() ? check.lower : std::max(open.front().bound, check.lower);
  check.within = check.upper <= accept;
  return check;
}

}  // namespace bezier::outline
