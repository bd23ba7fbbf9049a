#pragma once

#include <cstddef>

#include "core/intersect/result.hpp"

namespace bezier::path {

/// An intersection located on two segments: `intersection.t` (and its interval) is on
/// segment `segment_t`, `intersection.s` on segment `segment_s`, each the segment's own
/// parameter in [0, 1]. With two paths, segment_t is in the first and segment_s in the
/// second; with one path both are in it.
struct PathContact {
  std::size_t segment_t = 0;
  std::size_t segment_s = 0;
  core::Intersection intersection;
};

/// Coincident pieces of two segments (core::Overlap's intervals on segment_t and segment_s).
struct PathOverlap {
  std::size_t segment_t = 0;
  std::size_t segment_s = 0;
  core::Overlap overlap;
};

}  // namespace bezier::path
