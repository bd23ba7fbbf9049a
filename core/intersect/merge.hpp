#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/base/work_budget.hpp"
#include "core/intersect/result.hpp"
#include "core/intersect/search.hpp"

namespace bezier::core {

/// A root known exactly: an end point of f equal to an end point of g, bit for bit.
struct ExactRoot {
  double t = 0.0;
  double s = 0.0;
};

/// One contact between the curves: the union of candidate boxes that touch each other.
struct Contact {
  ParamInterval t;       ///< hull of the boxes' t intervals
  ParamInterval s;       ///< hull of the boxes' s intervals
  bool resolved = true;  ///< every box reached the search width
  int boxes = 0;
  bool exact = false;  ///< holds an exact root (below)
  ExactRoot exact_root;
};

/// The contacts, sorted by t.lo.
struct MergedContacts {
  std::vector<Contact> contacts;
};

/// Groups candidate boxes into contacts, so that a root found from several boxes (a root
/// on a split line, a tangency seen by a chain of small boxes, an exact end-point root and
/// the boxes that converged onto it) is reported once. Two boxes belong to the same contact
/// when their t intervals and their s intervals both overlap or lie within `gap` of each
/// other; the relation is closed transitively (box_components.hpp: O(k log k) whatever the
/// number of touching pairs). Unresolved contacts are then joined as merge.cpp describes.
/// Each grouping (merge_cost, work_cost.hpp) is reserved from `budget` before it runs, and
/// none runs that the budget does not cover: when it runs out, `contacts` is empty if it
/// did not cover the first grouping, and otherwise not every unresolved contact that
/// should be one has been joined.
[[nodiscard]] MergedContacts merge_candidates(std::span<const SearchCandidate> candidates,
                                              std::span<const ExactRoot> exact_roots, double gap,
                                              WorkBudget& budget);

}  // namespace bezier::core
