#include "envs/free_space2d.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

#include "acd/concavity.h"
#include "acd/internal/ring_locator.h"
#include "envs/occupancy_grid.h"
#include "test_util.h"

namespace acdplan::envs {
namespace {

using testing::ExpectValidAndDecomposes;
using ::testing::HasSubstr;
using testing::TotalArea;

acd::Polygon2d Box(double x0, double y0, double x1, double y1) {
  return acd::Polygon2d{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

// How FreeSpace2d() builds the free space: a world whose edges are all axis-parallel is traced
// on the grid of its coordinates; one slanted edge anywhere (here a triangle outside the
// bounds, which changes nothing) sends the same world through exact Boolean operations.
enum class Construction { kTraced, kBoolean };

// The bounds [0, 10]^2 with `obstacles`.
Workspace2d MakeWorkspace(std::vector<acd::Polygon2d> obstacles,
                          Construction construction = Construction::kTraced) {
  Workspace2d w;
  w.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 10));
  w.obstacles = std::move(obstacles);
  if (construction == Construction::kBoolean) {
    w.obstacles.push_back(acd::Polygon2d{{{20, 20}, {21, 20}, {20, 21}}, {}});
  }
  return w;
}

// The tests of what the free space is, run on both constructions.
class FreeSpace2dBothWaysTest : public ::testing::TestWithParam<Construction> {
 protected:
  Workspace2d WorkspaceWith(std::vector<acd::Polygon2d> obstacles) const {
    return MakeWorkspace(std::move(obstacles), GetParam());
  }
};

INSTANTIATE_TEST_SUITE_P(Constructions, FreeSpace2dBothWaysTest,
                         ::testing::Values(Construction::kTraced, Construction::kBoolean),
                         [](const ::testing::TestParamInfo<Construction>& info) {
                           return info.param == Construction::kTraced ? "Traced" : "Boolean";
                         });

// The free area one hole pinch closes: a diamond of half-diagonal gap * diagonal, half of it in
// the free space.
const double kPinchArea = [] {
  const double e = FreeSpace2dOptions{}.pinch_gap * std::sqrt(200.0);
  return e * e;
}();

TEST_P(FreeSpace2dBothWaysTest, NoObstaclesIsTheBounds) {
  const std::vector<acd::Polygon2d> free = FreeSpace2d(WorkspaceWith({}));
  ASSERT_EQ(free.size(), 1u);
  EXPECT_NEAR(acd::Area(free[0]), 100.0, 1e-9);
  EXPECT_EQ(free[0].outer.size(), 4u);
}

TEST_P(FreeSpace2dBothWaysTest, InteriorObstacleIsAHole) {
  const std::vector<acd::Polygon2d> free = FreeSpace2d(WorkspaceWith({Box(2, 2, 4, 4)}));
  ASSERT_EQ(free.size(), 1u);
  ASSERT_EQ(free[0].holes.size(), 1u);
  EXPECT_NEAR(acd::Area(free[0]), 96.0, 1e-9);
  ExpectValidAndDecomposes(free);
}

TEST_P(FreeSpace2dBothWaysTest, OverlappingObstaclesAreUnited) {
  // Two 3x3 squares overlapping in a 1x1 square, and a clockwise third one inside the first.
  acd::Polygon2d inner = Box(2.5, 2.5, 3, 3);
  std::reverse(inner.outer.begin(), inner.outer.end());
  const std::vector<acd::Polygon2d> free =
      FreeSpace2d(WorkspaceWith({Box(2, 2, 5, 5), Box(4, 4, 7, 7), inner}));
  ASSERT_EQ(free.size(), 1u);
  ASSERT_EQ(free[0].holes.size(), 1u);
  EXPECT_EQ(free[0].holes[0].size(), 8u);
  EXPECT_NEAR(acd::Area(free[0]), 100.0 - 17.0, 1e-9);
  ExpectValidAndDecomposes(free);
}

TEST_P(FreeSpace2dBothWaysTest, ObstaclesCrossingOrOutsideTheBounds) {
  const std::vector<acd::Polygon2d> free =
      FreeSpace2d(WorkspaceWith({Box(-1, -1, 3, 3), Box(8, 4, 12, 6), Box(20, 20, 21, 21)}));
  ASSERT_EQ(free.size(), 1u);
  EXPECT_TRUE(free[0].holes.empty());
  EXPECT_NEAR(acd::Area(free[0]), 100.0 - 9.0 - 4.0, 1e-9);
  ExpectValidAndDecomposes(free);
}

TEST_P(FreeSpace2dBothWaysTest, ObstacleAlongTheBoundsEdge) {
  // Shares part of the bottom edge of the bounds: a notch, not a hole.
  const std::vector<acd::Polygon2d> free = FreeSpace2d(WorkspaceWith({Box(3, 0, 5, 2)}));
  ASSERT_EQ(free.size(), 1u);
  EXPECT_TRUE(free[0].holes.empty());
  EXPECT_EQ(free[0].outer.size(), 8u);
  EXPECT_NEAR(acd::Area(free[0]), 96.0, 1e-9);
}

TEST_P(FreeSpace2dBothWaysTest, WallSplitsTheFreeSpace) {
  const std::vector<acd::Polygon2d> free =
      FreeSpace2d(WorkspaceWith({Box(4, -1, 6, 11), Box(1, 1, 2, 2), Box(8, 8, 9, 9)}));
  ASSERT_EQ(free.size(), 2u);
  // Sorted by lowest-leftmost vertex: the left region first.
  EXPECT_NEAR(acd::Area(free[0]), 39.0, 1e-9);
  EXPECT_NEAR(acd::Area(free[1]), 39.0, 1e-9);
  EXPECT_LT(free[0].outer[0].x(), 5.0);
  EXPECT_EQ(free[0].holes.size(), 1u);
  EXPECT_EQ(free[1].holes.size(), 1u);
  ExpectValidAndDecomposes(free);
}

TEST_P(FreeSpace2dBothWaysTest, ObstacleWithAHoleEnclosesAFreeRegion) {
  acd::Polygon2d ring = Box(2, 2, 8, 8);
  ring.holes.push_back(Box(4, 4, 6, 6).outer);
  const std::vector<acd::Polygon2d> free = FreeSpace2d(WorkspaceWith({ring}));
  ASSERT_EQ(free.size(), 2u);
  EXPECT_NEAR(acd::Area(free[0]), 64.0, 1e-9);
  EXPECT_NEAR(acd::Area(free[1]), 4.0, 1e-9);
  ExpectValidAndDecomposes(free);
}

TEST_P(FreeSpace2dBothWaysTest, ObstaclesTouchingAlongAnEdge) {
  const std::vector<acd::Polygon2d> free =
      FreeSpace2d(WorkspaceWith({Box(2, 2, 4, 4), Box(4, 2, 6, 4)}));
  ASSERT_EQ(free.size(), 1u);
  ASSERT_EQ(free[0].holes.size(), 1u);
  EXPECT_EQ(free[0].holes[0].size(), 4u);  // One 4x2 hole, the shared edge gone.
  EXPECT_NEAR(acd::Area(free[0]), 92.0, 1e-9);
}

TEST_P(FreeSpace2dBothWaysTest, ObstaclesTouchingAtAPointAreClosedByADiamond) {
  // The two holes would touch at (4, 4): the pinch is closed, the holes become one.
  const std::vector<acd::Polygon2d> free =
      FreeSpace2d(WorkspaceWith({Box(2, 2, 4, 4), Box(4, 4, 6, 6)}));
  ASSERT_EQ(free.size(), 1u);
  ASSERT_EQ(free[0].holes.size(), 1u);
  EXPECT_NEAR(acd::Area(free[0]), 92.0 - kPinchArea, 1e-9);
  EXPECT_LT(acd::Area(free[0]), 92.0);
  ExpectValidAndDecomposes(free);
}

TEST(FreeSpace2dTest, ObstacleTouchingTheBoundsAtAPoint) {
  // A triangle standing on its tip at (5, 0) on the bounds' bottom edge.
  const acd::Polygon2d tip{{{5, 0}, {6, 2}, {4, 2}}, {}};
  const std::vector<acd::Polygon2d> free = FreeSpace2d(MakeWorkspace({tip}));
  ASSERT_EQ(free.size(), 1u);
  EXPECT_TRUE(free[0].holes.empty());  // The hole merged into the outer ring at the pinch.
  EXPECT_NEAR(acd::Area(free[0]), 98.0, 1e-9);
  ExpectValidAndDecomposes(free);
}

TEST_P(FreeSpace2dBothWaysTest, LobesMeetingAtAPointBecomeTwoPolygonsExactly) {
  // Free space: the bottom-left and top-right quarters, meeting at (5, 5).
  const std::vector<acd::Polygon2d> free =
      FreeSpace2d(WorkspaceWith({Box(0, 5, 5, 10), Box(5, 0, 10, 5)}));
  ASSERT_EQ(free.size(), 2u);
  EXPECT_DOUBLE_EQ(acd::Area(free[0]), 25.0);
  EXPECT_DOUBLE_EQ(acd::Area(free[1]), 25.0);
  EXPECT_EQ(free[0].outer.size(), 4u);
  ExpectValidAndDecomposes(free);
}

TEST_P(FreeSpace2dBothWaysTest, LobesWithHolesKeepTheirHoles) {
  const std::vector<acd::Polygon2d> free = FreeSpace2d(
      WorkspaceWith({Box(0, 5, 5, 10), Box(5, 0, 10, 5), Box(1, 1, 2, 2), Box(7, 7, 8, 8)}));
  ASSERT_EQ(free.size(), 2u);
  EXPECT_EQ(free[0].holes.size(), 1u);
  EXPECT_EQ(free[1].holes.size(), 1u);
  EXPECT_NEAR(TotalArea(free), 48.0, 1e-9);
}

TEST_P(FreeSpace2dBothWaysTest, RegionsTouchingAtTwoCornersStayTwoPolygons) {
  // A pocket [2, 4] x [4, 5] in a C of three boxes, closed on the east by the cell [4, 5] x [4, 5]
  // that touches the C only at the corners (4, 4) and (4, 5), where the pocket meets the free
  // space outside. Each region passes each corner once: two polygons, exactly, no diamond. (CGAL's
  // own output rings make them one ring with the cell as a hole touching it at both corners.)
  const std::vector<acd::Polygon2d> free = FreeSpace2d(
      WorkspaceWith({Box(1, 3, 2, 6), Box(2, 5, 4, 6), Box(2, 3, 4, 4), Box(4, 4, 5, 5)}));
  ASSERT_EQ(free.size(), 2u);
  const acd::Polygon2d& pocket = free[1];  // Its lowest-left vertex (2, 4) comes after (0, 0).
  EXPECT_TRUE(pocket.holes.empty());
  EXPECT_EQ(pocket.outer.size(), 4u);
  EXPECT_DOUBLE_EQ(acd::Area(pocket), 2.0);
  EXPECT_DOUBLE_EQ(TotalArea(free), 92.0);
  ExpectValidAndDecomposes(free);
}

TEST_P(FreeSpace2dBothWaysTest, ObstaclesCoveringTheBoundsLeaveNothing) {
  EXPECT_TRUE(FreeSpace2d(WorkspaceWith({Box(-1, -1, 11, 11)})).empty());
  EXPECT_TRUE(FreeSpace2d(WorkspaceWith({Box(0, 0, 5, 10), Box(5, 0, 10, 10)})).empty());
}

TEST_P(FreeSpace2dBothWaysTest, TranslatingTheWorldTranslatesTheFreeSpace) {
  Workspace2d w = WorkspaceWith({Box(2, 2, 4, 4), Box(4, 4, 6, 6), Box(4, -1, 5, 1)});
  const std::vector<acd::Polygon2d> a = FreeSpace2d(w);
  const Eigen::Vector2d shift(100.25, -37.5);
  w.bounds.translate(shift);
  for (acd::Polygon2d& o : w.obstacles) {
    for (acd::Point2d& p : o.outer) p += shift;
  }
  const std::vector<acd::Polygon2d> b = FreeSpace2d(w);
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_NEAR(acd::Area(a[k]), acd::Area(b[k]), 1e-9);
    EXPECT_EQ(acd::VertexCount(a[k]), acd::VertexCount(b[k]));
  }
}

// Two regions whose lowest-left vertex is the same point (5, 5), wedged apart by slanted
// obstacles: their order is by their rings, not the sort's choice, so it is the same whatever
// the obstacles' order.
TEST(FreeSpace2dTest, RegionsSharingTheirLowestLeftVertexAreOrderedByTheirRings) {
  Workspace2d workspace;
  workspace.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 10));
  std::vector<acd::Polygon2d> obstacles = {
      {{{0, 0}, {5, 0}, {5, 10}, {0, 10}}, {}},  // The left half.
      {{{5, 5}, {10, 4}, {10, 6}}, {}},          // A wedge to the right.
      {{{5, 0}, {10, 0}, {5, 5}}, {}},           // Below it.
  };
  auto order = [](const acd::Polygon2d& a, const acd::Polygon2d& b) {  // For the permutations.
    return std::make_pair(a.outer.size(), a.outer[1].y()) <
           std::make_pair(b.outer.size(), b.outer[1].y());
  };
  std::sort(obstacles.begin(), obstacles.end(), order);
  std::vector<acd::Polygon2d> first;
  do {  // All 6 orders.
    workspace.obstacles = obstacles;
    const std::vector<acd::Polygon2d> free = FreeSpace2d(workspace);
    ASSERT_EQ(free.size(), 2u);
    EXPECT_EQ(free[0].outer.front(), acd::Point2d(5, 5));  // Then (10, 0): before (10, 6).
    EXPECT_EQ(free[0].outer.size(), 3u);
    if (first.empty()) first = free;
    EXPECT_EQ(free[0].outer, first[0].outer);
    EXPECT_EQ(free[1].outer, first[1].outer);
  } while (std::next_permutation(obstacles.begin(), obstacles.end(), order));
}

TEST(FreeSpace2dTest, RandomGridsGiveValidFreeSpace) {
  // Cell grids are full of corner contacts; every result must be valid and lose at most the
  // pinch diamonds' area.
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    std::mt19937_64 rng(seed);
    OccupancyGrid grid;
    grid.width = 14;
    grid.height = 11;
    grid.resolution = 0.5;
    grid.origin = Eigen::Vector2d(-3, 1);
    int blocked = 0;
    for (int i = 0; i < grid.width * grid.height; ++i) {
      grid.blocked.push_back(rng() % 100 < 40 ? 1 : 0);
      blocked += grid.blocked.back();
    }
    const std::vector<acd::Polygon2d> free = FreeSpace2d(GridWorkspace(grid));
    const double expected = 0.25 * (grid.width * grid.height - blocked);
    const double pinch = std::pow(FreeSpace2dOptions{}.pinch_gap * std::hypot(7.0, 5.5), 2);
    EXPECT_LE(TotalArea(free), expected + 1e-9) << "seed " << seed;
    EXPECT_GE(TotalArea(free), expected - pinch * grid.width * grid.height) << "seed " << seed;
    ExpectValidAndDecomposes(free);
  }
}

bool Before(const acd::Point2d& a, const acd::Point2d& b) {
  return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

// `polygons` with each ring started at its lowest-leftmost vertex, the holes and the polygons in
// the order of their first vertices: the same set of polygons gives the same list.
std::vector<acd::Polygon2d> Canonical(std::vector<acd::Polygon2d> polygons) {
  auto start = [](acd::Ring2d* ring) {
    std::rotate(ring->begin(), std::min_element(ring->begin(), ring->end(), Before), ring->end());
  };
  auto by_first = [](const acd::Ring2d& a, const acd::Ring2d& b) { return Before(a[0], b[0]); };
  for (acd::Polygon2d& polygon : polygons) {
    start(&polygon.outer);
    for (acd::Ring2d& hole : polygon.holes) start(&hole);
    std::sort(polygon.holes.begin(), polygon.holes.end(), by_first);
  }
  std::sort(
      polygons.begin(), polygons.end(),
      [&](const acd::Polygon2d& a, const acd::Polygon2d& b) { return by_first(a.outer, b.outer); });
  return polygons;
}

// The same ring up to the rounding of constructed points (a pinch diamond's, 1 ulp apart when
// one construction rounds it from an exact value and the other adds in doubles).
void ExpectNear(const acd::Ring2d& a, const acd::Ring2d& b, const std::string& where) {
  ASSERT_EQ(a.size(), b.size()) << where;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_LE((a[i] - b[i]).lpNorm<Eigen::Infinity>(), 1e-12 * (1.0 + b[i].norm()))
        << where << ", vertex " << i;
  }
}

TEST(FreeSpace2dTest, TracedGridFreeSpaceIsItsFreeCells) {
  // Every free cell's centre in exactly one polygon, no blocked cell's; the polygons as
  // PreparePolygon() leaves them (the trace skips it); the area the free cells' less at most one
  // pinch diamond per grid corner; and the exact Boolean construction of the same world gives
  // the same polygons.
  for (const int percent : {15, 30, 45, 60}) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
      std::mt19937_64 rng(seed * 100 + percent);
      OccupancyGrid grid;
      grid.width = 17;
      grid.height = 13;
      grid.resolution = 0.25;
      grid.origin = Eigen::Vector2d(-1.5, 3.25);
      for (int i = 0; i < grid.width * grid.height; ++i) {
        grid.blocked.push_back(static_cast<int>(rng() % 100) < percent ? 1 : 0);
      }
      const Workspace2d world = GridWorkspace(grid);
      const std::vector<acd::Polygon2d> traced = FreeSpace2d(world);
      const std::string where = std::to_string(percent) + "% blocked, seed " + std::to_string(seed);
      const std::vector<acd::internal::RingLocator> locators(traced.begin(), traced.end());
      double free_area = 0.0;
      for (int r = 0; r < grid.height; ++r) {
        for (int c = 0; c < grid.width; ++c) {
          const acd::Point2d centre =
              grid.origin + grid.resolution * acd::Point2d(c + 0.5, grid.height - 1 - r + 0.5);
          int count = 0;
          for (const acd::internal::RingLocator& polygon : locators) {
            count += polygon.InsideParity(centre);
          }
          EXPECT_EQ(count, grid.Blocked(r, c) ? 0 : 1) << where << ", cell " << r << ", " << c;
          free_area += grid.Blocked(r, c) ? 0.0 : grid.resolution * grid.resolution;
        }
      }
      const double pinch =
          std::pow(FreeSpace2dOptions{}.pinch_gap * world.bounds.diagonal().norm(), 2);
      const double corners = (grid.width - 1) * (grid.height - 1);
      for (const acd::Polygon2d& polygon : traced) {  // Valid and clean as traced.
        const acd::Polygon2d again = acd::PreparePolygon(polygon, where);
        EXPECT_EQ(again.outer, polygon.outer) << where;
        EXPECT_EQ(again.holes, polygon.holes) << where;
      }
      EXPECT_LE(TotalArea(traced), free_area + 1e-12) << where;
      EXPECT_GE(TotalArea(traced), free_area - corners * pinch) << where;
      ExpectValidAndDecomposes(traced);

      Workspace2d slanted = world;
      slanted.obstacles.push_back(acd::Polygon2d{{{20, 20}, {21, 20}, {20, 21}}, {}});
      const std::vector<acd::Polygon2d> boolean = Canonical(FreeSpace2d(slanted));
      const std::vector<acd::Polygon2d> same = Canonical(traced);
      ASSERT_EQ(boolean.size(), same.size()) << where;
      for (size_t k = 0; k < same.size(); ++k) {
        ExpectNear(boolean[k].outer, same[k].outer, where);
        ASSERT_EQ(boolean[k].holes.size(), same[k].holes.size()) << where;
        for (size_t h = 0; h < same[k].holes.size(); ++h) {
          ExpectNear(boolean[k].holes[h], same[k].holes[h], where);
        }
      }
    }
  }
}

TEST(FreeSpace2dTest, NoisyGridIsSplitAtEachPiecesWitness) {
  // The free space of a noisy occupancy grid is one region with holes on every side of every
  // hole. Each split resolves its piece's most concave feature (Algorithm 1): a hole is cut
  // along a path through its neighbours to the outer boundary even where a walk from hole to
  // nearest hole curls round and shuts itself in. (Before, such a split went to another
  // feature after searches of every boundary point: a 256 x 256 grid took minutes. Not
  // guaranteed: at 35% blocked cells 7 of 27,000 splits of such grids still go elsewhere.) A
  // piece of eight holes or more whose witness split would peel a few holes off the others is
  // halved by a walk from another hole instead: its split names a vertex of that hole.
  acd::Decompose2dOptions options;
  options.measure = acd::ConcavityMeasure::kStraightLine;
  options.keep_pieces = true;
  options.tau = 0.02 * 48.0 * std::sqrt(2.0);  // As `acdplan env` takes it: 2% of the diagonal.
  acd::ConcavityOptions measure;
  measure.measure = options.measure;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    std::mt19937_64 rng(seed);
    OccupancyGrid grid;
    grid.width = grid.height = 48;
    for (int i = 0; i < grid.width * grid.height; ++i) grid.blocked.push_back(rng() % 4 == 0);
    const std::vector<acd::Polygon2d> free = FreeSpace2d(GridWorkspace(grid));
    const acd::Decomposition2d d = acd::Decompose2d(free, options);
    const acd::DecompositionCheck check = acd::CheckDecomposition(free, d);
    EXPECT_TRUE(check.ok()) << "seed " << seed << ": " << (check.ok() ? "" : check.problems[0]);
    for (const acd::HierarchyNode2d& node : d.tree) {
      if (node.children[0] < 0) continue;
      const acd::Concavity2d c = acd::MeasureConcavity(node.piece, measure);
      // A hole's split names one of the hole's vertices, where its cuts leave it.
      acd::Ring2d witnesses = c.witness_hole >= 0 ? node.piece.holes[c.witness_hole]
                                                  : acd::Ring2d{node.piece.outer[c.witness_vertex]};
      if (c.witness_hole >= 0 && node.piece.holes.size() >= 8) {  // Perhaps halved.
        for (const acd::Ring2d& hole : node.piece.holes) {
          witnesses.insert(witnesses.end(), hole.begin(), hole.end());
        }
      }
      EXPECT_THAT(witnesses, ::testing::Contains(node.witness))
          << "seed " << seed << ": a piece of " << acd::VertexCount(node.piece) << " vertices and "
          << node.piece.holes.size() << " holes";
    }
  }
}

TEST(FreeSpace2dTest, Errors) {
  Workspace2d empty_bounds = MakeWorkspace({});
  empty_bounds.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(1, 1), Eigen::Vector2d(1, 5));
  EXPECT_THAT(testing::ErrorOf([&] { FreeSpace2d(empty_bounds); }),
              HasSubstr("FreeSpace2d(): bounds: expected finite xmin < xmax and ymin < ymax"));
  const acd::Polygon2d bowtie{{{0, 0}, {2, 2}, {2, 0}, {0, 1}}, {}};
  EXPECT_THAT(testing::ErrorOf([&] {
                FreeSpace2d(MakeWorkspace({Box(1, 1, 2, 2), bowtie}));
              }),
              HasSubstr("FreeSpace2d(): obstacle 1: outer ring is not simple"));
  EXPECT_THAT(testing::ErrorOf([&] { FreeSpace2d(MakeWorkspace({}), {0.0}); }),
              HasSubstr("FreeSpace2d(): pinch_gap must be finite and > 0"));
}

}  // namespace
}  // namespace acdplan::envs
