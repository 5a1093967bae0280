#include "collision/obstacle_set.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "acd/convex_hull3d.h"
#include "acd/mesh_measures.h"
#include "acd/prepare_mesh.h"
#include "base/input_error.h"
#include "collision/internal/mesh_building.h"
#include "collision/point_locator.h"
#include "envs/generators.h"
#include "envs/mesh_loader.h"
#include "test_worlds.h"
#include "tests/data_paths.h"

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

TEST(ObstacleSet3d, EachConnectedComponentIsDecomposedAndSaysSo) {
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
  EXPECT_EQ(set.hulls_source, "ACD (Decompose3d, tau_rel = 0.02: 2 solid, 0 surface)");
  ASSERT_EQ(set.components.size(), 2u);
  EXPECT_EQ(set.pieces[1].component, 1);
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

std::vector<Eigen::Vector3d> Points(const acd::TriangleMesh& mesh) {
  std::vector<Eigen::Vector3d> points;
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
    points.push_back(mesh.vertices.row(i).transpose());
  }
  return points;
}

TEST(ObstacleSet3d, ACubeIsOneConvexSolidPiece) {
  const ObstacleSet set = BuildObstacleSet(testing::MeshWorld(testing::CubeMesh(2)));
  ASSERT_EQ(set.components.size(), 1u);
  EXPECT_TRUE(set.components[0].closed);
  ASSERT_EQ(set.pieces.size(), 1u);
  EXPECT_TRUE(set.pieces[0].closed);
  EXPECT_TRUE(set.pieces[0].convex);
  EXPECT_EQ(set.pieces[0].component, 0);
  EXPECT_EQ(set.pieces[0].triangles.size(), 12u);  // Every face meets the hull's box.
  EXPECT_EQ(set.hulls_source, "ACD (Decompose3d, tau_rel = 0.02: 1 solid, 0 surface)");
  EXPECT_TRUE(set.notes.empty());
}

TEST(ObstacleSet3d, ConvexPiecesLieInsideTheObstacle) {
  // Claimed convex pieces skip the exact confirmation: their hulls must be inside the obstacle.
  std::vector<std::string> names = {"cube-notch", "box-thick"};
  if (!testing::kSanitizerBuild) names.push_back("torus1");
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    const envs::Workspace3d world = testing::MeshWorld(
        envs::ReadMesh(acdplan::test::DataDir() + "/meshes/vhacd/" + name + ".obj"));
    auto set = std::make_shared<const ObstacleSet>(BuildObstacleSet(world));
    const PointLocator exact(set, LocateMethod::kExact);
    EXPECT_FALSE(set->pieces.empty());
    for (const ObstaclePiece& piece : set->pieces) {
      if (!piece.convex) continue;
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (const Eigen::Vector3d& p : Points(piece.hull)) {
        centroid += p / static_cast<double>(piece.hull.vertices.rows());
      }
      // Points just inside the hull, towards its centroid, are inside the obstacle.
      for (const Eigen::Vector3d& p : Points(piece.hull)) {
        EXPECT_TRUE(exact.Inside(Eigen::Vector3d(p + 1e-6 * (centroid - p))));
      }
      EXPECT_TRUE(exact.Inside(centroid));
    }
  }
}

TEST(ObstacleSet3d, EqualsItsHullIsExact) {
  const acd::TriangleMesh cube = testing::CubeMesh(2);
  EXPECT_TRUE(internal::EqualsItsHull(cube, acd::ConvexHull3(Points(cube), 0.0)));
  // A dent 1e-12 deep: the top face (z = 1) as a fan around its centre, pushed inwards.
  std::vector<Eigen::Vector3d> corners = Points(cube);
  std::vector<Eigen::Vector3i> faces;
  for (Eigen::Index f = 0; f < cube.triangles.rows(); ++f) {
    bool top = true;
    for (int k = 0; k < 3; ++k) top = top && cube.vertices(cube.triangles(f, k), 2) == 1.0;
    if (!top) faces.push_back(cube.triangles.row(f).transpose());
  }
  std::vector<int> ring;  // The top corners, counter-clockwise seen from +z.
  for (const Eigen::Vector2d& xy : {Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, -1),
                                    Eigen::Vector2d(1, 1), Eigen::Vector2d(-1, 1)}) {
    for (size_t i = 0; i < corners.size(); ++i) {
      if (corners[i] == Eigen::Vector3d(xy.x(), xy.y(), 1)) ring.push_back(static_cast<int>(i));
    }
  }
  ASSERT_EQ(ring.size(), 4u);
  corners.emplace_back(0, 0, 1 - 1e-12);
  for (int k = 0; k < 4; ++k) faces.emplace_back(ring[k], ring[(k + 1) % 4], 8);
  const acd::TriangleMesh dented = acd::MakeTriangleMesh(corners, faces);
  ASSERT_TRUE(acd::PrepareMesh(dented).solid());
  EXPECT_FALSE(internal::EqualsItsHull(dented, acd::ConvexHull3(Points(dented), 0.0)));
  // The same fan without the dent is convex (coplanar faces are fine).
  acd::TriangleMesh flat = dented;
  flat.vertices(8, 2) = 1.0;
  EXPECT_TRUE(internal::EqualsItsHull(flat, acd::ConvexHull3(Points(flat), 0.0)));
  // Schoenhardt's twisted prism: every vertex is a vertex of its hull, yet it is not convex
  // (three faces cut into the hull).
  std::vector<Eigen::Vector3d> v;
  const double twist = 0.5;
  for (int level = 0; level < 2; ++level) {
    for (int k = 0; k < 3; ++k) {
      const double a = 2 * M_PI * k / 3 + (level == 1 ? twist : 0.0);
      v.emplace_back(std::cos(a), std::sin(a), level);
    }
  }
  // Bottom 0,1,2 and top 3,4,5; each side quad (k, k+1, k+1+3, k+3) split along the diagonal
  // (k, k+1+3), which the twist makes a reflex edge.
  std::vector<Eigen::Vector3i> f = {{0, 2, 1}, {3, 4, 5}};
  for (int k = 0; k < 3; ++k) {
    const int a = k, b = (k + 1) % 3, c = b + 3, d = a + 3;
    f.emplace_back(a, b, c);
    f.emplace_back(a, c, d);
  }
  const acd::TriangleMesh schoenhardt = acd::MakeTriangleMesh(v, f);
  ASSERT_TRUE(acd::PrepareMesh(schoenhardt).solid());
  const acd::TriangleMesh hull = acd::ConvexHull3(v, 0.0);
  EXPECT_EQ(hull.vertices.rows(), 6);
  EXPECT_FALSE(internal::EqualsItsHull(schoenhardt, hull));
}

TEST(ObstacleSet3d, AnOpenMeshGetsSurfacePatchesWithVolume) {
  acd::TriangleMesh open = testing::CubeMesh(2);
  open.triangles.conservativeResize(10, 3);  // No x+ face.
  const ObstacleSet set = BuildObstacleSet(testing::MeshWorld(open));
  ASSERT_EQ(set.components.size(), 1u);
  EXPECT_FALSE(set.components[0].closed);
  ASSERT_FALSE(set.pieces.empty());
  for (const ObstaclePiece& piece : set.pieces) {
    EXPECT_FALSE(piece.closed);
    EXPECT_FALSE(piece.convex);
    EXPECT_GT(acd::MeshVolume(piece.hull), 0.0);
  }
  EXPECT_NE(set.hulls_source.find("1 surface"), std::string::npos) << set.hulls_source;
}

TEST(ObstacleSet3d, RejectsABadTauRel) {
  ObstacleSetOptions options;
  options.tau_rel_3d = 0;
  EXPECT_EQ(ErrorOf([&] { BuildObstacleSet(testing::MeshWorld(testing::CubeMesh(1)), options); }),
            "BuildObstacleSet(): tau_rel_3d must be finite and > 0, got 0.000000");
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
