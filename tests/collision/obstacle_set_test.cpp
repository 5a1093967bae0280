#include "collision/obstacle_set.h"

#include <gtest/gtest.h>

#include <string>

#include "base/input_error.h"
#include "envs/generators.h"
#include "envs/mesh_loader.h"
#include "test_worlds.h"

namespace acdplan::collision {
namespace {

std::string ErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const acdplan::InputError& e) {
    return e.what();
  }
  return "";
}

envs::Workspace2d SquareWorld() {
  envs::Workspace2d w;
  w.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(-5, -5), Eigen::Vector2d(5, 5));
  acd::Polygon2d square;
  square.outer = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  w.obstacles.push_back(square);
  return w;
}

TEST(ObstacleSet2d, ConvexObstacleIsOnePieceWithItsOwnHull) {
  const ObstacleSet set = BuildObstacleSet(SquareWorld());
  EXPECT_EQ(set.dimension, 2);
  ASSERT_EQ(set.pieces.size(), 1u);
  EXPECT_EQ(set.pieces[0].planes.rows(), 6);  // 4 walls + 2 caps
  EXPECT_TRUE(set.pieces[0].closed);
  EXPECT_NEAR(set.pieces[0].box.min().z(), -0.5, 1e-15);
  EXPECT_NEAR(set.pieces[0].box.max().z(), 0.5, 1e-15);
  EXPECT_EQ(TriangleCount(set), 12);  // 8 wall + 2 x 2 cap triangles
  EXPECT_EQ(set.hulls_source, "ACD (Decompose2d, tau = 0.02)");
}

TEST(ObstacleSet2d, EveryBuiltInWorldHasClosedPiecesCoveringItsArea) {
  for (const std::string& name : envs::GeneratorNames()) {
    SCOPED_TRACE(name);
    const envs::Workspace2d world = envs::GenerateWorkspace2d(name, 1);
    const ObstacleSet set = BuildObstacleSet(world);
    double obstacle_area = 0, piece_area = 0;
    for (const auto& p : world.obstacles) obstacle_area += acd::Area(p);
    for (const ObstaclePiece& piece : set.pieces) {
      piece_area += acd::Area(piece.polygon);
      EXPECT_TRUE(piece.closed);
      // Every vertex of the piece is inside its hull's half-spaces.
      for (Eigen::Index i = 0; i < piece.solid.vertices.rows(); ++i) {
        const Eigen::Vector3d v = piece.solid.vertices.row(i).transpose();
        EXPECT_LE((piece.planes.leftCols<3>() * v - piece.planes.col(3)).maxCoeff(), 1e-9);
      }
    }
    EXPECT_NEAR(piece_area, obstacle_area, 1e-9 * obstacle_area);
  }
}

TEST(ObstacleSet2d, RejectsBadOptions) {
  ObstacleSetOptions options;
  options.tau = -1;
  EXPECT_EQ(ErrorOf([&] { BuildObstacleSet(SquareWorld(), options); }),
            "BuildObstacleSet(): tau must be finite and >= 0, got -1.000000");
  options = {};
  options.extrusion_height = 0;
  EXPECT_EQ(ErrorOf([&] { BuildObstacleSet(SquareWorld(), options); }),
            "BuildObstacleSet(): extrusion_height must be finite and > 0, got 0.000000");
}

TEST(ObstacleSet3d, OnePiecePerConnectedComponentAndSaysSo) {
  envs::Workspace3d world;
  world.bounds = Eigen::AlignedBox3d(Eigen::Vector3d(-5, -5, -5), Eigen::Vector3d(5, 5, 5));
  acd::TriangleMesh two = testing::CubeMesh(1.0);
  // A second, disjoint cube in the same mesh.
  acd::TriangleMesh other = testing::CubeMesh(1.0);
  two.vertices.conservativeResize(16, 3);
  two.vertices.bottomRows(8) = other.vertices.rowwise() + Eigen::RowVector3d(3, 0, 0);
  two.triangles.conservativeResize(24, 3);
  two.triangles.bottomRows(12) = other.triangles.array() + 8;
  world.obstacles.push_back(two);
  const ObstacleSet set = BuildObstacleSet(world);
  EXPECT_EQ(set.dimension, 3);
  ASSERT_EQ(set.pieces.size(), 2u);
  EXPECT_TRUE(set.pieces[0].closed);
  EXPECT_NEAR(set.pieces[1].box.min().x(), 2.5, 1e-12);
  EXPECT_EQ(set.hulls_source, "connected components (no 3D ACD yet)");
}

TEST(ObstacleSet3d, VerticesSplitAtSeamsAreWelded) {
  // Each triangle with its own three vertices, as a file with per-face normals reads.
  const acd::TriangleMesh cube = testing::CubeMesh(1.0);
  acd::TriangleMesh split;
  split.vertices.resize(36, 3);
  split.triangles.resize(12, 3);
  for (int f = 0; f < 12; ++f) {
    for (int k = 0; k < 3; ++k) {
      split.vertices.row(3 * f + k) = cube.vertices.row(cube.triangles(f, k));
      split.triangles(f, k) = 3 * f + k;
    }
  }
  envs::Workspace3d world;
  world.bounds = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1));
  world.obstacles.push_back(split);
  const ObstacleSet set = BuildObstacleSet(world);
  ASSERT_EQ(set.pieces.size(), 1u);
  EXPECT_TRUE(set.pieces[0].closed);
  EXPECT_EQ(set.meshes[0].vertices.rows(), 8);
}

TEST(ObstacleSet3d, FlatComponentGetsAThinSolidHull) {
  envs::Workspace3d world;
  world.bounds = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1));
  acd::TriangleMesh quad;
  quad.vertices.resize(4, 3);
  quad.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  quad.triangles.resize(2, 3);
  quad.triangles << 0, 1, 2, 0, 2, 3;
  world.obstacles.push_back(quad);
  const ObstacleSet set = BuildObstacleSet(world);
  ASSERT_EQ(set.pieces.size(), 1u);
  EXPECT_FALSE(set.pieces[0].closed);
  EXPECT_GT(set.pieces[0].box.sizes().z(), 0.0);
  EXPECT_GE(set.pieces[0].planes.rows(), 6);
}

TEST(ObstacleSet3d, RejectsAnInvalidMesh) {
  envs::Workspace3d world;
  world.bounds = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1));
  acd::TriangleMesh bad = testing::CubeMesh(1.0);
  bad.triangles(4, 1) = 17;
  world.obstacles.push_back(bad);
  EXPECT_NE(ErrorOf([&] { BuildObstacleSet(world); }).find("BuildObstacleSet(): obstacle 0"),
            std::string::npos);
}

}  // namespace
}  // namespace acdplan::collision
