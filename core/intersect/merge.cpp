#include "core/intersect/merge.hpp"

#include <algorithm>
#include <limits>

#include "core/intersect/box_components.hpp"
#include "core/intersect/work_cost.hpp"

namespace bezier::core {

namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

struct Item {
  ParamInterval t, s;
  bool resolved = true;
  bool exact = false;
  ExactRoot root;
};

bool near(ParamInterval a, ParamInterval b, double gap) noexcept {
  return b.lo <= a.hi + gap && a.lo <= b.hi + gap;
}

double extent(const Contact& c) noexcept {
  return std::max(c.t.width(), c.s.width());
}

void absorb(Contact& into, const Contact& c) {
  into.t = {std::min(into.t.lo, c.t.lo), std::max(into.t.hi, c.t.hi)};
  into.s = {std::min(into.s.lo, c.s.lo), std::max(into.s.hi, c.s.hi)};
  into.resolved = into.resolved && c.resolved;
  into.boxes += c.boxes;
  if (c.exact) {
    into.exact = true;
    into.exact_root = c.exact_root;
  }
}

/// A contact's hull grown by its extent on every side.
ClosedBox grown(const Contact& c) noexcept {
  const double e = extent(c);
  return {{c.t.lo - e, c.t.hi + e}, {c.s.lo - e, c.s.hi + e}};
}

/// Boxes left at the precision floor (unresolved) trace a contact of order >= 3 as a tube
/// along the stretch where the curves agree to within rounding, and the search's decisions
/// there, at the floor, can leave holes in the tube several boxes long (a third-order
/// contact at an end: Merge.HighOrderContactIsReportedOnce). Two unresolved contacts are one when the gap between them, in t and in s,
/// is at most the sum of their extents (their hulls grown by their extents meet); repeated
/// until nothing changes, as joined contacts grow. Each round is one box_components over
/// the unresolved contacts (O(u log u)), charged before it runs; the contacts joined keep
/// the place of the first of them.
void merge_unresolved(MergedContacts& merged, WorkBudget& budget) {
  std::vector<Contact>& contacts = merged.contacts;
  for (;;) {
    std::vector<std::size_t> unresolved;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      if (!contacts[i].resolved) unresolved.push_back(i);
    }
    if (unresolved.size() < 2) return;
    const std::int64_t cost = merge_cost(static_cast<std::int64_t>(unresolved.size()));
    if (!budget.reserve(cost)) return;
    budget.charge(cost);
    std::vector<ClosedBox> boxes;
    boxes.reserve(unresolved.size());
    for (const std::size_t i : unresolved) boxes.push_back(grown(contacts[i]));
    const std::vector<std::size_t> label = box_components(boxes);
    std::vector<std::size_t> first_of(unresolved.size(), kNone);  // by label
    std::vector<bool> absorbed(contacts.size(), false);
    bool joined = false;
    for (std::size_t j = 0; j < unresolved.size(); ++j) {
      std::size_t& first = first_of[label[j]];
      if (first == kNone) {
        first = unresolved[j];
        continue;
      }
      absorb(contacts[first], contacts[unresolved[j]]);
      absorbed[unresolved[j]] = true;
      joined = true;
    }
    if (!joined) return;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      if (!absorbed[i]) contacts[kept++] = contacts[i];
    }
    contacts.resize(kept);
  }
}

/// One box, or a few resolved ones no two within `gap` of each other in both t and s: the
/// sweep below would leave each one a contact of its own.
bool each_its_own_contact(std::span<const SearchCandidate> candidates, double gap) noexcept {
  if (candidates.size() == 1) return true;
  if (candidates.size() > 8) return false;  // the sweep's sort beats the pairwise test
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!candidates[i].resolved) return false;
    for (std::size_t j = i + 1; j < candidates.size(); ++j) {
      if (near(candidates[i].t, candidates[j].t, gap) && near(candidates[i].s, candidates[j].s, gap))
        return false;
    }
  }
  return true;
}

}  // namespace

MergedContacts merge_candidates(std::span<const SearchCandidate> candidates,
                                std::span<const ExactRoot> exact_roots, double gap,
                                WorkBudget& budget) {
  MergedContacts merged;
  if (candidates.empty() && exact_roots.empty()) return merged;
  const std::int64_t cost =
      merge_cost(static_cast<std::int64_t>(candidates.size() + exact_roots.size()));
  if (!budget.reserve(cost)) return merged;
  budget.charge(cost);
  std::vector<Contact>& contacts = merged.contacts;
  // The common cases, without the sweep's bookkeeping.
  if (exact_roots.empty() && each_its_own_contact(candidates, gap)) {
    // One crossing, or two or three separate ones: the usual cases.
    contacts.reserve(candidates.size());
    for (const SearchCandidate& c : candidates)
      contacts.push_back({c.t, c.s, c.resolved, 1, false, {}});
    std::sort(contacts.begin(), contacts.end(),
              [](const Contact& a, const Contact& b) { return a.t.lo < b.t.lo; });
    return merged;
  }
  std::vector<Item> items;
  items.reserve(candidates.size() + exact_roots.size());
  for (const SearchCandidate& c : candidates) items.push_back({c.t, c.s, c.resolved, false, {}});
  for (const ExactRoot& r : exact_roots) items.push_back({{r.t, r.t}, {r.s, r.s}, true, true, r});
  std::sort(items.begin(), items.end(),
            [](const Item& a, const Item& b) { return a.t.lo < b.t.lo; });
  // Two boxes are within `gap` of each other in t and in s exactly when their intervals
  // extended by `gap` upwards meet.
  std::vector<ClosedBox> boxes;
  boxes.reserve(items.size());
  for (const Item& item : items) {
    boxes.push_back({{item.t.lo, item.t.hi + gap}, {item.s.lo, item.s.hi + gap}});
  }
  const std::vector<std::size_t> label = box_components(boxes);
  std::vector<std::size_t> index_of(items.size(), kNone);  // by label
  for (std::size_t i = 0; i < items.size(); ++i) {
    std::size_t& index = index_of[label[i]];
    if (index == kNone) {
      index = contacts.size();
      contacts.push_back({items[i].t, items[i].s, true, 0, false, {}});
    }
    absorb(contacts[index],
           {items[i].t, items[i].s, items[i].resolved, 1, items[i].exact, items[i].root});
  }
  merge_unresolved(merged, budget);
  std::sort(contacts.begin(), contacts.end(),
            [](const Contact& a, const Contact& b) { return a.t.lo < b.t.lo; });
  return merged;
}

}  // namespace bezier::core
