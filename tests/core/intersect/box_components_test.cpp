// box_components (core/intersect/box_components.hpp): the components of the boxes'
// intersection graph, against the definition (every pair tested, closed transitively).

#include "core/intersect/box_components.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <numeric>
#include <vector>

#include "tests/support/mulberry32.hpp"

namespace bezier::core {
namespace {

bool meet(ParamInterval a, ParamInterval b) {
  return a.lo <= b.hi && b.lo <= a.hi;
}

/// The components by definition: every pair tested, then a fixpoint of the labels.
std::vector<std::size_t> components_by_pairs(const std::vector<ClosedBox>& boxes) {
  std::vector<std::size_t> label(boxes.size());
  std::iota(label.begin(), label.end(), std::size_t{0});
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      for (std::size_t j = 0; j < boxes.size(); ++j) {
        if (label[j] < label[i] && meet(boxes[i].t, boxes[j].t) && meet(boxes[i].s, boxes[j].s)) {
          label[i] = label[j];
          changed = true;
        }
      }
    }
  }
  return label;
}

/// Whether two labellings give the same partition.
bool same_partition(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) {
  std::map<std::size_t, std::size_t> a_to_b, b_to_a;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a_to_b.emplace(a[i], b[i]).first->second != b[i]) return false;
    if (b_to_a.emplace(b[i], a[i]).first->second != a[i]) return false;
  }
  return true;
}

/// Boxes with end points on a coarse grid (so that many touch exactly, closed intervals
/// meeting at one end) and of mixed sizes.
std::vector<ClosedBox> random_boxes(test::Mulberry32& rng, int count, int grid) {
  std::vector<ClosedBox> boxes;
  const auto coordinate = [&] { return static_cast<double>(static_cast<int>(rng.next() * grid)); };
  for (int i = 0; i < count; ++i) {
    const double t = coordinate(), s = coordinate();
    const double wt = rng.next() < 0.2 ? coordinate() : static_cast<int>(rng.next() * 3);
    const double ws = rng.next() < 0.2 ? coordinate() : static_cast<int>(rng.next() * 3);
    boxes.push_back({{t, t + wt}, {s, s + ws}});
  }
  return boxes;
}

TEST(BoxComponents, EqualTheComponentsOfEveryPairTested) {
  test::Mulberry32 rng(17);
  for (int trial = 0; trial < 300; ++trial) {
    const int count = 1 + static_cast<int>(rng.next() * 60);
    const int grid = 4 + static_cast<int>(rng.next() * 60);
    const std::vector<ClosedBox> boxes = random_boxes(rng, count, grid);
    EXPECT_TRUE(same_partition(box_components(boxes), components_by_pairs(boxes)))
        << "trial " << trial;
  }
}

TEST(BoxComponents, TouchingAtOneEndIsMeeting) {
  const std::vector<ClosedBox> boxes = {{{0, 1}, {0, 1}}, {{1, 2}, {1, 2}}, {{2.5, 3}, {0, 3}}};
  const std::vector<std::size_t> label = box_components(boxes);
  EXPECT_EQ(label[0], label[1]);
  EXPECT_NE(label[0], label[2]);
}

TEST(BoxComponents, NoBoxes) {
  EXPECT_TRUE(box_components({}).empty());
}

/// A column of boxes sharing one t interval, each touching the next in s (k^2 / 2 meeting
/// pairs), beside a second column apart from it: two components.
TEST(BoxComponents, ColumnsOfManyBoxesSharingTheirTInterval) {
  std::vector<ClosedBox> boxes;
  constexpr int kBoxes = 20000;
  for (int i = 0; i < kBoxes; ++i) {
    const double s = i;
    boxes.push_back({{0.0, 1.0}, {s, s + 1.0}});
    boxes.push_back({{0.0, 1.0}, {s + 0.25 + 2 * kBoxes, s + 1.25 + 2 * kBoxes}});
  }
  const std::vector<std::size_t> label = box_components(boxes);
  for (std::size_t i = 0; i < boxes.size(); i += 2) {
    EXPECT_EQ(label[i], label[0]);
    EXPECT_EQ(label[i + 1], label[1]);
  }
  EXPECT_NE(label[0], label[1]);
}

}  // namespace
}  // namespace bezier::core
