#include "envs/occupancy_grid.h"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <string>

#include "acd/prepare_polygon.h"
#include "test_util.h"

namespace acdplan::envs {
namespace {

// A grid from text rows ('#' blocked, '.' free), first row on top.
OccupancyGrid Grid(const std::vector<std::string>& rows, double resolution = 1.0,
                   Eigen::Vector2d origin = Eigen::Vector2d::Zero()) {
  OccupancyGrid grid;
  grid.height = static_cast<int>(rows.size());
  grid.width = static_cast<int>(rows[0].size());
  grid.resolution = resolution;
  grid.origin = origin;
  for (const std::string& row : rows) {
    for (char c : row) grid.blocked.push_back(c == '#' ? 1 : 0);
  }
  return grid;
}

int BlockedCount(const OccupancyGrid& grid) {
  int n = 0;
  for (auto b : grid.blocked) n += b;
  return n;
}

// Each polygon is valid and already clean; together they cover exactly the blocked cells.
void ExpectExactValidCover(const OccupancyGrid& grid, const std::vector<acd::Polygon2d>& polygons) {
  double area = 0.0;
  for (size_t k = 0; k < polygons.size(); ++k) {
    const acd::Polygon2d clean = acd::PreparePolygon(polygons[k], "obstacle " + std::to_string(k));
    EXPECT_EQ(acd::VertexCount(clean), acd::VertexCount(polygons[k])) << "obstacle " << k;
    area += acd::Area(polygons[k]);
  }
  // Pieces have disjoint interiors, so the areas add up to the blocked cells' area.
  EXPECT_DOUBLE_EQ(area, BlockedCount(grid) * grid.resolution * grid.resolution);
}

TEST(TraceObstaclesTest, LongStraightWallHasFourVertices) {
  std::vector<std::string> rows(5, std::string(102, '.'));
  rows[2] = "." + std::string(100, '#') + ".";
  const std::vector<acd::Polygon2d> obstacles = TraceObstacles(Grid(rows));
  ASSERT_EQ(obstacles.size(), 1u);
  EXPECT_EQ(obstacles[0].outer.size(), 4u);
  EXPECT_TRUE(obstacles[0].holes.empty());
  EXPECT_DOUBLE_EQ(acd::SignedArea(obstacles[0].outer), 100.0);
}

TEST(TraceObstaclesTest, WorldCoordinatesWithRowZeroOnTop) {
  // One blocked cell in the top-left corner of a 3 x 2 grid, resolution 0.5, origin (1, 2).
  const std::vector<acd::Polygon2d> obstacles =
      TraceObstacles(Grid({"#..", "..."}, 0.5, Eigen::Vector2d(1, 2)));
  ASSERT_EQ(obstacles.size(), 1u);
  Eigen::AlignedBox2d box;
  for (const acd::Point2d& p : obstacles[0].outer) box.extend(p);
  EXPECT_EQ(box.min(), Eigen::Vector2d(1.0, 2.5));
  EXPECT_EQ(box.max(), Eigen::Vector2d(1.5, 3.0));
  EXPECT_GT(acd::SignedArea(obstacles[0].outer), 0.0);
}

TEST(TraceObstaclesTest, RingOfCellsHasOneHole) {
  const OccupancyGrid grid = Grid({"#####", "#...#", "#...#", "#####"});
  const std::vector<acd::Polygon2d> obstacles = TraceObstacles(grid);
  ASSERT_EQ(obstacles.size(), 1u);
  EXPECT_EQ(obstacles[0].outer.size(), 4u);
  ASSERT_EQ(obstacles[0].holes.size(), 1u);
  EXPECT_EQ(obstacles[0].holes[0].size(), 4u);
  EXPECT_LT(acd::SignedArea(obstacles[0].holes[0]), 0.0);
  ExpectExactValidCover(grid, obstacles);
}

TEST(TraceObstaclesTest, DiagonalContactMakesSeparateObstacles) {
  const OccupancyGrid grid = Grid({"#.", ".#"});
  const std::vector<acd::Polygon2d> obstacles = TraceObstacles(grid);
  ASSERT_EQ(obstacles.size(), 2u);
  EXPECT_EQ(obstacles[0].outer.size(), 4u);
  EXPECT_EQ(obstacles[1].outer.size(), 4u);
}

TEST(TraceObstaclesTest, SelfPinchIsCutIntoValidPieces) {
  // One 4-connected set whose boundary passes twice through a corner (between the cells at
  // rows 1-2, columns 1-2): a hole would touch the outer ring there.
  const OccupancyGrid grid = Grid({"####", "#.#.", "##.#", ".###"});
  const std::vector<acd::Polygon2d> obstacles = TraceObstacles(grid);
  EXPECT_GE(obstacles.size(), 2u);
  ExpectExactValidCover(grid, obstacles);
}

TEST(TraceObstaclesTest, RandomGridsGiveValidExactCovers) {
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    std::mt19937_64 rng(seed);
    OccupancyGrid grid;
    grid.width = 3 + static_cast<int>(rng() % 15);
    grid.height = 3 + static_cast<int>(rng() % 15);
    const unsigned density = 20 + static_cast<unsigned>(rng() % 60);
    for (int i = 0; i < grid.width * grid.height; ++i) {
      grid.blocked.push_back(rng() % 100 < density ? 1 : 0);
    }
    SCOPED_TRACE("seed " + std::to_string(seed));
    ExpectExactValidCover(grid, TraceObstacles(grid));
  }
}

TEST(TraceObstaclesTest, GridWorkspaceBoundsAreTheGridExtent) {
  const Workspace2d w = GridWorkspace(Grid({"#..", "..."}, 0.5, Eigen::Vector2d(1, 2)));
  EXPECT_EQ(w.bounds.min(), Eigen::Vector2d(1, 2));
  EXPECT_EQ(w.bounds.max(), Eigen::Vector2d(2.5, 3));
  EXPECT_EQ(w.obstacles.size(), 1u);
}

TEST(TraceObstaclesTest, Errors) {
  OccupancyGrid grid = Grid({"#."});
  grid.blocked.push_back(1);
  EXPECT_EQ(testing::ErrorOf([&] { TraceObstacles(grid); }),
            "TraceObstacles(): blocked has 3 cells, expected width * height = 2");
  grid = Grid({"#."});
  grid.resolution = 0;
  EXPECT_EQ(testing::ErrorOf([&] { TraceObstacles(grid); }),
            "TraceObstacles(): resolution must be finite and > 0, origin finite");
}

}  // namespace
}  // namespace acdplan::envs
