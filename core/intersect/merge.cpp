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

}  // namespace

std::vector<Contact> merge_candidates(std::span<const SearchCandidate> candidates,
                                      std::span<const ExactRoot> exact_roots, double gap) {
  // The common cases, without the sweep's bookkeeping.
  if (candidates.empty() && exact_roots.empty()) return {};
  if (candidates.size() == 1 && exact_roots.empty()) {
    return {Contact{candidates[0].t, candidates[0].s, candidates[0].resolved, 1, false, {}}};
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
    Contact& c = contacts[index_of[root]];
    c.t = {std::min(c.t.lo, items[i].t.lo), std::max(c.t.hi, items[i].t.hi)};
    c.s = {std::min(c.s.lo, items[i].s.lo), std::max(c.s.hi, items[i].s.hi)};
    c.resolved = c.resolved && items[i].resolved;
    ++c.boxes;
    if (items[i].exact) {
      c.exact = true;
      c.exact_root = items[i].root;
    }
  }
  std::sort(contacts.begin(), contacts.end(),
            [](const Contact& a, const Contact& b) { return a.t.lo < b.t.lo; });
  return contacts;
}

}  // namespace bezier::core
