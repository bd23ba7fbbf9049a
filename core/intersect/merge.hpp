#pragma once

#include <span>
#include <vector>

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

/// Groups candidate boxes into contacts, so that a root found from several boxes (a root
/// on a split line, a tangency seen by a chain of small boxes, an exact end-point root and
/// the boxes that converged onto it) is reported once. Two boxes belong to the same contact
/// when their t intervals and their s intervals both overlap or lie within `gap` of each
/// other; the relation is closed transitively (union-find over a sweep in t, O(k log k)
/// plus the touching pairs). Contacts come out sorted by t.lo.
[[nodiscard]] std::vector<Contact> merge_candidates(std::span<const SearchCandidate> candidates,
                                                    std::span<const ExactRoot> exact_roots,
                                                    double gap);

}  // namespace bezier::core
