#include "acd/internal/shortest_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/acd/geodesic_test_polygons.h"

namespace acdplan::acd::internal {
namespace {

using testing::BruteForceBridgeDistances;
using testing::BruteForceGeodesic;
using testing::kPi;
using testing::RandomComb;
using testing::RandomSpiral;
using testing::RandomStar;
using testing::RandomTwoOptPolygon;

double Diameter(const Ring2d& ring) {
  Point2d lo = ring[0], hi = ring[0];
  for (const Point2d& p : ring) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

void ExpectDistancesNear(const std::vector<double>& actual, const std::vector<double>& expected,
                         double scale, const std::string& label) {
  SCOPED_TRACE(label);
  ASSERT_EQ(actual.size(), expected.size());
  for (size_t i = 0; i < actual.size(); ++i) {
    EXPECT_NEAR(actual[i], expected[i], 1e-9 * scale) << "vertex " << i;
  }
}

// Checks distances against the brute force, and that every parent link is a visible segment
// whose length accounts for the distance difference.
void ExpectTreeMatchesBruteForce(const Ring2d& ring, int source, const std::string& label) {
  const ShortestPathTree tree = ComputeShortestPathTree(ring, source);
  const double scale = Diameter(ring);
  ExpectDistancesNear(tree.distance, BruteForceGeodesic(ring, source), scale, label);
  EXPECT_EQ(tree.parent[source], -1);
  for (int v = 0; v < static_cast<int>(ring.size()); ++v) {
    if (v == source) continue;
    const int p = tree.parent[v];
    ASSERT_GE(p, 0) << label << " vertex " << v;
    EXPECT_TRUE(testing::SegmentInside(ring, ring[v], ring[p]))
        << label << " link " << v << "-" << p;
    EXPECT_NEAR(tree.distance[v], tree.distance[p] + (ring[v] - ring[p]).norm(), 1e-12 * scale);
  }
}

TEST(ComputeShortestPathTreeTest, HookByHand) {
  // The hook of ShortestPathsToBridgeTest.HookPocket closed as a counter-clockwise polygon.
  const Ring2d hook = {{0, 0}, {0, -10}, {8, -10}, {8, -4}, {2, -4}, {2, -2}, {10, -2}, {10, 0}};
  const ShortestPathTree tree = ComputeShortestPathTree(hook, 3);  // From (8, -4).
  EXPECT_EQ(tree.parent[3], -1);
  EXPECT_EQ(tree.parent[6], 5);  // (10, -2) hangs off (2, -2), which hangs off (2, -4).
  EXPECT_EQ(tree.parent[5], 4);
  EXPECT_NEAR(tree.distance[6], 6 + 2 + 8, 1e-12);
  EXPECT_NEAR(tree.distance[7], 6 + 2 + std::sqrt(64 + 4.0), 1e-12);  // Round (2,-4), (2,-2).
  EXPECT_NEAR(tree.distance[0], 6 + std::sqrt(4 + 16.0), 1e-12);      // Round (2,-4) only.
  EXPECT_NEAR(tree.distance[1], std::sqrt(64 + 36.0), 1e-12);
}

TEST(ComputeShortestPathTreeTest, MatchesBruteForceOnRandomPolygons) {
  RandomEngine rng(2024);
  int cases = 0;
  for (int i = 0; i < 60; ++i) {
    auto size = [&rng] { return 4 + static_cast<int>(UniformIndex(rng, 57)); };  // [4, 60]
    const std::vector<std::pair<std::string, Ring2d>> rings = {
        {"star", RandomStar(size(), rng, 0.05)},
        {"2-opt", RandomTwoOptPolygon(size() / 2 + 3, rng)},
        {"comb", RandomComb(2 + i % 9, rng, /*jitter=*/i % 2 == 0)},
        {"spiral", RandomSpiral(0.3 + 0.05 * i, rng)},
    };
    for (const auto& [name, ring] : rings) {
      const int source = static_cast<int>(UniformIndex(rng, ring.size()));
      ExpectTreeMatchesBruteForce(ring, source, name + " " + std::to_string(i));
      ++cases;
    }
  }
  EXPECT_EQ(cases, 240);
}

TEST(ComputeShortestPathTreeTest, WeaklySimpleRing) {
  // Square with a bridged square hole: paths wrap around the hole.
  const Ring2d keyhole = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0},
                          {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}};
  const ShortestPathTree tree = ComputeShortestPathTree(keyhole, 1);  // From (4, 0).
  // (0, 4): the straight segment crosses the hole; around (3, 3) (or (1, 1)) it is 2 sqrt(10).
  EXPECT_NEAR(tree.distance[3], 2 * std::sqrt(10.0), 1e-12);
  EXPECT_NEAR(tree.distance[7], std::sqrt(10.0), 1e-12);  // (3, 3) is seen directly.
}

TEST(ComputeShortestPathTreeTest, RejectsBadInput) {
  const Ring2d square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  try {
    ComputeShortestPathTree(square, 4);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "ComputeShortestPathTree(): source 4 is not a vertex index in [0, 4)");
  }
  try {
    ComputeShortestPathTree(Reversed(square), 0);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "ComputeShortestPathTree(): the ring must be counter-clockwise, its signed area is "
              "-1.000000");
  }
}

// ---------------------------------------------------------------------------------------------

// Pocket chains (beta-, ..., beta+) of a counter-clockwise polygon: its runs between consecutive
// strictly convex hull vertices. Skips pockets with a vertex on the bridge line.
std::vector<Ring2d> HullPockets(const Ring2d& ring) {
  const int n = static_cast<int>(ring.size());
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return ring[a].x() < ring[b].x() || (ring[a].x() == ring[b].x() && ring[a].y() < ring[b].y());
  });
  std::vector<int> hull;  // Andrew's monotone chain, strictly convex.
  for (int pass = 0; pass < 2; ++pass) {
    const size_t base = hull.size();
    for (int i : order) {
      while (hull.size() >= base + 2 &&
             Orientation(ring[hull[hull.size() - 2]], ring[hull.back()], ring[i]) <= 0) {
        hull.pop_back();
      }
      hull.push_back(i);
    }
    hull.pop_back();
    std::reverse(order.begin(), order.end());
  }
  std::sort(hull.begin(), hull.end());
  std::vector<Ring2d> pockets;
  for (size_t h = 0; h < hull.size(); ++h) {
    const int a = hull[h], b = hull[(h + 1) % hull.size()];
    Ring2d chain;
    for (int i = a;; i = (i + 1) % n) {
      chain.push_back(ring[i]);
      if (i == b) break;
    }
    bool on_line = false;
    for (size_t k = 1; k + 1 < chain.size(); ++k) {
      on_line |= Orientation(chain.front(), chain.back(), chain[k]) == 0;
    }
    if (chain.size() > 2 && !on_line) pockets.push_back(chain);
  }
  return pockets;
}

// A star-shaped pocket below the bridge (-1, 0) -> (1, 0) around the centre (0, -cy): the chain
// sweeps the angles from beta- over the bottom round to beta+, with spiky radii, so vertices
// can reach far beyond either end of the bridge. Counter-clockwise.
Ring2d RandomStarPocket(int n, RandomEngine& rng) {
  auto unit = [&rng] { return UniformReal(rng, 0.0, 1.0); };
  const double cy = 0.2 + 0.8 * unit();
  const double from = std::atan2(cy, -1.0), to = std::atan2(cy, 1.0) + 2 * kPi;
  std::vector<double> angles(n);
  for (double& a : angles) a = from + (to - from) * (0.001 + 0.998 * unit());
  std::sort(angles.begin(), angles.end());
  Ring2d chain = {{-1, 0}};
  for (double a : angles) {
    double r = 0.1 + 2.4 * unit();
    if (std::sin(a) > 0) r = std::min(r, (cy - 0.01) / std::sin(a) * (0.3 + 0.7 * unit()));
    chain.emplace_back(r * std::cos(a), -cy + r * std::sin(a));
  }
  chain.emplace_back(1, 0);
  return chain;
}

void ExpectBridgeDistancesMatchBruteForce(const Ring2d& chain, const std::string& label) {
  ExpectDistancesNear(ShortestPathsToBridge(chain), BruteForceBridgeDistances(chain),
                      Diameter(chain), label);
}

TEST(ShortestPathsToBridgeTest, MatchesBruteForceOnStarPockets) {
  RandomEngine rng(99);
  for (int i = 0; i < 150; ++i) {
    const Ring2d chain = RandomStarPocket(3 + i % 50, rng);
    ExpectBridgeDistancesMatchBruteForce(chain, "star pocket " + std::to_string(i));
  }
}

TEST(ShortestPathsToBridgeTest, MatchesBruteForceOnHullPockets) {
  RandomEngine rng(5);
  int pockets = 0;
  for (int i = 0; i < 120; ++i) {
    const std::vector<std::pair<std::string, Ring2d>> rings = {
        {"2-opt", RandomTwoOptPolygon(6 + i % 35, rng)},
        {"spiral", RandomSpiral(1.0 + 0.05 * (i % 40), rng)},
        {"comb", RandomComb(2 + i % 7, rng, /*jitter=*/true)},
        {"star", RandomStar(8 + i % 40, rng, 0.1)},
    };
    for (const auto& [name, ring] : rings) {
      for (const Ring2d& chain : HullPockets(ring)) {
        ExpectBridgeDistancesMatchBruteForce(chain, name + " " + std::to_string(i));
        ++pockets;
      }
    }
  }
  EXPECT_GT(pockets, 200);
}

TEST(ShortestPathsToBridgeTest, HookPocket) {
  // A shelf (a tooth of P) hangs over the lower room, so the straight-line (SL) concavity of
  // (8,-10) and (8,-4) underestimates: their paths must climb around (2,-4) (Fig. 15 style).
  const Ring2d chain = {{0, 0}, {0, -10}, {8, -10}, {8, -4}, {2, -4}, {2, -2}, {10, -2}, {10, 0}};
  const std::vector<double> expected = {0, 10, 4 + 6 * std::sqrt(2.0), 10, 4, 2, 2, 0};
  const std::vector<double> sp = ShortestPathsToBridge(chain);
  ExpectDistancesNear(sp, expected, 1.0, "hook");
  EXPECT_GT(sp[2], 10.0 + 2.0);  // SL distance of (8, -10) is 10.
  EXPECT_GT(sp[3], 4.0 + 5.0);   // SL distance of (8, -4) is 4.
  ExpectBridgeDistancesMatchBruteForce(chain, "hook brute force");

  // Metamorphic: the reversed chain (the same pocket, clockwise), and a rotated, scaled and
  // translated copy give the same (scaled) distances.
  Ring2d reversed = Reversed(chain);
  std::vector<double> reversed_expected(expected.rbegin(), expected.rend());
  ExpectDistancesNear(ShortestPathsToBridge(reversed), reversed_expected, 1.0, "reversed");
  const double c = std::cos(0.7), s = std::sin(0.7);
  Ring2d moved;
  for (const Point2d& p : chain)
    moved.emplace_back(3 * (c * p.x() - s * p.y()) + 1e3, 3 * (s * p.x() + c * p.y()) - 2e3);
  std::vector<double> scaled = expected;
  for (double& d : scaled) d *= 3;
  ExpectDistancesNear(ShortestPathsToBridge(moved), scaled, 3e3, "moved");
}

TEST(ShortestPathsToBridgeTest, PathsEndAtTheBridgeEnds) {
  // (-4,-3) lies left of beta- = (0,0): its path ends at beta- (Lemma A.2), length 5. (5,-6)
  // sees the bridge perpendicularly: 6.
  const Ring2d chain = {{0, 0}, {-4, -3}, {5, -6}, {10, 0}};
  ExpectDistancesNear(ShortestPathsToBridge(chain), {0, 5, 6, 0}, 1.0, "ends");
  // Beyond beta+ = (10,0) under an overhang: (12,-4) sees beta+ directly, (12,-1) must bend
  // round (11,-1) first.
  const Ring2d overhang = {{0, 0}, {0, -4}, {12, -4}, {12, -1}, {11, -1}, {10, 0}};
  ExpectDistancesNear(ShortestPathsToBridge(overhang),
                      {0, 4, std::sqrt(20.0), 1 + std::sqrt(2.0), std::sqrt(2.0), 0}, 1.0,
                      "overhang");
}

TEST(ShortestPathsToBridgeTest, TwoVertexChainAndErrors) {
  EXPECT_EQ(ShortestPathsToBridge({{0, 0}, {1, 0}}), (std::vector<double>{0, 0}));
  try {
    ShortestPathsToBridge({{1, 1}, {0, -1}, {1, 1}});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "ShortestPathsToBridge(): the bridge has zero length, both ends at (1.000000, "
              "1.000000)");
  }
  try {
    ShortestPathsToBridge({{0, 0}, {1, -1}, {2, 1}, {3, -1}, {4, 0}});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "ShortestPathsToBridge(): chain vertex 2 (2.000000, 1.000000) lies beyond the "
              "bridge line, on the far side of the pocket");
  }
}

}  // namespace
}  // namespace acdplan::acd::internal
