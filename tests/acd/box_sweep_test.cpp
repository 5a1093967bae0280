#include "acd/internal/box_sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace acdplan::acd::internal {
namespace {

using Pairs = std::multiset<std::pair<int, int>>;

bool Overlap(const IdBox& x, const IdBox& y) {
  return x.lo[0] <= y.hi[0] && y.lo[0] <= x.hi[0] && x.lo[1] <= y.hi[1] && y.lo[1] <= x.hi[1];
}

Pairs AllPairs(const std::vector<IdBox>& a, const std::vector<IdBox>& b) {
  Pairs pairs;
  for (const IdBox& x : a) {
    for (const IdBox& y : b) {
      if (Overlap(x, y)) pairs.emplace(x.id, y.id);
    }
  }
  return pairs;
}

Pairs AllSelfPairs(const std::vector<IdBox>& boxes) {
  Pairs pairs;
  for (size_t i = 0; i < boxes.size(); ++i) {
    for (size_t j = i + 1; j < boxes.size(); ++j) {
      if (Overlap(boxes[i], boxes[j])) {
        pairs.emplace(std::min(boxes[i].id, boxes[j].id), std::max(boxes[i].id, boxes[j].id));
      }
    }
  }
  return pairs;
}

Pairs SweptPairs(const std::vector<IdBox>& a, const std::vector<IdBox>& b) {
  Pairs pairs;
  ForEachOverlap(a, b, [&](int x, int y) { pairs.emplace(x, y); });
  return pairs;
}

Pairs SweptSelfPairs(const std::vector<IdBox>& boxes) {
  Pairs pairs;
  ForEachSelfOverlap(boxes, [&](int x, int y) { pairs.emplace(std::min(x, y), std::max(x, y)); });
  return pairs;
}

// Boxes of the kinds the callers sweep, `count` of them with ids from `first_id` on: small ones
// spread over the plane (edges of a map), on a grid of integer coordinates so that many touch
// and many share a coordinate (the strips' bounds among them), a few long ones across it, and
// points (zero-size boxes). The engine's raw output only: the same boxes with any library.
std::vector<IdBox> MixedBoxes(int count, int first_id, std::mt19937* engine) {
  std::vector<IdBox> boxes;
  auto draw = [&](unsigned range) { return static_cast<double>((*engine)() % range); };
  for (int k = 0; k < count; ++k) {
    const unsigned kind = (*engine)() % 20;
    const double x = draw(400), y = draw(400);
    double w = draw(4), h = draw(4);
    if (kind == 0) w = draw(400);  // Long across x.
    if (kind == 1) h = draw(400);  // Long across y.
    if (kind == 2) w = h = 0.0;    // A point.
    boxes.push_back({{x, y}, {x + w, y + h}, first_id + k});
  }
  return boxes;
}

TEST(BoxSweepTest, ReportsEveryOverlappingPairOnceAsAllPairsDo) {
  std::mt19937 engine(7);
  // Below and above the size from which the sweep runs in strips.
  for (const int count : {0, 1, 2, 50, 600, 3000}) {
    const std::vector<IdBox> a = MixedBoxes(count, 0, &engine);
    const std::vector<IdBox> b = MixedBoxes(count / 2 + 1, 100000, &engine);
    EXPECT_EQ(SweptPairs(a, b), AllPairs(a, b)) << count;
    EXPECT_EQ(SweptPairs(a, {}), Pairs()) << count;
    EXPECT_EQ(SweptSelfPairs(a), AllSelfPairs(a)) << count;
  }
}

TEST(BoxSweepTest, TouchingGridCellsAndLongBoxes) {
  // A 40 x 40 grid of unit cells: each touches its 8 neighbours (closed boxes), with rows that
  // share their coordinates; then with boxes across the whole grid, which every strip holds.
  std::vector<IdBox> cells;
  for (int i = 0; i < 40; ++i) {
    for (int j = 0; j < 40; ++j) {
      cells.push_back({{double(i), double(j)}, {i + 1.0, j + 1.0}, 40 * i + j});
    }
  }
  const Pairs grid = SweptSelfPairs(cells);
  EXPECT_EQ(grid.size(), 2u * 40 * 39 + 2u * 39 * 39);  // Side and corner neighbours.
  EXPECT_EQ(grid, AllSelfPairs(cells));
  std::vector<IdBox> with_long = cells;
  with_long.push_back({{-1.0, 10.5}, {41.0, 10.5}, 5000});  // A flat box across every column.
  with_long.push_back({{20.0, -1.0}, {20.0, 41.0}, 5001});  // A thin box across every row.
  EXPECT_EQ(SweptSelfPairs(with_long), AllSelfPairs(with_long));
  EXPECT_EQ(SweptPairs(cells, with_long), AllPairs(cells, with_long));
}

TEST(BoxSweepTest, IdenticalBoxes) {
  std::vector<IdBox> same;
  for (int k = 0; k < 700; ++k) same.push_back({{1.0, 2.0}, {3.0, 4.0}, k});
  EXPECT_EQ(SweptSelfPairs(same).size(), 700u * 699 / 2);
  EXPECT_EQ(SweptPairs(same, same).size(), 700u * 700);
}

}  // namespace
}  // namespace acdplan::acd::internal
