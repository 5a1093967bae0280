#include "collision/point_locator.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "envs/generators.h"
#include "envs/mesh_loader.h"
#include "test_worlds.h"

namespace acdplan::collision {
namespace {

std::shared_ptr<const ObstacleSet> FrameWorld() {
  // A square frame: a polygon with a square hole.
  envs::Workspace2d w;
  w.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(-5, -5), Eigen::Vector2d(5, 5));
  acd::Polygon2d frame;
  frame.outer = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  frame.holes = {{{1, 1}, {1, 3}, {3, 3}, {3, 1}}};
  w.obstacles.push_back(frame);
  return std::make_shared<const ObstacleSet>(BuildObstacleSet(w));
}

TEST(PointLocator2d, ExactOnAPolygonWithAHole) {
  const PointLocator exact(FrameWorld(), LocateMethod::kExact);
  EXPECT_TRUE(exact.Inside(Eigen::Vector2d(0.5, 0.5)));
  EXPECT_FALSE(exact.Inside(Eigen::Vector2d(2, 2)));  // in the hole
  EXPECT_FALSE(exact.Inside(Eigen::Vector2d(-1, 2)));
  EXPECT_TRUE(exact.Inside(Eigen::Vector2d(4, 2)));    // on the outer boundary
  EXPECT_TRUE(exact.Inside(Eigen::Vector2d(1, 2)));    // on the hole's boundary
  EXPECT_TRUE(exact.Inside(Eigen::Vector2d(2, 0)));    // on a horizontal edge
  EXPECT_TRUE(exact.Inside(Eigen::Vector2d(0, 0)));    // a vertex
  EXPECT_TRUE(exact.Inside(Eigen::Vector2d(0.5, 1)));  // level with the hole's lower edge
  EXPECT_FALSE(exact.Inside(Eigen::Vector2d(4 + 1e-15 * 4, 2)));
}

TEST(PointLocator2d, HullsCoverTheHoleOnlyWhereAComponentDoes) {
  const PointLocator hulls(FrameWorld(), LocateMethod::kHulls);
  EXPECT_TRUE(hulls.Inside(Eigen::Vector2d(0.5, 0.5)));
  EXPECT_TRUE(hulls.Inside(Eigen::Vector2d(4, 4)));
  EXPECT_FALSE(hulls.Inside(Eigen::Vector2d(-0.1, 2)));
  EXPECT_EQ(hulls.method(), LocateMethod::kHulls);
  EXPECT_EQ(ToString(LocateMethod::kHulls), "hulls");
}

TEST(PointLocator2d, HullsNeverSayOutsideWhereExactSaysInsideOnBuiltInWorlds) {
  for (const std::string& name : envs::GeneratorNames()) {
    SCOPED_TRACE(name);
    const envs::Workspace2d workspace = envs::GenerateWorkspace2d(name, 1);
    auto set = std::make_shared<const ObstacleSet>(BuildObstacleSet(workspace));
    const PointLocator exact(set, LocateMethod::kExact), hulls(set, LocateMethod::kHulls);
    int missed = 0, wrong = 0, inside = 0;
    for (const auto& pose : testing::RandomPoses2d(workspace.bounds, testing::kPosesPerWorld, 31)) {
      const Eigen::Vector2d p = pose.translation();
      const bool e = exact.Inside(p), h = hulls.Inside(p);
      missed += e && !h;
      wrong += h != e;
      inside += e;
    }
    EXPECT_EQ(missed, 0);
    EXPECT_GT(inside, 0);
    EXPECT_LE(wrong, testing::kPosesPerWorld / 100);  // the 1% error target
  }
}

TEST(PointLocator2d, ExactMatchesAPlainCrossingTestOnAMaze) {
  // The slab index must not change answers: compare with a loop over every edge.
  const envs::Workspace2d workspace = envs::GenerateWorkspace2d("maze", 4);
  auto set = std::make_shared<const ObstacleSet>(BuildObstacleSet(workspace));
  const PointLocator exact(set, LocateMethod::kExact);
  auto plain = [&](const Eigen::Vector2d& p) {
    for (const acd::Polygon2d& polygon : workspace.obstacles) {
      bool in = false;
      auto ring = [&](const acd::Ring2d& r) {
        for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
          if ((r[i].y() > p.y()) != (r[j].y() > p.y()) &&
              p.x() <
                  (r[j].x() - r[i].x()) * (p.y() - r[i].y()) / (r[j].y() - r[i].y()) + r[i].x()) {
            in = !in;
          }
        }
      };
      ring(polygon.outer);
      for (const auto& h : polygon.holes) ring(h);
      if (in) return true;
    }
    return false;
  };
  for (const auto& pose : testing::RandomPoses2d(workspace.bounds, 20000, 8)) {
    const Eigen::Vector2d p = pose.translation();
    ASSERT_EQ(exact.Inside(p), plain(p)) << p.transpose();
  }
}

envs::Workspace3d MeshWorld(const acd::TriangleMesh& mesh) {
  envs::Workspace3d w;
  w.obstacles.push_back(mesh);
  const Eigen::AlignedBox3d box = acd::BoundingBox(mesh);
  w.bounds = Eigen::AlignedBox3d(box.min() - 0.1 * box.sizes(), box.max() + 0.1 * box.sizes());
  return w;
}

TEST(PointLocator3d, ExactOnACube) {
  auto set = std::make_shared<const ObstacleSet>(BuildObstacleSet(MeshWorld(testing::CubeMesh(2))));
  const PointLocator exact(set, LocateMethod::kExact);
  EXPECT_TRUE(exact.Inside(Eigen::Vector3d(0.2, 0.3, -0.9)));
  EXPECT_TRUE(exact.Inside(Eigen::Vector3d(1, 0, 0)));  // on a face
  EXPECT_FALSE(exact.Inside(Eigen::Vector3d(1.01, 0, 0)));
}

TEST(PointLocator3d, ExactRefusesAnOpenMesh) {
  acd::TriangleMesh open = testing::CubeMesh(2);
  open.triangles.conservativeResize(10, 3);  // drop the x+ face
  auto set = std::make_shared<const ObstacleSet>(BuildObstacleSet(MeshWorld(open)));
  try {
    PointLocator exact(set, LocateMethod::kExact);
    FAIL() << "no error";
  } catch (const acdplan::InputError& e) {
    EXPECT_STREQ(e.what(),
                 "PointLocator(): exact point location needs closed obstacle meshes: obstacle 0 "
                 "(part 0) is open: edge 1-3 at (1, 0, -1) has 1 face (a solid's edges have "
                 "exactly 2)");
  }
  // The hull locator needs no inside, so it accepts the open mesh.
  const PointLocator hulls(set, LocateMethod::kHulls);
  EXPECT_TRUE(hulls.Inside(Eigen::Vector3d(0, 0, 0)));
}

TEST(PointLocator3d, NestedShellsBoundACavity) {
  // A cube inside a cube, both in one mesh: the space between them is the solid.
  acd::TriangleMesh outer = testing::CubeMesh(4), inner = testing::CubeMesh(2);
  acd::TriangleMesh both = outer;
  both.vertices.conservativeResize(16, 3);
  both.vertices.bottomRows(8) = inner.vertices;
  both.triangles.conservativeResize(24, 3);
  both.triangles.bottomRows(12) = inner.triangles.array() + 8;
  auto set = std::make_shared<const ObstacleSet>(BuildObstacleSet(MeshWorld(both)));
  const PointLocator exact(set, LocateMethod::kExact), hulls(set, LocateMethod::kHulls);
  EXPECT_TRUE(exact.Inside(Eigen::Vector3d(1.5, 0, 0)));
  EXPECT_FALSE(exact.Inside(Eigen::Vector3d(0, 0, 0)));
  EXPECT_TRUE(hulls.Inside(Eigen::Vector3d(1.5, 0, 0)));  // conservative
  // The solid ACD's pieces surround the cavity, so their hulls leave (most of) it free.
  EXPECT_GT(set->pieces.size(), 1u);
}

class PointLocatorVhacdMesh : public ::testing::TestWithParam<std::string> {};

TEST_P(PointLocatorVhacdMesh, HullsNeverSayOutsideWhereExactSaysInside) {
  const envs::Workspace3d workspace = MeshWorld(
      envs::ReadMesh(std::string(ACDPLAN_DATA_DIR) + "/meshes/vhacd/" + GetParam() + ".obj"));
  auto set = std::make_shared<const ObstacleSet>(BuildObstacleSet(workspace));
  const PointLocator exact(set, LocateMethod::kExact), hulls(set, LocateMethod::kHulls);
  int missed = 0, inside = 0;
  for (const auto& pose :
       testing::RandomPoses3d(workspace.bounds, testing::kPosesPerWorld / 10, 12)) {
    const Eigen::Vector3d p = pose.translation();
    const bool e = exact.Inside(p);
    missed += e && !hulls.Inside(p);
    inside += e;
  }
  EXPECT_EQ(missed, 0);
  EXPECT_GT(inside, 0);
}

// Closed meshes only (bunny, for one, has 42 border edges).
const std::vector<std::string> kClosedMeshes = testing::kSanitizerBuild
                                                   ? std::vector<std::string>{"teddy"}
                                                   : std::vector<std::string>{"torus1", "teddy"};
INSTANTIATE_TEST_SUITE_P(Meshes, PointLocatorVhacdMesh, ::testing::ValuesIn(kClosedMeshes));

}  // namespace
}  // namespace acdplan::collision
