// libFuzzer target: core::classify (cubic classification) on arbitrary finite control
// points.
//
// Checks (core/cubic/classify.hpp, and cubic_type.hpp are the contract):
//  - the type equals the exact oracle's (tests/core/cubic/classify_oracle.hpp: the canonical
//    point in rationals, sharing no code with core/) whenever classify() says its
//    decisions were exact;
//  - the fields agree with the type: a cusp parameter exactly for `cusp`, a double point
//    on the segment exactly for the loop types (t1 = 0 for loop-at-start, t2 = 1 for
//    loop-at-end), 2 / 1 / 0 inflections for double-inflection / single-inflection / arch
//    and none for point, line, quadratic; parameters in [0,1] and increasing; the Loop–
//    Blinn class consistent with the type; no canonical point for collinear P0, P1, P2;
//  - invariance: the same type after swapping x and y, negating, scaling by a power of two
//    (all exact), and the mirrored type after reversal (t -> 1 - t).
// Only finite coordinates: classify() requires them (api/ rejects non-finite numbers).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <span>
#include <string>

#include "core/cubic/classify.hpp"
#include "tests/core/cubic/classify_oracle.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

using bezier::core::CubicClassification;
using bezier::core::CubicType;
using bezier::core::LoopBlinnClass;
using bezier::core::Point2;
using bezier::fuzz::check;
using Cubic = std::array<Point2, 4>;

std::string describe(const Cubic& p) {
  std::string s = "P = [";
  char buf[64];
  for (const Point2& q : p) {
    std::snprintf(buf, sizeof buf, "(%a, %a) ", q.x, q.y);
    s += buf;
  }
  return s + "]";
}

std::string type_name(CubicType t) {
  return std::string(bezier::core::to_string(t));
}

bool is_loop(CubicType t) {
  return t == CubicType::loop || t == CubicType::loop_at_start || t == CubicType::loop_at_end;
}

bool in_unit(double t) {
  return 0.0 <= t && t <= 1.0;
}

void check_fields(const Cubic& p, const CubicClassification& c) {
  const auto ctx = [&] { return type_name(c.type) + " for " + describe(p); };
  check(c.cusp.has_value() == (c.type == CubicType::cusp),
        [&] { return "cusp field vs type " + ctx(); });
  if (c.cusp) check(in_unit(*c.cusp), [&] { return "cusp outside [0,1]: " + ctx(); });
  check(c.self_intersection.has_value() == is_loop(c.type),
        [&] { return "double point vs type " + ctx(); });
  if (const auto& d = c.self_intersection) {
    check(d->on_segment && in_unit(d->t1) && in_unit(d->t2) && d->t1 <= d->t2 &&
              bezier::fuzz::is_finite(d->point),
          [&] { return "double point not on the segment or not ordered: " + ctx(); });
    if (c.type == CubicType::loop_at_start)
      check(d->t1 == 0.0, [&] { return "loop-at-start with t1 != 0: " + ctx(); });
    if (c.type == CubicType::loop_at_end)
      check(d->t2 == 1.0, [&] { return "loop-at-end with t2 != 1: " + ctx(); });
  }
  const auto inflections = c.inflections.values();
  check(inflections.size() <= 2, [&] { return "more than 2 inflections: " + ctx(); });
  for (std::size_t i = 0; i < inflections.size(); ++i) {
    check(in_unit(inflections[i]), [&] { return "inflection outside [0,1]: " + ctx(); });
    // Non-decreasing: two distinct roots closer than an ulp round to the same double
    // (found by this target: a cubic next to the cusp at t = 1 got inflections {1, 1}).
    if (i > 0)
      check(inflections[i - 1] <= inflections[i],
            [&] { return "inflections decreasing: " + ctx(); });
  }
  std::size_t expected_inflections = 3;  // 3: not determined by the type
  switch (c.type) {
    case CubicType::double_inflection:
      expected_inflections = 2;
      break;
    case CubicType::single_inflection:
      expected_inflections = 1;
      break;
    case CubicType::arch:
    case CubicType::point:
    case CubicType::line:
    case CubicType::quadratic:
      expected_inflections = 0;
      break;
    default:
      break;
  }
  if (expected_inflections != 3) {
    check(inflections.size() == expected_inflections,
          [&] { return "inflection count vs type " + ctx(); });
  }
  const auto lb = c.loop_blinn;
  check((c.type == CubicType::point) == (lb == LoopBlinnClass::point),
        [&] { return "Loop-Blinn point " + ctx(); });
  check((c.type == CubicType::line) == (lb == LoopBlinnClass::line),
        [&] { return "Loop-Blinn line " + ctx(); });
  check((c.type == CubicType::quadratic) == (lb == LoopBlinnClass::quadratic),
        [&] { return "Loop-Blinn quadratic " + ctx(); });
  if (c.type == CubicType::cusp)
    check(lb == LoopBlinnClass::cusp, [&] { return "cusp not in the cusp class " + ctx(); });
  if (is_loop(c.type))
    check(lb == LoopBlinnClass::loop, [&] { return "loop not in the loop class " + ctx(); });
  if (c.canonical_point) {
    check(bezier::fuzz::is_finite(*c.canonical_point),
          [&] { return "non-finite canonical point " + ctx(); });
  }
}

/// Whether the rational oracle is affordable: exact products of coordinates whose binary
/// exponents span more than a few hundred make the BigInt arithmetic of tests/support
/// take milliseconds, which would slow the whole run a hundredfold.
bool oracle_affordable(const Cubic& p) {
  int lo = 4096, hi = -4096;
  for (const Point2& q : p) {
    for (const double v : {q.x, q.y}) {
      if (v == 0.0) continue;
      int e = 0;
      (void)std::frexp(v, &e);
      lo = std::min(lo, e);
      hi = std::max(hi, e);
    }
  }
  return hi - lo <= 160;
}

/// Whether P0, P1, P2 are exactly collinear.
bool collinear_start(const Cubic& p) {
  using bezier::test::exact;
  const auto u = exact(p[1]) - exact(p[0]), v = exact(p[2]) - exact(p[0]);
  return bezier::test::exact_cross(u, v).is_zero();
}

/// p with f applied to every point, when that is exact for every coordinate.
template <class F>
std::optional<Cubic> mapped(const Cubic& p, F f) {
  Cubic q;
  for (std::size_t i = 0; i < 4; ++i) {
    const auto r = f(p[i]);
    if (!r) return std::nullopt;
    q[i] = *r;
  }
  return q;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider provider(data, size);
  const int scale_exponent = provider.ConsumeIntegralInRange<int>(-40, 40);
  bezier::fuzz::NumberSource numbers(provider);
  Cubic p;
  for (Point2& q : p) {
    q.x = numbers.finite();
    q.y = numbers.finite();
  }

  const CubicClassification c = bezier::core::classify(std::span<const Point2, 4>(p));
  check_fields(p, c);
  const bool use_oracle = oracle_affordable(p);
  if (c.exact && use_oracle) {
    const CubicType expected = bezier::test::exact_type(p);
    check(c.type == expected, [&] {
      return "type " + type_name(c.type) + ", exact oracle says " + type_name(expected) + ": " +
             describe(p);
    });
  }
  if (use_oracle && collinear_start(p)) {
    check(!c.canonical_point.has_value(),
          [&] { return "canonical point for collinear P0, P1, P2: " + describe(p); });
  }

  const auto same_type = [&](const Cubic& q, CubicType expected, const char* what) {
    const CubicClassification d = bezier::core::classify(std::span<const Point2, 4>(q));
    check_fields(q, d);
    if (!(c.exact && d.exact)) return;
    check(d.type == expected, [&] {
      return std::string(what) + ": " + type_name(d.type) + " instead of " + type_name(expected) +
             " for " + describe(p);
    });
  };
  const auto swapped = mapped(p, [](Point2 q) { return std::optional<Point2>(Point2{q.y, q.x}); });
  same_type(*swapped, c.type, "x <-> y");
  const auto negated = mapped(p, [](Point2 q) {
    return std::optional<Point2>(Point2{-q.x, -q.y});
  });
  same_type(*negated, c.type, "negated");
  const auto scaled = mapped(p, [&](Point2 q) -> std::optional<Point2> {
    const Point2 r{std::ldexp(q.x, scale_exponent), std::ldexp(q.y, scale_exponent)};
    if (!bezier::fuzz::is_finite(r) || std::ldexp(r.x, -scale_exponent) != q.x ||
        std::ldexp(r.y, -scale_exponent) != q.y) {
      return std::nullopt;
    }
    return r;
  });
  if (scaled) same_type(*scaled, c.type, "scaled by a power of two");
  const Cubic reversed{p[3], p[2], p[1], p[0]};
  const bool closed = p[0] == p[3] && c.type == CubicType::loop_at_start;
  same_type(reversed, closed ? c.type : bezier::test::mirrored(c.type), "reversed");
  return 0;
}
