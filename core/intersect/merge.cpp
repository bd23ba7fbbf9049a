#include "core/intersect/merge.hpp"

#include <algorithm>
#include <numeric>

namespace bezier::core {

namespace {

struct Item {
  ParamInterval t, s;
  bool resolved = true;
  bool exact = false;
  ExactRoot root;
};

bool near(ParamInterval a, ParamInterval b, double gap) noexcept {
  return b.lo <= a.hi + gap && a.lo <= b.hi + gap;
}

std::size_t find(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
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

/// Boxes left at the precision floor (unresolved) trace a contact of order >= 3 as a tube
/// along the stretch where the curves agree to within rounding, and the search's decisions
/// there, at the floor, can leave holes in the tube several boxes long (finding F11: a
/// third-order contact at an end came as two contacts 7e-6 apart, placed differently in the
/// two orders). Two unresolved contacts are one when the gap between them is at most the
/// larger one's extent; repeated until nothing changes, as merged contacts grow.
void merge_unresolved(std::vector<Contact>& contacts) {
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      if (contacts[i].resolved) continue;
      for (std::size_t j = i + 1; j < contacts.size(); ++j) {
        if (contacts[j].resolved) continue;
        const double gap = std::max(extent(contacts[i]), extent(contacts[j]));
        if (near(contacts[i].t, contacts[j].t, gap) && near(contacts[i].s, contacts[j].s, gap)) {
          absorb(contacts[i], contacts[j]);
          contacts.erase(contacts.begin() + static_cast<std::ptrdiff_t>(j));
          changed = true;
          --j;
        }
      }
    }
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

std::vector<Contact> merge_candidates(std::span<const SearchCandidate> candidates,
                                      std::span<const ExactRoot> exact_roots, double gap) {
  // The common cases, without the sweep's bookkeeping.
  if (candidates.empty() && exact_roots.empty()) return {};
  if (exact_roots.empty() && each_its_own_contact(candidates, gap)) {
    // One crossing, or two or three separate ones: the usual cases.
    std::vector<Contact> contacts;
    contacts.reserve(candidates.size());
    for (const SearchCandidate& c : candidates)
      contacts.push_back({c.t, c.s, c.resolved, 1, false, {}});
    std::sort(contacts.begin(), contacts.end(),
              [](const Contact& a, const Contact& b) { return a.t.lo < b.t.lo; });
    return contacts;
  }
  std::vector<Item> items;
  items.reserve(candidates.size() + exact_roots.size());
  for (const SearchCandidate& c : candidates) items.push_back({c.t, c.s, c.resolved, false, {}});
  for (const ExactRoot& r : exact_roots) items.push_back({{r.t, r.t}, {r.s, r.s}, true, true, r});
  std::sort(items.begin(), items.end(),
            [](const Item& a, const Item& b) { return a.t.lo < b.t.lo; });
  std::vector<std::size_t> parent(items.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  for (std::size_t i = 0; i < items.size(); ++i) {
    for (std::size_t j = i + 1; j < items.size() && items[j].t.lo <= items[i].t.hi + gap; ++j) {
      if (near(items[i].s, items[j].s, gap)) parent[find(parent, i)] = find(parent, j);
    }
  }
  std::vector<Contact> contacts;
  std::vector<std::size_t> index_of(items.size(), items.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::size_t root = find(parent, i);
    if (index_of[root] == items.size()) {
      index_of[root] = contacts.size();
      contacts.push_back({items[i].t, items[i].s, true, 0, false, {}});
    }
    absorb(contacts[index_of[root]],
           {items[i].t, items[i].s, items[i].resolved, 1, items[i].exact, items[i].root});
  }
  merge_unresolved(contacts);
  std::sort(contacts.begin(), contacts.end(),
            [](const Contact& a, const Contact& b) { return a.t.lo < b.t.lo; });
  return contacts;
}

}  // namespace bezier::core
