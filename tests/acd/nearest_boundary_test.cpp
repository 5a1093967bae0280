// NearestAccepted, on the grid and on the rings' blocks: it offers exactly the points a sort of
// all of them would, in the same order (ties by ring, index and kind), on point sets full of ties
// (small integer lattices), far from the origin (rounding in the grid's cells), with long edges
// (coarse grids) and skipped holes.

#include "acd/internal/nearest_boundary.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "acd/internal/edge_grid.h"
#include "acd/internal/ring_blocks.h"
#include "base/random.h"
#include "tests/polygon_fixtures.h"

namespace acdplan::acd::internal {
namespace {

struct Listed {
  double d2;
  BoundaryPoint end;
};

auto Key(const Listed& a) { return std::tie(a.d2, a.end.ring, a.end.index, a.end.on_edge); }

// Every point NearestAccepted() may offer, sorted: the definition it must match.
std::vector<BoundaryPoint> SortedScan(const Polygon2d& polygon, const Point2d& p,
                                      const std::vector<char>& skip) {
  std::vector<Listed> all;
  const int m = static_cast<int>(polygon.outer.size());
  for (int i = 0; i < m; ++i) {
    const Point2d& u = polygon.outer[i];
    all.push_back({(u - p).squaredNorm(), {-1, i, false, u}});
    if (const auto foot = EdgeFoot(p, u, polygon.outer[(i + 1) % m])) {
      all.push_back({(*foot - p).squaredNorm(), {-1, i, true, *foot}});
    }
  }
  for (int k = 0; k < static_cast<int>(polygon.holes.size()); ++k) {
    if (skip[k]) continue;
    for (int i = 0; i < static_cast<int>(polygon.holes[k].size()); ++i) {
      const Point2d& u = polygon.holes[k][i];
      all.push_back({(u - p).squaredNorm(), {k, i, false, u}});
    }
  }
  std::sort(all.begin(), all.end(),
            [](const Listed& a, const Listed& b) { return Key(a) < Key(b); });
  std::vector<BoundaryPoint> order;
  for (const Listed& l : all) order.push_back(l.end);
  return order;
}

// The two indexes NearestAccepted() searches.
enum class Index { kGrid, kBlocks };

template <typename SkipHole, typename Accept>
std::optional<BoundaryPoint> Search(Index index, const Polygon2d& polygon, const Point2d& p,
                                    SkipHole skip_hole, Accept accept) {
  if (index == Index::kGrid) {
    return NearestAccepted(polygon, EdgeGrid(polygon), p, skip_hole, accept);
  }
  const RingBlocks outer(polygon.outer, nullptr);
  HoleBlocks holes;
  holes.Assign(polygon.holes);
  double magnitude = 0.0;
  for (const Point2d& v : polygon.outer) magnitude = std::max(magnitude, v.cwiseAbs().maxCoeff());
  for (const Ring2d& hole : polygon.holes) {
    for (const Point2d& v : hole) magnitude = std::max(magnitude, v.cwiseAbs().maxCoeff());
  }
  return NearestAccepted(polygon, outer, holes, magnitude, p, skip_hole, accept);
}

const char* Name(Index index) { return index == Index::kGrid ? "grid" : "blocks"; }

bool Same(const BoundaryPoint& a, const BoundaryPoint& b) {
  return a.ring == b.ring && a.index == b.index && a.on_edge == b.on_edge && a.point == b.point;
}

TEST(NearestBoundaryTest, OffersEveryPointInTheOrderOfASort) {
  RandomEngine rng(11);
  const std::vector<std::pair<Point2d, double>> frames = {{Point2d(0.0, 0.0), 1.0},
                                                          {Point2d(0.0, 0.0), 1e7},
                                                          {Point2d(1e6, -3e6), 1.0},
                                                          {Point2d(-1e9, 1e9), 0.5},
                                                          {Point2d(0.25, 0.0), 1e-9}};
  for (int trial = 0; trial < 300; ++trial) {
    const auto& [origin, step] = frames[trial % frames.size()];
    const Polygon2d polygon = acdplan::test::RandomRings(rng, origin, step, true);
    std::vector<char> skip(polygon.holes.size());
    for (char& s : skip) s = UniformIndex(rng, 3) == 0 ? 1 : 0;
    for (int q = 0; q < 10; ++q) {
      // A vertex of some ring (as a hole path's links ask), or anywhere near the rings.
      Point2d p;
      if (q % 2 == 0 || polygon.holes.empty()) {
        p = polygon.outer[UniformIndex(rng, polygon.outer.size())];
      } else {
        const Ring2d& hole = polygon.holes[UniformIndex(rng, polygon.holes.size())];
        p = q % 4 == 1 ? hole[UniformIndex(rng, hole.size())]
                       : Point2d(origin + step * Point2d(UniformReal(rng, -5.0, 40.0),
                                                         UniformReal(rng, -5.0, 40.0)));
      }
      const std::vector<BoundaryPoint> expected = SortedScan(polygon, p, skip);
      for (const Index index : {Index::kGrid, Index::kBlocks}) {
        std::vector<BoundaryPoint> offered;
        const auto none = Search(
            index, polygon, p, [&](int k) { return skip[k] != 0; },
            [&](const BoundaryPoint& b) {
              offered.push_back(b);
              return false;
            });
        EXPECT_FALSE(none.has_value());
        ASSERT_EQ(offered.size(), expected.size())
            << Name(index) << " trial " << trial << " query " << q;
        for (size_t i = 0; i < expected.size(); ++i) {
          ASSERT_TRUE(Same(offered[i], expected[i]))
              << Name(index) << " trial " << trial << " query " << q << " position " << i
              << ": ring " << offered[i].ring << " index " << offered[i].index
              << " instead of ring " << expected[i].ring << " index " << expected[i].index;
        }
      }
    }
  }
}

TEST(NearestBoundaryTest, ReturnsTheFirstPointAccepted) {
  RandomEngine rng(12);
  for (int trial = 0; trial < 200; ++trial) {
    const Polygon2d polygon =
        acdplan::test::RandomRings(rng, Point2d(3.0, -2.0), trial % 2 == 0 ? 1.0 : 1e4, true);
    const std::vector<char> skip(polygon.holes.size(), 0);
    const Point2d p = polygon.outer[UniformIndex(rng, polygon.outer.size())];
    const std::vector<BoundaryPoint> expected = SortedScan(polygon, p, skip);
    // Accept points by a rule unrelated to the distance: the first that passes it wins.
    const std::uint64_t modulus = 1 + UniformIndex(rng, 7);
    auto rule = [&](const BoundaryPoint& b) {
      return static_cast<std::uint64_t>(3 * (b.ring + 1) + 5 * b.index + (b.on_edge ? 1 : 0)) %
                 modulus ==
             0;
    };
    const auto first = std::find_if(expected.begin(), expected.end(), rule);
    for (const Index index : {Index::kGrid, Index::kBlocks}) {
      int calls = 0;
      const auto got = Search(
          index, polygon, p, [](int) { return false; },
          [&](const BoundaryPoint& b) {
            ++calls;
            return rule(b);
          });
      if (first == expected.end()) {
        EXPECT_FALSE(got.has_value()) << Name(index) << " trial " << trial;
        EXPECT_EQ(calls, static_cast<int>(expected.size())) << Name(index) << " trial " << trial;
      } else {
        ASSERT_TRUE(got.has_value()) << Name(index) << " trial " << trial;
        EXPECT_TRUE(Same(*got, *first)) << Name(index) << " trial " << trial;
        EXPECT_EQ(calls, static_cast<int>(first - expected.begin()) + 1)
            << Name(index) << " trial " << trial;
      }
    }
  }
}

TEST(NearestBoundaryTest, EdgeFootOnlyInsideTheEdge) {
  const Point2d u(0.0, 0.0), w(4.0, 0.0);
  ASSERT_TRUE(EdgeFoot(Point2d(1.0, 3.0), u, w).has_value());
  EXPECT_EQ(*EdgeFoot(Point2d(1.0, 3.0), u, w), Point2d(1.0, 0.0));
  EXPECT_FALSE(EdgeFoot(Point2d(-1.0, 3.0), u, w).has_value());  // Beyond u.
  EXPECT_FALSE(EdgeFoot(Point2d(4.0, 1.0), u, w).has_value());   // At w.
  EXPECT_FALSE(EdgeFoot(Point2d(1.0, 1.0), u, u).has_value());   // No edge.
}

}  // namespace
}  // namespace acdplan::acd::internal
