// The ACD samplers against a point robot in the free space of the built-in narrow-passage
// worlds (checker: tests/planning/point_free_space_checker.h). Fixed seeds and sample
// budgets; no wall-clock limits.

#include <gtest/gtest.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/base/spaces/SO2StateSpace.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>

#include <cstdio>

#include "acd/decompose2d.h"
#include "base/input_error.h"
#include "envs/free_space2d.h"
#include "envs/generators.h"
#include "planning/acd_state_sampler.h"
#include "planning/acd_valid_state_sampler.h"
#include "planning/counting_validity_checker.h"
#include "planning/install_acd_samplers.h"
#include "planning/sample_budget_roadmap.h"
#include "tests/planning/point_free_space_checker.h"

namespace acdplan::planning {
namespace {

namespace ob = ompl::base;

struct World {
  envs::Workspace2d workspace;
  std::vector<acd::Polygon2d> free_space;
  acd::Decomposition2d decomposition;
};

World Decomposed(envs::Workspace2d workspace) {
  World world;
  world.workspace = std::move(workspace);
  world.free_space = envs::FreeSpace2d(world.workspace);
  acd::Decompose2dOptions options;
  const Eigen::Vector2d size = world.workspace.bounds.sizes();
  options.tau = 0.02 * size.norm();
  world.decomposition = acd::Decompose2d(world.free_space, options);
  return world;
}

World MakeWorld(const std::string& generator, std::uint64_t seed, double width) {
  return Decomposed(envs::GenerateWorkspace2d(generator, seed, {width}));
}

/// A 2D point space over the world's bounds with the point-in-free-space checker.
ob::SpaceInformationPtr PointSpace(const World& world) {
  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds bounds(2);
  for (int i = 0; i < 2; ++i) {
    bounds.setLow(i, world.workspace.bounds.min()[i]);
    bounds.setHigh(i, world.workspace.bounds.max()[i]);
  }
  space->setBounds(bounds);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  const std::vector<acd::Polygon2d>* free_space = &world.free_space;
  si->setStateValidityChecker(
      std::make_shared<CountingValidityChecker>(si.get(), [free_space](const ob::State* s) {
        const double* v = s->as<ob::RealVectorStateSpace::StateType>()->values;
        return testing::InsideFreeSpace(*free_space, Eigen::Vector2d(v[0], v[1]));
      }));
  si->setStateValidityCheckingResolution(0.002);
  si->setup();
  return si;
}

class QuietOmpl : public ::testing::Environment {
 public:
  void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_WARN); }
};
const auto* const kQuiet = ::testing::AddGlobalTestEnvironment(new QuietOmpl);

TEST(AcdValidStateSampler, SamplesAreValidAndInBounds) {
  const World world = MakeWorld("wall_gap", 1, 0.2);
  ob::SpaceInformationPtr si = PointSpace(world);
  AcdSamplerOptions options;
  options.seed = 7;
  AcdValidStateSampler sampler(si.get(), world.decomposition, options);
  ob::State* state = si->allocState();
  int valid = 0;
  for (int i = 0; i < 500; ++i) {
    if (!sampler.sample(state)) continue;
    ++valid;
    EXPECT_TRUE(si->isValid(state));
    EXPECT_TRUE(si->satisfiesBounds(state));
  }
  EXPECT_EQ(valid, 500);
  si->freeState(state);
}

TEST(AcdValidStateSampler, SameSeedSameSamples) {
  const World world = MakeWorld("wall_gap", 1, 0.2);
  ob::SpaceInformationPtr si = PointSpace(world);
  AcdSamplerOptions options;
  options.seed = 11;
  AcdValidStateSampler a(si.get(), world.decomposition, options);
  AcdValidStateSampler b(si.get(), world.decomposition, options);
  ob::State* sa = si->allocState();
  ob::State* sb = si->allocState();
  for (int i = 0; i < 50; ++i) {
    ASSERT_TRUE(a.sample(sa));
    ASSERT_TRUE(b.sample(sb));
    EXPECT_TRUE(si->equalStates(sa, sb));
  }
  si->freeState(sa);
  si->freeState(sb);
}

TEST(AcdValidStateSampler, OpeningsAttractSamples) {
  // The gap of wall_gap is 0.2 x 0.5 of a 10 x 10 world (0.1% of the area); ACD puts far more
  // than that share of the samples there.
  const World world = MakeWorld("wall_gap", 1, 0.2);
  ob::SpaceInformationPtr si = PointSpace(world);
  AcdValidStateSampler sampler(si.get(), world.decomposition);
  ob::State* state = si->allocState();
  int in_wall_band = 0;
  const int n = 1000;
  for (int i = 0; i < n; ++i) {
    ASSERT_TRUE(sampler.sample(state));
    const double x = state->as<ob::RealVectorStateSpace::StateType>()->values[0];
    if (std::abs(x - 5.0) <= 0.25) ++in_wall_band;
  }
  EXPECT_GT(in_wall_band, n / 20);
  si->freeState(state);
}

TEST(AcdValidStateSampler, SampleNearStaysNear) {
  const World world = MakeWorld("wall_gap", 1, 0.2);
  ob::SpaceInformationPtr si = PointSpace(world);
  AcdValidStateSampler sampler(si.get(), world.decomposition);
  ob::State* near = si->allocState();
  ob::State* state = si->allocState();
  near->as<ob::RealVectorStateSpace::StateType>()->values[0] = 4.5;
  near->as<ob::RealVectorStateSpace::StateType>()->values[1] = 2.2;
  for (int i = 0; i < 100; ++i) {
    if (!sampler.sampleNear(state, near, 0.5)) continue;
    EXPECT_TRUE(si->isValid(state));
    const double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
    EXPECT_LE(std::abs(v[0] - 4.5), 0.5 + 1e-12);
    EXPECT_LE(std::abs(v[1] - 2.2), 0.5 + 1e-12);
  }
  si->freeState(near);
  si->freeState(state);
}

TEST(AcdStateSampler, SupportsSE2AndSE3AndRealVector3) {
  const World world = MakeWorld("wall_gap", 1, 0.5);
  AcdSamplerOptions options;
  options.orientation = AcdOrientation::kAligned;
  {
    auto se2 = std::make_shared<ob::SE2StateSpace>();
    ob::RealVectorBounds bounds(2);
    bounds.setLow(0);
    bounds.setHigh(10);
    se2->setBounds(bounds);
    AcdStateSampler sampler(se2.get(), world.decomposition, options);
    ob::State* s = se2->allocState();
    for (int i = 0; i < 200; ++i) {
      sampler.sampleUniform(s);
      EXPECT_TRUE(se2->satisfiesBounds(s));
    }
    se2->freeState(s);
  }
  {
    auto se3 = std::make_shared<ob::SE3StateSpace>();
    ob::RealVectorBounds bounds(3);
    bounds.setLow(0);
    bounds.setHigh(10);
    se3->setBounds(bounds);
    AcdStateSampler sampler(se3.get(), world.decomposition);
    ob::State* s = se3->allocState();
    for (int i = 0; i < 200; ++i) {
      sampler.sampleUniform(s);
      EXPECT_TRUE(se3->satisfiesBounds(s));
    }
    se3->freeState(s);
  }
  {
    auto r3 = std::make_shared<ob::RealVectorStateSpace>(3);
    r3->setBounds(0, 10);
    AcdStateSampler sampler(r3.get(), world.decomposition);
    ob::State* s = r3->allocState();
    for (int i = 0; i < 200; ++i) {
      sampler.sampleUniform(s);
      EXPECT_TRUE(r3->satisfiesBounds(s));
    }
    r3->freeState(s);
  }
}

TEST(AcdStateSampler, AlignedYawIsAcrossTheOpening) {
  // wall_gap's openings are vertical segments (x = 4.75 and x = 5.25): across them is yaw 0
  // or pi for a robot whose long axis is its x axis.
  const World world = MakeWorld("wall_gap", 1, 0.5);
  AcdSamplerOptions options;
  options.orientation = AcdOrientation::kAligned;
  options.uniform_share = 0;
  options.opening_weight = 1e6;  // Essentially always an opening.
  options.aligned_jitter = 0;
  auto se2 = std::make_shared<ob::SE2StateSpace>();
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0);
  bounds.setHigh(10);
  se2->setBounds(bounds);
  AcdStateSampler sampler(se2.get(), world.decomposition, options);
  ob::State* s = se2->allocState();
  int aligned = 0;
  for (int i = 0; i < 100; ++i) {
    sampler.sampleUniform(s);
    const double yaw = s->as<ob::SE2StateSpace::StateType>()->getYaw();
    if (std::abs(std::sin(yaw)) < 1e-9) ++aligned;
  }
  EXPECT_GE(aligned, 95);
  se2->freeState(s);
}

TEST(AcdStateSampler, RejectsUnsupportedSpacesAndBadOptions) {
  const World world = MakeWorld("wall_gap", 1, 0.5);
  auto so2 = std::make_shared<ob::SO2StateSpace>();
  EXPECT_THROW(AcdStateSampler(so2.get(), world.decomposition), std::invalid_argument);
  auto r2 = std::make_shared<ob::RealVectorStateSpace>(2);
  r2->setBounds(0, 10);
  AcdSamplerOptions options;
  options.uniform_share = 1.5;
  try {
    AcdStateSampler sampler(r2.get(), world.decomposition, options);
    FAIL() << "expected acdplan::InputError";
  } catch (const acdplan::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("uniform_share"), std::string::npos) << error.what();
  }
}

/// Figure-4 protocol with `sampler` ("acd" or "uniform") on a point robot.
bool ConnectsWithBudget(const World& world, const std::string& sampler, std::uint64_t seed,
                        int samples) {
  ob::SpaceInformationPtr si = PointSpace(world);
  if (sampler == "acd") {
    AcdSamplerOptions options;
    options.seed = seed;
    InstallAcdSamplers(si, world.decomposition, options);
  } else {
    InstallSeededUniformSampler(si, seed);
  }
  ob::ScopedState<> start(si), goal(si);
  start[0] = 2.5, start[1] = 5.0;
  goal[0] = 7.5, goal[1] = 5.0;
  SampleBudgetOptions options;
  options.samples = samples;
  const SampleBudgetRoadmap roadmap =
      BuildSampleBudgetRoadmap(si, start.get(), goal.get(), options);
  EXPECT_EQ(roadmap.samples, samples);
  return roadmap.solved;
}

/// Solves start -> goal in wall_gap (gap 0.2) with `planner` and the ACD samplers, on an
/// iteration budget (no wall-clock limit).
bool SolvesWith(const std::string& planner_name, std::uint64_t seed) {
  const World world = MakeWorld("wall_gap", 1, 0.2);
  ob::SpaceInformationPtr si = PointSpace(world);
  AcdSamplerOptions options;
  options.seed = seed;
  InstallAcdSamplers(si, world.decomposition, options);
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  ob::ScopedState<> start(si), goal(si);
  start[0] = 2.5, start[1] = 5.0;
  goal[0] = 7.5, goal[1] = 5.0;
  pdef->setStartAndGoalStates(start, goal);
  ob::PlannerPtr planner;
  if (planner_name == "PRM") {
    planner = std::make_shared<ompl::geometric::PRM>(si);
  } else {
    planner = std::make_shared<ompl::geometric::RRTConnect>(si);
  }
  planner->setProblemDefinition(pdef);
  planner->setup();
  const ob::PlannerStatus status = planner->solve(ob::plannerOrTerminationCondition(
      ob::exactSolnPlannerTerminationCondition(pdef), ob::IterationTerminationCondition(20000)));
  if (status != ob::PlannerStatus::EXACT_SOLUTION) return false;
  auto* path = pdef->getSolutionPath()->as<ompl::geometric::PathGeometric>();
  return path->check();
}

TEST(AcdSamplers, WorkInsidePrm) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) EXPECT_TRUE(SolvesWith("PRM", seed));
}

TEST(AcdSamplers, WorkInsideRrtConnect) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) EXPECT_TRUE(SolvesWith("RRTConnect", seed));
}

// The demo world (configs/demo.yaml): wall_gap with a 1.0 thick wall and a 0.05 wide gap in a
// 10 x 10 world, point robot, start (2.5, 5), goal (7.5, 5), 200 collision-free samples.
TEST(Figure4Protocol, AcdConnectsTheDemoWorldUniformDoesNot) {
  envs::WallGapOptions wall;
  wall.wall_thickness = 1.0;
  wall.passage_width = 0.05;
  const World world = Decomposed(envs::MakeWallWithGap(1, wall));
  int acd = 0, uniform = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    acd += ConnectsWithBudget(world, "acd", seed, 200);
    uniform += ConnectsWithBudget(world, "uniform", seed, 200);
  }
  EXPECT_GE(acd, 9);
  EXPECT_LE(uniform, 1);
}

// Not a check: prints the Figure-4 outcomes over wall thickness x passage width (10 seeds
// each) -- the measurements behind the demo world's choice.
TEST(Figure4Protocol, WidthSweep) {
  for (double thickness : {0.5, 1.0, 2.0})
    for (double width : {0.05, 0.1, 0.2, 0.3, 0.5}) {
      envs::WallGapOptions wall;
      wall.wall_thickness = thickness;
      wall.passage_width = width;
      const World world = Decomposed(envs::MakeWallWithGap(1, wall));
      int acd = 0, uniform = 0;
      for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        acd += ConnectsWithBudget(world, "acd", seed, 200);
        uniform += ConnectsWithBudget(world, "uniform", seed, 200);
      }
      std::printf(
          "wall_gap thickness %.1f width %.2f: acd %d/10, uniform %d/10 (components %zu, openings "
          "%zu)\n",
          thickness, width, acd, uniform, world.decomposition.components.size(),
          world.decomposition.openings.size());
    }
}

}  // namespace
}  // namespace acdplan::planning
