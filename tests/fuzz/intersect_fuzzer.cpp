// libFuzzer target: core::intersect (curve-curve intersection) on arbitrary finite control
// points, any degrees 0..20, every method and option.
//
// Checks on every result (core/intersect/intersect.hpp and result.hpp are the contract):
//  - status: tolerance_too_small exactly when tolerance < kMinTolerance (and then nothing
//    reported), otherwise ok or work_cap_reached;
//  - each intersection: finite estimate and point, intervals inside [0,1] containing the
//    estimate, narrower than the tolerance when `resolved`, sorted by t then s, and f(t)
//    close to g(s) (within what the interval widths allow: |f'| <= 2 n scale(f));
//  - each overlap: intervals inside [0,1], sorted by t, end points matching;
//  - end points equal bit for bit are roots, so they lie in a reported box;
//  - swapping the curves swaps the answer, and scaling both by a power of two
//    changes no parameter (the working frame is exact).
// Only finite coordinates: intersect() asserts them (api/ rejects non-finite numbers).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/curve/evaluate.hpp"
#include "core/intersect/intersect.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

using bezier::core::Curve;
using bezier::core::IntersectionResult;
using bezier::core::IntersectOptions;
using bezier::core::IntersectStatus;
using bezier::core::ParamInterval;
using bezier::core::Point2;
using bezier::fuzz::check;

/// Mostly low degrees (where most inputs are), sometimes up to the API's 20; never more
/// points than the bytes left can describe (an exhausted provider yields zeros, and curves
/// of a dozen points at the origin would crowd out everything else).
int pick_degree(FuzzedDataProvider& data) {
  const auto b = data.ConsumeIntegral<std::uint8_t>();
  const int wanted = b < 224 ? b % 5 : b % 21;
  return std::min(wanted, static_cast<int>(data.remaining_bytes() / 4));
}

bool inside_unit(ParamInterval i) {
  return 0.0 <= i.lo && i.lo <= i.hi && i.hi <= 1.0;
}

bool meets(ParamInterval a, ParamInterval b) {
  return a.lo <= b.hi && b.lo <= a.hi;
}

std::string describe(const Curve& f, const Curve& g, const IntersectOptions& o) {
  std::string s = "f = [";
  char buf[64];
  for (const Point2& p : f.points()) {
    std::snprintf(buf, sizeof buf, "(%a, %a) ", p.x, p.y);
    s += buf;
  }
  s += "], g = [";
  for (const Point2& p : g.points()) {
    std::snprintf(buf, sizeof buf, "(%a, %a) ", p.x, p.y);
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "], tolerance %a, method %d, fat curve %d", o.tolerance,
                static_cast<int>(o.method), o.fat_curve_degree);
  return s + buf;
}

/// Upper bound of |B'| on [0,1]: the hodograph's control points n (P_{i+1} − P_i) are at
/// most 2 n scale in each coordinate, times √2 for the length.
double derivative_bound(const Curve& c) {
  return 3.0 * c.degree() * bezier::core::scale(c);
}

/// The larger side of the bounding box of the control points of c and d.
double extent(const Curve& c, const Curve& d) {
  double lo_x = c.front().x, hi_x = lo_x, lo_y = c.front().y, hi_y = lo_y;
  for (const Curve* k : {&c, &d}) {
    for (const Point2& p : k->points()) {
      lo_x = std::fmin(lo_x, p.x), hi_x = std::fmax(hi_x, p.x);
      lo_y = std::fmin(lo_y, p.y), hi_y = std::fmax(hi_y, p.y);
    }
  }
  return std::fmax(hi_x - lo_x, hi_y - lo_y);
}

/// Whether c spans less than 2^-40 of the bounding box of both curves (a degree-0 curve
/// always): finding F20.
bool point_like(const Curve& c, const Curve& other) {
  return extent(c, c) <= 0x1p-40 * extent(c, other);
}

/// Whether c' vanishes at an end (P0 = P1 or P(n-1) = Pn): finding F20.
bool has_flat_end(const Curve& c) {
  return c.degree() >= 1 && (c[0] == c[1] || c[c.degree() - 1] == c.back());
}

void check_result(const Curve& f, const Curve& g, const IntersectOptions& options,
                  const IntersectionResult& r, bool wild) {
  const auto context = [&] { return describe(f, g, options); };
  if (!(options.tolerance >= bezier::core::kMinTolerance)) {
    check(r.status == IntersectStatus::tolerance_too_small && r.intersections.empty() &&
              r.overlaps.empty(),
          [&] { return "tolerance below kMinTolerance not reported: " + context(); });
    return;
  }
  check(r.status == IntersectStatus::ok || r.status == IntersectStatus::work_cap_reached, [&] {
    return "unexpected status " + std::to_string(static_cast<int>(r.status)) + ": " + context();
  });

  const double scale = std::fmax(bezier::core::scale(f), bezier::core::scale(g));
  // (At least a few subnormal steps: a segment one subnormal long has two points.)
  const double rounding = std::fmax(0x1p-40 * (f.degree() + g.degree() + 2) * scale, 0x1p-1070);
  for (std::size_t i = 0; i < r.intersections.size(); ++i) {
    const auto& x = r.intersections[i];
    const auto where = [&] { return "intersection " + std::to_string(i) + " of " + context(); };
    check(std::isfinite(x.t) && std::isfinite(x.s) && bezier::fuzz::is_finite(x.point),
          [&] { return "non-finite estimate or point, " + where(); });
    check(inside_unit(x.t_interval) && inside_unit(x.s_interval),
          [&] { return "interval outside [0,1], " + where(); });
    check(x.t_interval.contains(x.t) && x.s_interval.contains(x.s),
          [&] { return "estimate outside its interval, " + where(); });
    if (x.resolved && !wild) {
      // (Findings F2, fixed by 0308300: a tiny curve's [0, 1] was flagged resolved; F10.)
      check(x.t_interval.width() < options.tolerance && x.s_interval.width() < options.tolerance,
            [&] { return "resolved interval not narrower than the tolerance, " + where(); });
    }
    if (i > 0) {
      const auto& p = r.intersections[i - 1];
      check(p.t < x.t || (p.t == x.t && p.s <= x.s),
            [&] { return "not sorted by t then s, " + where(); });
    }
    // f(t) and g(s) are within |f'| w_t + |g'| w_s of a common point (the root in the box).
    const Point2 ft = bezier::core::evaluate(f, x.t), gs = bezier::core::evaluate(g, x.s);
    const double gap = std::fmax(std::fabs(ft.x - gs.x), std::fabs(ft.y - gs.y));
    // (0 * infinity would be NaN: a zero-width interval contributes nothing.)
    const auto drift = [](double bound, double width) {
      return width == 0.0 ? 0.0 : bound * width;
    };
    const double allowed = drift(derivative_bound(f), x.t_interval.width()) +
                           drift(derivative_bound(g), x.s_interval.width()) + rounding;
    check(gap <= allowed, [&] {
      char buf[128];
      std::snprintf(buf, sizeof buf, " (t %a, s %a, gap %a, allowed %a)", x.t, x.s, gap, allowed);
      return "f(t) and g(s) too far apart, " + where() + buf;
    });
  }
  for (std::size_t i = 0; i < r.overlaps.size(); ++i) {
    const auto& o = r.overlaps[i];
    const auto where = [&] { return "overlap " + std::to_string(i) + " of " + context(); };
    check(inside_unit(o.t_interval) && inside_unit(o.s_interval),
          [&] { return "overlap interval outside [0,1], " + where(); });
    if (i > 0) {
      check(r.overlaps[i - 1].t_interval.lo <= o.t_interval.lo,
            [&] { return "overlaps not sorted by t, " + where(); });
    }
    const Point2 f_lo = bezier::core::evaluate(f, o.t_interval.lo);
    const Point2 g_lo = bezier::core::evaluate(g, o.reversed ? o.s_interval.hi : o.s_interval.lo);
    const double gap = std::fmax(std::fabs(f_lo.x - g_lo.x), std::fabs(f_lo.y - g_lo.y));
    check(gap <= 0x1p-30 * scale + rounding,
          [&] { return "overlap ends do not match, " + where(); });
  }

  if (r.status != IntersectStatus::ok) return;
  // End points equal bit for bit are exact roots: some box (or overlap) holds them.
  for (const double te : {0.0, 1.0}) {
    for (const double se : {0.0, 1.0}) {
      const Point2 a = te == 0.0 ? f.front() : f.back();
      const Point2 b = se == 0.0 ? g.front() : g.back();
      if (!(a == b)) continue;
      // (Findings F4, F10: roots at the end of a curve below the frame's resolution, and
      // at an end where the derivative vanishes, were missed.)
      bool found = false;
      for (const auto& x : r.intersections)
        found = found || (x.t_interval.contains(te) && x.s_interval.contains(se));
      for (const auto& o : r.overlaps)
        found = found || (o.t_interval.contains(te) && o.s_interval.contains(se));
      check(found, [&] {
        return "end point root (" + std::to_string(te) + ", " + std::to_string(se) +
               ") missing: " + context();
      });
    }
  }
}

/// Both curves times 2^k, when that is exact (no overflow, no subnormal, nothing lost).
std::optional<std::array<Curve, 2>> scaled(const Curve& f, const Curve& g, int k) {
  std::array<std::vector<Point2>, 2> out;
  const std::array<const Curve*, 2> in = {&f, &g};
  for (std::size_t c = 0; c < 2; ++c) {
    for (const Point2& p : in[c]->points()) {
      const Point2 q{std::ldexp(p.x, k), std::ldexp(p.y, k)};
      for (const auto& [v, w] : {std::pair{p.x, q.x}, std::pair{p.y, q.y}}) {
        if (!std::isfinite(w) || std::ldexp(w, -k) != v) return std::nullopt;
        if (w != 0.0 && std::fabs(w) < 0x1p-1000) return std::nullopt;  // keep clear of subnormals
        if (v != 0.0 && std::fabs(v) < 0x1p-1000) return std::nullopt;
      }
      out[c].push_back(q);
    }
  }
  return std::array<Curve, 2>{Curve(std::move(out[0])), Curve(std::move(out[1]))};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider provider(data, size);
  IntersectOptions options;
  const auto config = provider.ConsumeIntegral<std::uint8_t>();
  options.method = static_cast<bezier::core::IntersectMethod>(config % 3);
  options.fat_curve_degree = (config & 4u) ? 3 : 2;
  constexpr std::array kTolerances = {1e-12, 1e-9, 1e-6, 1e-3, 0.5, 0x1p-46, 0x1p-47, 1e-15};
  options.tolerance = kTolerances[(config >> 3) % kTolerances.size()];
  // A fiftieth of the API default keeps executions fast: high-order contacts (f = (1-t)^n P0
  // against a point at the origin) spend any budget, at about 0.1 ms per step here.
  options.max_work = 4000;
  const auto flags = provider.ConsumeIntegral<std::uint8_t>();
  const bool check_symmetry = (flags & 1u) != 0;
  const bool check_scaling = (flags & 2u) != 0;
  // Wild inputs (a quarter) use the whole double range: curves 2^500 apart in size, or far
  // from the origin, are below each other's rounding (finding F2), so only the basic
  // invariants hold there. Tame inputs keep every magnitude within 2^-30 .. 2^30.
  const bool wild = (flags & 12u) == 0;
  const int scale_exponent = provider.ConsumeIntegralInRange<int>(-60, 60);

  bezier::fuzz::NumberSource numbers(provider, wild ? 0 : 30);
  const int n = pick_degree(provider);
  const int m = pick_degree(provider);
  const Curve f = bezier::fuzz::finite_curve(numbers, n);
  const Curve g = bezier::fuzz::finite_curve(numbers, m);

  if (bezier::fuzz::print_inputs()) {
    std::fprintf(stderr, "%s (wild %d, symmetry %d, scaling 2^%d: %d)\n",
                 describe(f, g, options).c_str(), wild, check_symmetry, scale_exponent,
                 check_scaling);
  }
  const IntersectionResult r = bezier::core::intersect(f, g, options);
  check_result(f, g, options, r, wild);
  // Wild inputs get no comparisons (curves 2^500 apart in size are below each other's
  // rounding, finding F2). (Findings F4, F10, F11: curves below each other's resolution, with
  // a vanishing end derivative, or in contact of order >= 3 gave answers that differed with
  // the order of the curves.)
  if (r.status != IntersectStatus::ok || wild) return 0;
  // Finding F20: a curve below 2^-40 of the other, or with a vanishing end derivative, may
  // give an overlap in one order and none in the other, or contacts placed differently in
  // the two orders.
  const bool swap_comparable =
      !point_like(f, g) && !point_like(g, f) && !has_flat_end(f) && !has_flat_end(g);
  const double scale = std::fmax(bezier::core::scale(f), bezier::core::scale(g));
  if (check_symmetry) {
    const IntersectionResult w = bezier::core::intersect(g, f, options);
    check_result(g, f, options, w, wild);
    if (w.status == IntersectStatus::ok && swap_comparable) {
      check(w.overlaps.size() == r.overlaps.size(), [&] {
        return "swapping the curves changes the overlaps (" + std::to_string(r.overlaps.size()) +
               " vs " + std::to_string(w.overlaps.size()) + "): " + describe(f, g, options);
      });
      // Every contact in one order has its mirror image in the other, except near misses at
      // an end (a curve ending an ulp away from the other: within rounding either answer is
      // right, and the two orders may decide differently).
      const auto near_miss_at_end = [&](const Curve& a, const Curve& b,
                                        const bezier::core::Intersection& x) {
        const bool at_end = x.t == 0.0 || x.t == 1.0 || x.s == 0.0 || x.s == 1.0;
        const Point2 p = bezier::core::evaluate(a, x.t), q = bezier::core::evaluate(b, x.s);
        return at_end && std::fmax(std::fabs(p.x - q.x), std::fabs(p.y - q.y)) <= 0x1p-48 * scale;
      };
      for (const auto& [from, to, a, b] :
           {std::tuple{&w, &r, &g, &f}, std::tuple{&r, &w, &f, &g}}) {
        for (const auto& x : from->intersections) {
          bool matched = false;
          for (const auto& y : to->intersections) {
            matched =
                matched || (meets(x.t_interval, y.s_interval) && meets(x.s_interval, y.t_interval));
          }
          check(matched || near_miss_at_end(*a, *b, x), [&] {
            char buf[96];
            std::snprintf(buf, sizeof buf, " (t %a, s %a)", x.t, x.s);
            return std::string("an intersection has no mirror image after swapping the curves") +
                   buf + ": " + describe(f, g, options);
          });
        }
      }
    }
  }
  if (check_scaling) {
    if (const auto c = scaled(f, g, scale_exponent)) {
      const IntersectionResult s = bezier::core::intersect((*c)[0], (*c)[1], options);
      check(s.status == r.status && s.intersections.size() == r.intersections.size() &&
                s.overlaps.size() == r.overlaps.size(),
            [&] {
              return "scaling by 2^" + std::to_string(scale_exponent) +
                     " changes the answer: " + describe(f, g, options);
            });
      for (std::size_t i = 0; i < s.intersections.size(); ++i) {
        const auto& a = r.intersections[i];
        const auto& b = s.intersections[i];
        check(a.t == b.t && a.s == b.s && a.t_interval == b.t_interval &&
                  a.s_interval == b.s_interval && a.kind == b.kind,
              [&] {
                char buf[160];
                std::snprintf(buf, sizeof buf, " (t %a vs %a, s %a vs %a)", a.t, b.t, a.s, b.s);
                return "scaling by 2^" + std::to_string(scale_exponent) + " changes intersection " +
                       std::to_string(i) + buf + ": " + describe(f, g, options);
              });
      }
    }
  }
  return 0;
}
