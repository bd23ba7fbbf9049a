#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/base/curve.hpp"
#include "core/path/path.hpp"
#include "core/region/fill_rule.hpp"

namespace bezier::region {

/// A region of the plane (DESIGN.md §8): a path whose subpaths are all closed, and the
/// fill rule that says which points it holds: those whose winding number w.r.t. the path
/// satisfies the rule (fills(), fill_rule.hpp).
///
/// Invariant: every subpath of `path` is closed (its last segment ends bit for bit where its
/// first starts, Subpath::closed is true); the path may have no segment (the empty region).
struct Region {
  path::Path path;
  FillRule fill_rule = FillRule::nonzero;
};

/// The region a path fills under `rule`, as SVG fills it: every open subpath is closed by a
/// line from its end to its start (a subpath that already ends where it starts is marked
/// closed, with no segment added). The path's arc_tolerance stays with it.
[[nodiscard]] Region region_from_path(path::Path path, FillRule rule);

/// Where a list of curves breaks the chain rule of region_from_curves: the index of the
/// first curve that neither starts exactly at the end of the curve before it nor follows a
/// curve that closed its chain; nullopt when there is none.
[[nodiscard]] std::optional<std::size_t> chain_break(const std::vector<core::Curve>& curves);

/// The region of `curves` (any degree) under `rule`. The curves form chains: each curve
/// starts exactly at the end of the one before, until one ends exactly where its chain
/// started; that closes the chain, and the next curve starts a new chain anywhere. Each
/// chain is a subpath; a last chain that is not closed is closed by a line, as SVG closes
/// an open subpath for filling. Precondition: !chain_break(curves).
[[nodiscard]] Region region_from_curves(std::vector<core::Curve> curves, FillRule rule);

}  // namespace bezier::region
