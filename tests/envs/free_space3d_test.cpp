#include "envs/free_space3d.h"

#include <gtest/gtest.h>

#include "acd/mesh_measures.h"
#include "acd/prepare_mesh.h"
#include "base/input_error.h"
#include "tests/envs/test_worlds3d.h"

namespace acdplan::envs {
namespace {

using testing::BoxMesh;

Workspace3d Bounds10() {
  Workspace3d world;
  world.bounds = Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 10, 10));
  return world;
}

void ExpectSolid(const FreeSpace3dResult& free) {
  const acd::PreparedMesh prepared = acd::PrepareMesh(free.mesh);
  EXPECT_TRUE(prepared.solid()) << prepared.defects.first;
}

TEST(FreeSpace3d, EmptyWorldIsTheBox) {
  const FreeSpace3dResult free = FreeSpace3d(Bounds10());
  EXPECT_NEAR(free.volume, 1000.0, 1e-9);
  EXPECT_TRUE(free.notes.empty());
  ExpectSolid(free);
}

TEST(FreeSpace3d, DisjointObstaclesSubtractTheirVolumes) {
  Workspace3d world = Bounds10();
  world.obstacles.push_back(BoxMesh({1, 1, 1}, {3, 3, 3}));  // 8, floating: a cavity.
  world.obstacles.push_back(BoxMesh({5, 5, 5}, {6, 8, 9}));  // 12.
  const FreeSpace3dResult free = FreeSpace3d(world);
  EXPECT_NEAR(free.volume, 1000.0 - 8 - 12, 1e-9);
  const acd::PreparedMesh prepared = acd::PrepareMesh(free.mesh);
  ASSERT_TRUE(prepared.solid()) << prepared.defects.first;
  EXPECT_EQ(prepared.parts.size(), 1u);  // One solid with two cavities.
}

TEST(FreeSpace3d, OverlappingObstaclesCountOnce) {
  Workspace3d world = Bounds10();
  world.obstacles.push_back(BoxMesh({2, 2, 2}, {4, 4, 4}));  // 8
  world.obstacles.push_back(BoxMesh({3, 3, 3}, {5, 5, 5}));  // 8, overlap 1
  const FreeSpace3dResult free = FreeSpace3d(world);
  EXPECT_NEAR(free.volume, 1000.0 - 15, 1e-9);
  ExpectSolid(free);
}

TEST(FreeSpace3d, ObstacleCrossingTheBoundsIsClipped) {
  Workspace3d world = Bounds10();
  world.obstacles.push_back(BoxMesh({-2, 4, 4}, {2, 6, 6}));       // 2 x 2 x 2 inside.
  world.obstacles.push_back(BoxMesh({20, 20, 20}, {21, 21, 21}));  // Outside: ignored.
  const FreeSpace3dResult free = FreeSpace3d(world);
  EXPECT_NEAR(free.volume, 1000.0 - 8, 1e-9);
  ExpectSolid(free);
}

TEST(FreeSpace3d, WindowWallLeavesTheWindow) {
  const double side = 1.0;
  const FreeSpace3dResult free = FreeSpace3d(testing::WindowWall(side));
  EXPECT_NEAR(free.volume, 1000.0 - 1.0 * (100 - side * side), 1e-9);
  EXPECT_TRUE(free.notes.empty());
  ExpectSolid(free);
}

TEST(FreeSpace3d, OpenBoxIsClosedThenSubtracted) {
  Workspace3d world = Bounds10();
  acd::TriangleMesh open = BoxMesh({2, 2, 2}, {4, 4, 4});
  open.triangles.conservativeResize(10, 3);  // Drop the x+ face: an open box.
  world.obstacles.push_back(open);
  const FreeSpace3dResult free = FreeSpace3d(world);
  EXPECT_NEAR(free.volume, 1000.0 - 8, 1e-9);
  EXPECT_TRUE(free.notes.empty());
}

TEST(FreeSpace3d, LoneSheetIsLeftToTheCollisionChecker) {
  Workspace3d world = Bounds10();
  world.obstacles.push_back(acd::MakeTriangleMesh(
      {{1, 1, 5}, {4, 1, 5}, {1, 4, 5}, {4, 4, 5}, {2, 2, 5.5}}, {{0, 1, 2}, {1, 3, 2}}));
  const FreeSpace3dResult free = FreeSpace3d(world);
  EXPECT_NEAR(free.volume, 1000.0, 1e-9);
  ASSERT_EQ(free.notes.size(), 1u);
  EXPECT_NE(free.notes[0].find("obstacle 0: not a solid"), std::string::npos) << free.notes[0];
  EXPECT_NE(free.notes[0].find("left to the collision checker"), std::string::npos);
}

TEST(FreeSpace3d, CoveredBoundsGiveNoFreeSpace) {
  Workspace3d world = Bounds10();
  world.obstacles.push_back(BoxMesh({-1, -1, -1}, {11, 11, 11}));
  const FreeSpace3dResult free = FreeSpace3d(world);
  EXPECT_EQ(free.mesh.triangles.rows(), 0);
  EXPECT_EQ(free.volume, 0.0);
}

TEST(FreeSpace3d, EmptyBoundsAreAnError) {
  Workspace3d world;
  EXPECT_THROW(FreeSpace3d(world), InputError);
}

}  // namespace
}  // namespace acdplan::envs
