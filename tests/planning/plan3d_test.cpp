// 3D scenarios: the 3D ACD sampling targets, the orientation law of the SE(3) sampler, the
// window wall that the ACD sampler passes and uniform sampling does not, and 3D scenario files.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>

#include "base/input_error.h"
#include "collision/collision_world.h"
#include "collision/obstacle_set.h"
#include "envs/free_space_decomposition3d.h"
#include "planning/internal/acd_targets3d.h"
#include "planning/plan_picture3d.h"
#include "planning/plan_scenario.h"
#include "planning/plan_scenario3d.h"
#include "planning/scenario.h"
#include "tests/asan_build.h"
#include "tests/data_paths.h"
#include "tests/envs/test_worlds3d.h"
#include "tests/scratch_dir.h"

namespace acdplan::planning {
namespace {

namespace fs = std::filesystem;
using envs::testing::BoxMesh;
using envs::testing::WindowWall;

// Every test decomposes into its own scratch cache, never the user's.
class Plan3d : public ::testing::Test {
 protected:
  void SetUp() override { setenv("ACDPLAN_CACHE_DIR", (dir_ / "cache").c_str(), 1); }
  void TearDown() override { unsetenv("ACDPLAN_CACHE_DIR"); }
  std::string Write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  test::ScratchDir scratch_{"acdplan_plan3d"};
  fs::path dir_ = scratch_.path();
};

// A rod 2 long and 0.2 thick along its body x axis: the window of side 0.4 is twice its width.
envs::Robot Rod() { return envs::Robot::Mesh(BoxMesh({-1, -0.1, -0.1}, {1, 0.1, 0.1})); }

Scenario WindowWallScenario(SamplerType sampler, PlannerType planner, int samples,
                            std::uint64_t seed) {
  Scenario s;
  s.dimension = 3;
  s.workspace3d = WindowWall(0.4);
  s.robot = Rod();
  s.start = {2, 3, 3, 0, 0, M_PI / 2};  // Across the window's axis: it must turn to pass.
  s.goal = {8, 7, 7, 0, M_PI / 2, 0};
  s.sampler = sampler;
  s.planner = planner;
  s.samples = samples;
  s.seed = seed;
  s.sampler_options.orientation = AcdOrientation::kAligned;
  s.sampler_options.aligned_jitter = 0.05;  // The window leaves the rod little tilt.
  // The wall is 1 thick: a tolerance above that keeps the window's tunnel in one component
  // (2 components, the window their opening); 0.02 cuts the world into slabs.
  s.tau_diag = 0.1;
  return s;
}

// Kolmogorov-Smirnov statistic of `values` against the continuous CDF `cdf`.
template <typename Cdf>
double KsStatistic(std::vector<double> values, Cdf cdf) {
  std::sort(values.begin(), values.end());
  const double n = static_cast<double>(values.size());
  double d = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    const double f = cdf(values[i]);
    d = std::max({d, f - i / n, (i + 1) / n - f});
  }
  return d;
}

TEST_F(Plan3d, EveryTargetLiesInFreeSpace) {
  const envs::Workspace3d world = WindowWall(0.4);
  envs::FreeSpaceDecomposition3dOptions options;
  options.tau = 0.1 * world.bounds.sizes().norm();
  const envs::FreeSpaceDecomposition3d d = envs::DecomposeFreeSpace3d(world, options);
  const internal::AcdTargets3d targets(d, AcdSamplerOptions{});
  ASSERT_EQ(targets.targets().size(), d.components.size() + d.openings.size());
  auto obstacles =
      std::make_shared<const collision::ObstacleSet>(collision::BuildObstacleSet(world));
  const collision::CollisionWorld point(obstacles, envs::Robot::Point());
  int openings = 0;
  for (const internal::AcdTarget3d& t : targets.targets()) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = t.position;
    EXPECT_TRUE(world.bounds.contains(t.position));
    EXPECT_TRUE(point.IsValid(pose)) << t.position.transpose();
    EXPECT_GT(t.sigma, 0);
    if (t.opening) {
      ++openings;
      // The window is the narrowest opening: the heaviest target, spread by its width.
    }
  }
  EXPECT_GE(openings, 1);
  const auto heaviest =
      std::max_element(targets.targets().begin(), targets.targets().end(),
                       [](const internal::AcdTarget3d& a, const internal::AcdTarget3d& b) {
                         return a.weight < b.weight;
                       });
  EXPECT_TRUE(heaviest->opening);
  EXPECT_NEAR(heaviest->position.y(), 5.0, 1e-6);
  EXPECT_NEAR(heaviest->position.z(), 5.0, 1e-6);
  EXPECT_NEAR(heaviest->sigma, 0.5 * 0.4, 1e-6);  // opening_spread x width (a point).
  EXPECT_NEAR(heaviest->sigma_normal, 0.5 * 0.4, 1e-6);
}

TEST_F(Plan3d, PrincipalAxisOfTheRod) {
  const internal::LongAxis3d axis = internal::PrincipalAxis(Rod().mesh.vertices);
  EXPECT_NEAR(std::abs(axis.axis.x()), 1.0, 1e-9);
  EXPECT_NEAR(axis.length, 2.0, 1e-9);
  EXPECT_NEAR(axis.thickness, 0.2, 1e-9);
  // A cube has no long axis.
  EXPECT_EQ(internal::PrincipalAxis(acd::Cube(1.0).vertices).axis.squaredNorm(), 0.0);
}

// Near an opening the long axis follows the documented law: tan(tilt from the normal) /
// aligned_jitter is Rayleigh (CDF 1 - exp(-r^2 / 2)); uniform rotations spread the axis
// uniformly on the sphere, so its cosine with any direction is uniform on [-1, 1]. KS at
// n = 4000: the 1% critical value is 1.63 / sqrt(n) = 0.026.
TEST_F(Plan3d, OrientationStatistics) {
  const envs::FreeSpaceDecomposition3d d;
  AcdSamplerOptions options;
  options.orientation = AcdOrientation::kAligned;
  options.aligned_jitter = 0.2;
  internal::LongAxis3d axis;
  axis.axis = Eigen::Vector3d(1, 1, 0).normalized();  // Any body axis.
  axis.length = 2;
  const internal::AcdTargets3d targets(d, options, axis);
  const Eigen::Vector3d normal = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  RandomEngine rng(7);
  const int n = 4000;
  std::vector<double> aligned, uniform;
  int flipped = 0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d along = targets.AlignedRotation(rng, normal) * axis.axis;
    const double c = along.dot(normal);
    flipped += c < 0;
    const double tilt = std::acos(std::min(1.0, std::abs(c)));
    aligned.push_back(std::tan(tilt) / options.aligned_jitter);
    uniform.push_back((internal::UniformRotation(rng) * axis.axis).dot(normal));
  }
  const double critical = 1.63 / std::sqrt(static_cast<double>(n));
  EXPECT_LT(KsStatistic(aligned, [](double r) { return 1 - std::exp(-r * r / 2); }), critical);
  EXPECT_LT(KsStatistic(uniform, [](double c) { return (c + 1) / 2; }), critical);
  // Either way round, about equally; and the aligned law is far from uniform.
  EXPECT_NEAR(flipped, n / 2, 4 * std::sqrt(n / 4.0));
  std::vector<double> aligned_cosines;
  RandomEngine again(8);
  for (int i = 0; i < n; ++i) {
    aligned_cosines.push_back((targets.AlignedRotation(again, normal) * axis.axis).dot(normal));
  }
  EXPECT_GT(KsStatistic(aligned_cosines, [](double c) { return (c + 1) / 2; }), 0.3);
}

int SolvedSeeds(SamplerType sampler, PlannerType planner, int samples) {
  int solved = 0;
  for (int seed = 1; seed <= acdplan::test::kRateSeeds; ++seed) {
    solved += PlanScenario(WindowWallScenario(sampler, planner, samples, seed)).solved;
  }
  return solved;
}

TEST_F(Plan3d, WindowWallAcdConnectsWhereUniformDoesNot) {
  const int budget = 150;  // Collision-free samples (the Figure-4 protocol).
  const int acd = SolvedSeeds(SamplerType::kAcd, PlannerType::kPrm, budget);
  const int acd_prm = SolvedSeeds(SamplerType::kAcd, PlannerType::kPrmAcd, budget);
  const int uniform = SolvedSeeds(SamplerType::kUniform, PlannerType::kPrm, budget);
  const int seeds = acdplan::test::kRateSeeds;
  std::printf("budget %d: acd+PRM %d/%d, acd+PRM_ACD %d/%d, uniform+PRM %d/%d\n", budget, acd,
              seeds, acd_prm, seeds, uniform, seeds);
  EXPECT_GE(std::max(acd, acd_prm), seeds - 1);
  EXPECT_LE(uniform, 1);
}

// An OBJ of the box [low, high].
std::string BoxObj(const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
  const acd::TriangleMesh mesh = BoxMesh(low, high);
  std::string obj;
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
    obj += "v " + std::to_string(mesh.vertices(i, 0)) + " " + std::to_string(mesh.vertices(i, 1)) +
           " " + std::to_string(mesh.vertices(i, 2)) + "\n";
  }
  for (Eigen::Index i = 0; i < mesh.triangles.rows(); ++i) {
    obj += "f " + std::to_string(mesh.triangles(i, 0) + 1) + " " +
           std::to_string(mesh.triangles(i, 1) + 1) + " " +
           std::to_string(mesh.triangles(i, 2) + 1) + "\n";
  }
  return obj;
}

TEST_F(Plan3d, ScenarioFileWithA3dWorldAndAMeshRobot) {
  Write("block.obj", BoxObj({4, 0, 0}, {6, 10, 6}));
  Write("world3d.yaml", "bounds: [0, 0, 0, 10, 10, 10]\nobstacles:\n  - mesh: block.obj\n");
  fs::create_directories(dir_ / "robots");
  Write("robots/rod.obj", BoxObj({-1, -0.1, -0.1}, {1, 0.1, 0.1}));
  const std::string path = Write("rod.yaml",
                                 "workspace: world3d.yaml\n"
                                 "robot: {shape: mesh, mesh: robots/rod.obj}\n"
                                 "start: [2, 5, 2, 0, 0, 0]\n"
                                 "goal: [8, 5, 2, 0, 0, 1.5707963]\n"
                                 "acd: {tau_diag: 0.1}\n"
                                 "planner: {name: RRTConnect, time_limit: 5}\n"
                                 "seed: 3\n");
  const Scenario s = LoadScenario(path);
  EXPECT_EQ(s.dimension, 3);
  EXPECT_EQ(s.robot.shape, envs::RobotShape::kMesh);
  EXPECT_EQ(s.workspace3d.obstacles.size(), 1u);
  EXPECT_EQ(s.sampler_options.orientation, AcdOrientation::kAligned);  // The 3D mesh default.
  const PlanResult r = PlanScenario(s);
  ASSERT_TRUE(r.solved);
  ASSERT_TRUE(r.decomposition3d);
  EXPECT_GE(r.components, 2);
  EXPECT_EQ(r.path.front().size(), 7u);  // x, y, z, qx, qy, qz, qw.
  // The path goes over the block (z > 6 somewhere) and ends at the goal.
  double top = 0;
  for (const auto& q : r.path) top = std::max(top, q[2]);
  EXPECT_GT(top, 6.0);
  EXPECT_TRUE(PoseOfReals(r.path.back()).isApprox(PoseFromXyzRpy(s.goal), 1e-6));
  // A cache entry was written under $ACDPLAN_CACHE_DIR; a second run reads it.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "cache"), fs::directory_iterator()), 1);
  EXPECT_TRUE(PlanScenario(s).decomposition3d->from_cache);

  // A point in the same world plans in R^3.
  const std::string point = Write("point.yaml",
                                  "workspace: world3d.yaml\nstart: [2, 5, 2]\ngoal: [8, 5, 2]\n"
                                  "planner: {name: PRM_ACD, samples: 100}\nacd: {tau_diag: 0.1}\n");
  const PlanResult p = PlanScenario(LoadScenario(point));
  EXPECT_TRUE(p.solved);
  EXPECT_EQ(p.path.front().size(), 3u);
}

TEST_F(Plan3d, ScenarioErrorsNameTheKey) {
  Write("world3d.yaml", "bounds: [0, 0, 0, 10, 10, 10]\n");
  Write("rod.obj", BoxObj({-1, -0.1, -0.1}, {1, 0.1, 0.1}));
  Write("world2d.yaml", "bounds: [0, 0, 10, 10]\n");
  auto error = [this](const std::string& text) {
    const std::string path = Write("s.yaml", text);
    try {
      LoadScenario(path);
    } catch (const InputError& e) {
      return std::string(e.what()).substr(path.size());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("workspace: world3d.yaml\nstart: [1, 1]\ngoal: [2, 2, 2]\n"),
            ": start: expected [x, y, z] (a point in a 3D world)");
  EXPECT_EQ(error("workspace: world3d.yaml\nrobot: {shape: mesh, mesh: rod.obj}\n"
                  "start: [1, 1, 1]\ngoal: [2, 2, 2]\n"),
            ": start: expected [x, y, z, roll, pitch, yaw] (a mesh robot plans in SE(3))");
  EXPECT_EQ(error("workspace: world3d.yaml\nrobot: {shape: disc, radius: 1}\n"
                  "start: [1, 1, 1]\ngoal: [2, 2, 2]\n"),
            ": robot.shape: a 3D world needs a point or a mesh robot, not a disc");
  EXPECT_EQ(error("workspace: world2d.yaml\nrobot: {shape: mesh, mesh: rod.obj}\n"
                  "start: [1, 1, 1, 0, 0, 0]\ngoal: [2, 2, 2, 0, 0, 0]\n"),
            ": robot.shape: a mesh robot needs a 3D world");
  EXPECT_EQ(error("workspace: world3d.yaml\nrobot: {shape: mesh}\nstart: [1, 1, 1]\n"
                  "goal: [2, 2, 2]\n"),
            ": robot.mesh: required for shape mesh (a mesh file)");
  EXPECT_EQ(error("workspace: world3d.yaml\nrobot: {shape: point, mesh: rod.obj}\n"
                  "start: [1, 1, 1]\ngoal: [2, 2, 2]\n"),
            ": robot.mesh: only for shape mesh");
  // In collision at the start: an InputError when planning.
  Scenario s = LoadScenario(Write("ok.yaml",
                                  "workspace: world3d.yaml\nrobot: {shape: mesh, "
                                  "mesh: rod.obj}\nstart: [1, 1, 1, 0, 0, 0]\n"
                                  "goal: [5, 5, 5, 0, 0, 0]\n"));
  s.start = {20, 1, 1, 0, 0, 0};
  EXPECT_THROW(PlanScenario(s), InputError);
}

TEST_F(Plan3d, PicturesShowWorldOpeningsAndPath) {
  const Scenario s = WindowWallScenario(SamplerType::kAcd, PlannerType::kPrm, 150, 1);
  const PlanResult r = PlanScenario(s);
  ASSERT_TRUE(r.solved);
  const std::vector<acd::SceneMesh3d> scene = PlanScene3d(s, r);
  std::vector<std::string> names;
  for (const acd::SceneMesh3d& item : scene) names.push_back(item.name);
  for (const char* name : {"obstacle_0", "obstacle_3", "opening_0", "path", "start", "goal"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  }
  const acd::ObjFiles obj = acd::SceneToObj(scene, "plan.mtl", "test");
  EXPECT_NE(obj.obj.find("o path\nusemtl path\n"), std::string::npos);
  EXPECT_NE(obj.mtl.find("newmtl opening_0"), std::string::npos);
  const std::string svg = PlanResultToSvg(s, r);
  EXPECT_NE(svg.find("(+z up)"), std::string::npos);
  EXPECT_NE(svg.find("solved"), std::string::npos);
  EXPECT_GT(std::count(svg.begin(), svg.end(), '\n'), 50);
  EXPECT_FALSE(acd::SceneToGlb(scene).empty());
}

// A cube floating in the middle: with a large tolerance the free space is one component with a
// cavity, whose centroid is inside the cube. Such a target is allowed when its spread reaches
// free space: the nearest free point along an axis is within sigma.
TEST_F(Plan3d, ATargetInAnObstacleIsReachedByItsSpread) {
  envs::Workspace3d world;
  world.bounds = Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 10, 10));
  world.obstacles.push_back(BoxMesh({4, 4, 4}, {6, 6, 6}));
  envs::FreeSpaceDecomposition3dOptions options;
  options.tau = 100;
  const envs::FreeSpaceDecomposition3d d = envs::DecomposeFreeSpace3d(world, options);
  const internal::AcdTargets3d targets(d, AcdSamplerOptions{});
  auto obstacles =
      std::make_shared<const collision::ObstacleSet>(collision::BuildObstacleSet(world));
  const collision::CollisionWorld point(obstacles, envs::Robot::Point());
  int inside = 0;
  for (const internal::AcdTarget3d& t : targets.targets()) {
    auto free_at = [&](const Eigen::Vector3d& p) {
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.translation() = p;
      return point.IsValid(pose);
    };
    if (free_at(t.position)) continue;
    ++inside;
    double nearest = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
      for (double sign : {-1.0, 1.0}) {
        for (double step = 0.01; step < 10; step += 0.01) {
          if (free_at(t.position + sign * step * Eigen::Vector3d::Unit(axis))) {
            nearest = std::min(nearest, step);
            break;
          }
        }
      }
    }
    EXPECT_LE(nearest, t.sigma) << t.position.transpose();
  }
  EXPECT_EQ(inside, 1);  // The one component's centroid, in the cube.
}

TEST_F(Plan3d, Shipped3dConfigsLoad) {
  for (const char* name :
       {"window_wall_3d.yaml", "bug_trap_3d.yaml", "cubicles_3d.yaml", "bent_tube_3d.yaml"}) {
    SCOPED_TRACE(name);
    const Scenario s = LoadScenario(acdplan::test::SourceDir() + "/configs/" + name);
    EXPECT_EQ(s.dimension, 3);
    EXPECT_FALSE(s.workspace3d.obstacles.empty());
  }
  // The window wall's one opening is the window (side 1), and acd solves it at seed 1.
  Scenario s = LoadScenario(acdplan::test::SourceDir() + "/configs/window_wall_3d.yaml");
  EXPECT_EQ(s.robot.shape, envs::RobotShape::kMesh);
  const PlanResult r = PlanScenario(s);
  EXPECT_TRUE(r.solved);
  ASSERT_EQ(r.openings, 1);
  EXPECT_NEAR(r.decomposition3d->openings[0].width, 1.0, 1e-6);
}

}  // namespace
}  // namespace acdplan::planning
