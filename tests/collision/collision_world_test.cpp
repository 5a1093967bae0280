#include "collision/collision_world.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "base/input_error.h"
#include "collision/internal/mesh_building.h"
#include "envs/generators.h"
#include "envs/mesh_loader.h"
#include "test_worlds.h"
#include "tests/data_paths.h"

namespace acdplan::collision {
namespace {

std::shared_ptr<const ObstacleSet> SquareSet() {
  envs::Workspace2d w;
  w.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(-5, -5), Eigen::Vector2d(5, 5));
  acd::Polygon2d square;
  square.outer = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  w.obstacles.push_back(square);
  return std::make_shared<const ObstacleSet>(BuildObstacleSet(w));
}

// The square with a dent 0.01 deep in its top edge: shallower than BuildObstacleSet's default
// tau (0.02), so it stays one piece, and that piece is not convex.
std::shared_ptr<const ObstacleSet> DentedSquareSet() {
  envs::Workspace2d w;
  w.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(-5, -5), Eigen::Vector2d(5, 5));
  acd::Polygon2d dented;
  dented.outer = {{0, 0}, {2, 0}, {2, 2}, {1.2, 2}, {1, 1.99}, {0.8, 2}, {0, 2}};
  w.obstacles.push_back(dented);
  return std::make_shared<const ObstacleSet>(BuildObstacleSet(w));
}

Eigen::Isometry2d At(double x, double y, double theta = 0) {
  Eigen::Isometry2d pose = Eigen::Isometry2d::Identity();
  pose.translation() << x, y;
  pose.linear() = Eigen::Rotation2Dd(theta).toRotationMatrix();
  return pose;
}

TEST(CollisionWorld, DiscNearASquareInEveryMode) {
  const CollisionWorld world(SquareSet(), envs::Robot::Disc(0.25));
  for (CollisionMode mode : AllCollisionModes()) {
    SCOPED_TRACE(ToString(mode));
    EXPECT_TRUE(world.IsValid(At(3, 1), mode));
    EXPECT_FALSE(world.IsValid(At(2.2, 1), mode));  // overlaps the right wall
    // Entirely inside the obstacle: no surface contact, the containment test must see it.
    EXPECT_FALSE(world.IsValid(At(1, 1), mode));
    EXPECT_NEAR(world.Clearance(At(3, 1), mode), 0.75, 1e-6);
    EXPECT_EQ(world.Clearance(At(1, 1), mode), 0.0);
  }
}

TEST(CollisionWorld, PolygonRobotInsideAndAroundAnObstacle) {
  const CollisionWorld world(SquareSet(), testing::LRobot());
  for (CollisionMode mode : AllCollisionModes()) {
    SCOPED_TRACE(ToString(mode));
    EXPECT_FALSE(world.IsValid(At(1, 1, 0.3), mode));  // inside
    EXPECT_TRUE(world.IsValid(At(-1, 1, 0.3), mode));
    EXPECT_FALSE(world.IsValid(At(2.25, 1, 0.0), mode));  // straddles x = 2
  }
}

TEST(CollisionWorld, HullsAreConservativeNearAConcaveFeature) {
  // A U-shaped obstacle decomposed with a large tau stays one piece: its hull covers the slot.
  envs::Workspace2d w;
  w.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(-5, -5), Eigen::Vector2d(5, 5));
  acd::Polygon2d u;
  u.outer = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  w.obstacles.push_back(u);
  ObstacleSetOptions options;
  options.tau = 10;
  auto set = std::make_shared<const ObstacleSet>(BuildObstacleSet(w, options));
  ASSERT_EQ(set->pieces.size(), 1u);
  const CollisionWorld world(set, envs::Robot::Disc(0.2));
  const Eigen::Isometry2d in_slot = At(1.5, 2.2);
  EXPECT_TRUE(world.IsValid(in_slot, CollisionMode::kBvh));
  EXPECT_FALSE(world.IsValid(in_slot, CollisionMode::kHulls));
  EXPECT_TRUE(world.IsValid(in_slot, CollisionMode::kHullsExact));
  EXPECT_NEAR(world.Clearance(in_slot, CollisionMode::kHullsExact), 0.3, 1e-6);
  EXPECT_EQ(world.Clearance(in_slot, CollisionMode::kHulls), 0.0);
}

TEST(CollisionWorld, PointRobotIsLocatedExactly) {
  const CollisionWorld world(SquareSet(), envs::Robot::Point());
  for (CollisionMode mode : AllCollisionModes()) {
    SCOPED_TRACE(ToString(mode));
    EXPECT_FALSE(world.IsValid(At(1, 1), mode));
    EXPECT_FALSE(world.IsValid(At(2, 1), mode));  // on the boundary: contact
    EXPECT_TRUE(world.IsValid(At(2.001, 1), mode));
    EXPECT_NEAR(world.Clearance(At(3, 1), mode), 1.0, 1e-6);
  }
}

TEST(CollisionWorld, OnlyConcavePiecesAreConfirmedOnTheirTriangles) {
  const auto convex = SquareSet();
  const auto dented = DentedSquareSet();
  ASSERT_EQ(convex->pieces.size(), 1u);
  ASSERT_EQ(dented->pieces.size(), 1u);
  EXPECT_TRUE(convex->pieces[0].convex);
  EXPECT_FALSE(dented->pieces[0].convex);
  const auto poses = testing::RandomPoses2d(
      Eigen::AlignedBox2d(Eigen::Vector2d(-1, -1), Eigen::Vector2d(3, 3)), 500, 11);
  const CollisionWorld square_world(convex, envs::Robot::Disc(0.25));
  const CollisionWorld dented_world(dented, envs::Robot::Disc(0.25));
  for (const auto& pose : poses) {
    EXPECT_EQ(square_world.IsValid(pose, CollisionMode::kHullsExact),
              square_world.IsValid(pose, CollisionMode::kBvh));
    EXPECT_EQ(dented_world.IsValid(pose, CollisionMode::kHullsExact),
              dented_world.IsValid(pose, CollisionMode::kBvh));
  }
  EXPECT_GT(square_world.counters().hull_tests, 0u);
  EXPECT_EQ(square_world.counters().exact_confirmations, 0u);
  EXPECT_GT(dented_world.counters().exact_confirmations, 0u);
}

TEST(CollisionWorld, CountersAreThreadSafe) {
  const CollisionWorld world(DentedSquareSet(), envs::Robot::Disc(0.25));
  const auto poses = testing::RandomPoses2d(
      Eigen::AlignedBox2d(Eigen::Vector2d(-5, -5), Eigen::Vector2d(5, 5)), 2000, 7);
  int invalid[2] = {0, 0};
  auto run = [&](int t) {
    for (const auto& pose : poses) invalid[t] += !world.IsValid(pose);
  };
  std::thread a(run, 0), b(run, 1);
  a.join();
  b.join();
  EXPECT_EQ(invalid[0], invalid[1]);
  const CollisionCounters c = world.counters();
  EXPECT_EQ(c.checks, 4000u);
  EXPECT_EQ(c.collisions, static_cast<std::uint64_t>(invalid[0] + invalid[1]));
  EXPECT_GT(c.hull_tests, 0u);
  EXPECT_GT(c.exact_confirmations, 0u);
  const_cast<CollisionWorld&>(world).ResetCounters();
  EXPECT_EQ(world.counters().checks, 0u);
}

TEST(CollisionWorld, RejectsARobotOfTheWrongDimension) {
  try {
    CollisionWorld world(SquareSet(), envs::Robot::Mesh(testing::CubeMesh(0.1)));
    FAIL() << "no error";
  } catch (const acdplan::InputError& e) {
    EXPECT_STREQ(e.what(),
                 "CollisionWorld(): a mesh robot moves in 3D; this world is 2D (use a point, a "
                 "disc or a polygon)");
  }
  envs::Workspace3d w3;
  w3.bounds = Eigen::AlignedBox3d(Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1));
  w3.obstacles.push_back(testing::CubeMesh(0.5));
  auto set3 = std::make_shared<const ObstacleSet>(BuildObstacleSet(w3));
  try {
    CollisionWorld world(set3, envs::Robot::Disc(0.1));
    FAIL() << "no error";
  } catch (const acdplan::InputError& e) {
    EXPECT_STREQ(e.what(),
                 "CollisionWorld(): a disc robot moves in the plane; this world is 3D (use a "
                 "mesh or a point)");
  }
}

// The randomized properties on every built-in 2D world, for a disc and a polygon robot.
class BuiltInWorlds : public ::testing::TestWithParam<std::string> {};

TEST_P(BuiltInWorlds, HullsExactEqualsBvhAndHullsAreConservative) {
  const envs::Workspace2d workspace = envs::GenerateWorkspace2d(GetParam(), 1);
  auto set = std::make_shared<const ObstacleSet>(BuildObstacleSet(workspace));
  const auto poses = testing::RandomPoses2d(workspace.bounds, testing::kPosesPerWorld, 20240611);
  const envs::Robot robots[] = {envs::Robot::Disc(0.2), testing::LRobot()};
  for (const envs::Robot& robot : robots) {
    SCOPED_TRACE(ToString(robot.shape));
    const CollisionWorld world(set, robot);
    int mismatches = 0, missed = 0, collisions = 0, false_positives = 0;
    for (const auto& pose : poses) {
      const bool bvh = world.IsValid(pose, CollisionMode::kBvh);
      const bool hulls = world.IsValid(pose, CollisionMode::kHulls);
      const bool hulls_exact = world.IsValid(pose, CollisionMode::kHullsExact);
      mismatches += bvh != hulls_exact;
      missed += hulls && !bvh;
      false_positives += !hulls && bvh;
      collisions += !bvh;
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_EQ(missed, 0);
    // Sanity: the worlds are neither empty nor full for these robots.
    EXPECT_GT(collisions, testing::kPosesPerWorld / 50);
    EXPECT_LT(collisions, testing::kPosesPerWorld);
    RecordProperty(ToString(robot.shape) + "_hull_false_positives", false_positives);
  }
}

INSTANTIATE_TEST_SUITE_P(Generators, BuiltInWorlds, ::testing::ValuesIn(envs::GeneratorNames()),
                         [](const auto& info) { return info.param; });

TEST(BuiltInWorlds, ClearanceOfHullsExactMatchesBvh) {
  const envs::Workspace2d workspace = envs::GenerateWorkspace2d("two_rooms", 3);
  auto set = std::make_shared<const ObstacleSet>(BuildObstacleSet(workspace));
  const CollisionWorld world(set, testing::LRobot());
  for (const auto& pose : testing::RandomPoses2d(workspace.bounds, 500, 5)) {
    const double exact = world.Clearance(pose, CollisionMode::kBvh);
    EXPECT_NEAR(world.Clearance(pose, CollisionMode::kHullsExact), exact, 1e-6);
    EXPECT_LE(world.Clearance(pose, CollisionMode::kHulls), exact + 1e-6);
  }
}

// A mesh that is no solid (a crossing pair of cubes beside the rest), with a cavity shell in an
// outer cube: the parts are single shells, and the outer cube's convex piece covers the cavity,
// so a hit on it must be confirmed like a concave piece's.
TEST(CollisionWorld, ACavityShellIsFreeSpaceInEveryExactMode) {
  const acd::TriangleMesh c = testing::CubeMesh(2);
  envs::Workspace3d w;
  w.obstacles.push_back(testing::Combined({testing::CubeMesh(4), testing::InsideOut(c),
                                           testing::Translated(c, {10, 0, 0}),
                                           testing::Translated(c, {11, 0.5, 0.5})}));
  w.bounds = Eigen::AlignedBox3d(Eigen::Vector3d(-3, -3, -3), Eigen::Vector3d(13, 3, 3));
  auto set = std::make_shared<const ObstacleSet>(BuildObstacleSet(w));
  ASSERT_EQ(set->components.size(), 4u);
  auto at = [](double x, double y, double z) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() << x, y, z;
    return pose;
  };
  const CollisionWorld point(set, envs::Robot::Point());
  const CollisionWorld cube(set, envs::Robot::Mesh(testing::CubeMesh(0.2)));
  for (const CollisionMode mode : {CollisionMode::kBvh, CollisionMode::kHullsExact}) {
    SCOPED_TRACE(ToString(mode));
    EXPECT_TRUE(point.IsValid(at(0.5, 0, 0), mode));        // in the cavity
    EXPECT_FALSE(point.IsValid(at(1.5, 0, 0), mode));       // in the wall
    EXPECT_FALSE(point.IsValid(at(1, 0.5, 0), mode));       // on the cavity's surface
    EXPECT_FALSE(point.IsValid(at(10.5, 0.2, 0.2), mode));  // where the pair overlaps
    EXPECT_TRUE(cube.IsValid(at(0.5, 0, 0), mode));
    EXPECT_FALSE(cube.IsValid(at(0.95, 0, 0), mode));  // through the cavity's wall
    EXPECT_FALSE(cube.IsValid(at(1.5, 0, 0), mode));   // inside the wall
    EXPECT_FALSE(cube.IsValid(at(10.5, 0.2, 0.2), mode));
  }
  EXPECT_FALSE(point.IsValid(at(0.5, 0, 0), CollisionMode::kHulls));  // conservative
  for (const auto& pose : testing::RandomPoses3d(w.bounds, 2000, 5)) {
    EXPECT_EQ(point.IsValid(pose, CollisionMode::kHullsExact),
              point.IsValid(pose, CollisionMode::kBvh));
    EXPECT_EQ(cube.IsValid(pose, CollisionMode::kHullsExact),
              cube.IsValid(pose, CollisionMode::kBvh));
  }
}

// 3D: meshes of data/meshes/vhacd as obstacles, a small cube robot.
class CollisionWorldVhacdMesh : public ::testing::TestWithParam<std::string> {};

TEST_P(CollisionWorldVhacdMesh, HullsExactEqualsBvhAndHullsAreConservative) {
  envs::Workspace3d workspace;
  workspace.obstacles.push_back(
      envs::ReadMesh(acdplan::test::DataDir() + "/meshes/vhacd/" + GetParam() + ".obj"));
  const Eigen::AlignedBox3d box = acd::BoundingBox(workspace.obstacles[0]);
  workspace.bounds =
      Eigen::AlignedBox3d(box.min() - 0.1 * box.sizes(), box.max() + 0.1 * box.sizes());
  auto set = std::make_shared<const ObstacleSet>(BuildObstacleSet(workspace));
  // A convex robot (hull hits confirmed on the triangles near it by the separating axis test)
  // and an L-shaped one (confirmed by FCL's BVH-BVH test).
  const double side = 0.05 * box.sizes().norm();
  acd::Polygon2d l_shape;
  l_shape.outer = {{0, 0},           {side, 0}, {side, side / 2}, {side / 2, side / 2},
                   {side / 2, side}, {0, side}};
  for (const acd::TriangleMesh& robot :
       {testing::CubeMesh(side), internal::ExtrudePolygon(l_shape, 0, side / 2)}) {
    SCOPED_TRACE(robot.vertices.rows());
    const CollisionWorld world(set, envs::Robot::Mesh(robot));
    int mismatches = 0, missed = 0, collisions = 0;
    const int count = testing::kPosesPerWorld / 10;
    for (const auto& pose : testing::RandomPoses3d(workspace.bounds, count, 99)) {
      const bool bvh = world.IsValid(pose, CollisionMode::kBvh);
      mismatches += bvh != world.IsValid(pose, CollisionMode::kHullsExact);
      missed += world.IsValid(pose, CollisionMode::kHulls) && !bvh;
      collisions += !bvh;
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_EQ(missed, 0);
    EXPECT_GT(collisions, count / 100);
  }
}

// The obstacles are decomposed (solid ACD; bunny after repair): sanitizer builds take the small
// one.
const std::vector<std::string> kMeshes =
    testing::kSanitizerBuild ? std::vector<std::string>{"cube-notch"}
                             : std::vector<std::string>{"torus1", "cube-notch", "bunny"};
INSTANTIATE_TEST_SUITE_P(Meshes, CollisionWorldVhacdMesh, ::testing::ValuesIn(kMeshes),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name) c = std::isalnum(c) ? c : '_';
                           return name;
                         });

}  // namespace
}  // namespace acdplan::collision
