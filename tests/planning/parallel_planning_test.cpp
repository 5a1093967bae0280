// Planners, the ACD samplers and the hull collision checker on several threads at once: OMPL's
// ParallelPlan over planners sharing one SpaceInformation, PRM's own roadmap-construction
// thread, and PlanScenario() on several threads. Labelled `threads`: tools/test.sh --tsan runs
// these under ThreadSanitizer, which fails the test on any data race in our code.
//
// Fixed seeds; the budgets are "until the first exact solution", with a generous time limit
// only as a safety net (no assertion depends on wall-clock time).

#include <gtest/gtest.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/tools/multiplan/ParallelPlan.h>
#include <ompl/util/Console.h>

#include <cmath>
#include <future>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "acd/decompose2d.h"
#include "collision/collision_world.h"
#include "collision/obstacle_set.h"
#include "envs/free_space2d.h"
#include "envs/generators.h"
#include "planning/acd_prm.h"
#include "planning/counting_validity_checker.h"
#include "planning/install_acd_samplers.h"
#include "planning/plan_scenario.h"

namespace acdplan::planning {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

/// Safety net only: every solve below stops at its first exact solution long before this.
constexpr double kSafetyLimitS = 120.0;

/// A generated world with its ACD, the planning world (kHullsExact, as PlanScenario builds it)
/// and an exact reference world (kBvh) to check the paths with.
struct World {
  envs::Workspace2d workspace;
  acd::Decomposition2d decomposition;
  envs::Robot robot;
  std::shared_ptr<const collision::CollisionWorld> hulls;  ///< kHullsExact: the planners'.
  std::shared_ptr<const collision::CollisionWorld> exact;  ///< kBvh: the reference.
};

World MakeWorld(const std::string& generator, std::uint64_t seed, double passage_width,
                const envs::Robot& robot) {
  World world;
  world.workspace = envs::GenerateWorkspace2d(generator, seed, {passage_width});
  acd::Decompose2dOptions options;
  options.tau = 0.02 * world.workspace.bounds.sizes().norm();
  world.decomposition = acd::Decompose2d(envs::FreeSpace2d(world.workspace), options);
  world.robot = robot;
  auto obstacles =
      std::make_shared<const collision::ObstacleSet>(collision::BuildObstacleSet(world.workspace));
  collision::CollisionWorldOptions hulls;
  hulls.mode = collision::CollisionMode::kHullsExact;
  world.hulls = std::make_shared<const collision::CollisionWorld>(obstacles, robot, hulls);
  collision::CollisionWorldOptions exact;
  exact.mode = collision::CollisionMode::kBvh;
  world.exact = std::make_shared<const collision::CollisionWorld>(obstacles, robot, exact);
  return world;
}

Eigen::Isometry2d At(const Eigen::Vector2d& xy) {
  Eigen::Isometry2d pose = Eigen::Isometry2d::Identity();
  pose.translate(xy);
  return pose;
}

/// R^2 over the world's bounds; validity as in PlanScenario() (hull world, robot inside the
/// bounds), the hull world asked exactly once per check so its counter must equal the
/// checker's; the ACD samplers installed with `seed`.
std::shared_ptr<ob::SpaceInformation> MakeSpace(const World& world, std::uint64_t seed,
                                                std::shared_ptr<CountingValidityChecker>* out) {
  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds bounds(2);
  for (int i = 0; i < 2; ++i) {
    bounds.setLow(i, world.workspace.bounds.min()[i]);
    bounds.setHigh(i, world.workspace.bounds.max()[i]);
  }
  space->setBounds(bounds);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  auto hulls = world.hulls;
  const envs::Robot robot = world.robot;
  const Eigen::AlignedBox2d box = world.workspace.bounds;
  auto checker = std::make_shared<CountingValidityChecker>(
      si.get(), [hulls, robot, box](const ob::State* state) {
        const double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
        const Eigen::Isometry2d pose = At(Eigen::Vector2d(v[0], v[1]));
        const bool free = hulls->IsValid(pose);  // First, so every check reaches the world.
        return free && envs::InsideBounds(robot, box, pose);
      });
  si->setStateValidityChecker(checker);
  si->setStateValidityCheckingResolution(0.002);
  si->setup();
  AcdSamplerOptions options;
  options.seed = seed;
  InstallAcdSamplers(si, world.decomposition, options);
  *out = checker;
  return si;
}

std::shared_ptr<ob::ProblemDefinition> MakeProblem(const std::shared_ptr<ob::SpaceInformation>& si,
                                                   const Eigen::Vector2d& start,
                                                   const Eigen::Vector2d& goal) {
  ob::ScopedState<> a(si), b(si);
  a[0] = start.x();
  a[1] = start.y();
  b[0] = goal.x();
  b[1] = goal.y();
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  pdef->setStartAndGoalStates(a, b);
  return pdef;
}

ob::PlannerTerminationCondition UntilSolved(const std::shared_ptr<ob::ProblemDefinition>& pdef) {
  return ob::plannerOrTerminationCondition(ob::exactSolnPlannerTerminationCondition(pdef),
                                           ob::timedPlannerTerminationCondition(kSafetyLimitS));
}

/// Every waypoint and every state the planner's motion validator checked along the straight
/// segments (OMPL's discrete validator: ceil(length / segment) equal steps, segment = the
/// checking resolution 0.002 x the bounds' diagonal) is free under the exact (kBvh) world and
/// inside the bounds; the path joins `start` and `goal`. (Between those states a point robot
/// can clip a wall corner: that is OMPL's discretisation, the same for every checker.)
void ExpectPathValid(const World& world, const std::vector<Eigen::Vector2d>& path,
                     const Eigen::Vector2d& start, const Eigen::Vector2d& goal,
                     const std::string& what) {
  ASSERT_GE(path.size(), 2u) << what;
  EXPECT_LE((path.front() - start).norm(), 1e-9) << what;
  EXPECT_LE((path.back() - goal).norm(), 1e-9) << what;
  int bad = 0;
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const double segment = 0.002 * world.workspace.bounds.sizes().norm();
    const int steps =
        std::max(1, static_cast<int>(std::ceil((path[i + 1] - path[i]).norm() / segment)));
    for (int k = 0; k <= steps; ++k) {
      const Eigen::Vector2d p =
          path[i] + (path[i + 1] - path[i]) * (static_cast<double>(k) / steps);
      if (!world.exact->IsValid(At(p)) ||
          !envs::InsideBounds(world.robot, world.workspace.bounds, At(p))) {
        ++bad;
      }
    }
  }
  EXPECT_EQ(bad, 0) << what << ": points of the path in collision under the exact checker";
}

std::vector<Eigen::Vector2d> Points(const og::PathGeometric& geometric) {
  std::vector<Eigen::Vector2d> path;
  for (std::size_t i = 0; i < geometric.getStateCount(); ++i) {
    const double* v = geometric.getState(i)->as<ob::RealVectorStateSpace::StateType>()->values;
    path.emplace_back(v[0], v[1]);
  }
  return path;
}

std::vector<Eigen::Vector2d> SolutionPath(const ob::ProblemDefinition& pdef) {
  return Points(*pdef.getSolutionPath()->as<og::PathGeometric>());
}

/// The hull world's counters agree with the checker's: the world was asked exactly once per
/// check (no increment lost between threads), some checks failed (narrow passage) and, for a
/// robot with a shape, every exact confirmation followed an FCL hull test.
void ExpectCountersConsistent(const World& world, const CountingValidityChecker& checker,
                              const std::string& what) {
  const collision::CollisionCounters c = world.hulls->counters();
  EXPECT_GT(checker.checks(), 0u) << what;
  EXPECT_EQ(c.checks, checker.checks()) << what;
  EXPECT_GT(c.collisions, 0u) << what;
  EXPECT_LT(c.collisions, c.checks) << what;
  if (world.robot.shape == envs::RobotShape::kPoint) {
    EXPECT_EQ(c.hull_tests, 0u) << what;  // Located in the hull tree, no FCL tests.
  } else {
    EXPECT_GT(c.hull_tests, 0u) << what;
    EXPECT_LE(c.exact_confirmations, c.hull_tests) << what;
  }
}

class QuietOmpl : public ::testing::Environment {
 public:
  void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_ERROR); }
};
const auto* const kQuiet = ::testing::AddGlobalTestEnvironment(new QuietOmpl);

// The zigzag corridor (0.5 wide, from x = 0 to x = 10 at y = 5) with a disc robot: the hull
// world goes through FCL's broadphase tree for every check.
const Eigen::Vector2d kZigStart(0.5, 5.0), kZigGoal(9.5, 5.0);

TEST(ParallelPlanning, ParallelPlanFirstSolutionStopsTheOthers) {
  const World world = MakeWorld("zigzag", 3, 0.5, envs::Robot::Disc(0.05));
  std::shared_ptr<CountingValidityChecker> checker;
  auto si = MakeSpace(world, 17, &checker);
  auto pdef = MakeProblem(si, kZigStart, kZigGoal);
  ompl::tools::ParallelPlan parallel(pdef);
  parallel.addPlanner(std::make_shared<og::PRM>(si));
  parallel.addPlanner(std::make_shared<og::PRM>(si));
  parallel.addPlanner(std::make_shared<og::RRTConnect>(si));
  parallel.addPlanner(std::make_shared<og::RRTConnect>(si));
  const ob::PlannerStatus status = parallel.solve(UntilSolved(pdef), /*hybridize=*/false);
  ASSERT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION);
  ASSERT_TRUE(pdef->hasExactSolution());
  ExpectPathValid(world, SolutionPath(*pdef), kZigStart, kZigGoal, "ParallelPlan");
  ExpectCountersConsistent(world, *checker, "ParallelPlan");
}

TEST(ParallelPlanning, ParallelPlanHybridizesEverySolution) {
  // Every planner runs to its own first solution; the solutions are then hybridized.
  const World world = MakeWorld("wall_gap", 2, 0.3, envs::Robot{});
  std::shared_ptr<CountingValidityChecker> checker;
  auto si = MakeSpace(world, 23, &checker);
  const Eigen::Vector2d start(2.5, 5.0), goal(7.5, 5.0);
  auto pdef = MakeProblem(si, start, goal);
  ompl::tools::ParallelPlan parallel(pdef);
  parallel.addPlanner(std::make_shared<og::RRTConnect>(si));
  parallel.addPlanner(std::make_shared<og::RRTConnect>(si));
  parallel.addPlanner(std::make_shared<og::PRM>(si));
  const ob::PlannerStatus status =
      parallel.solve(ob::timedPlannerTerminationCondition(kSafetyLimitS),
                     /*minSolCount=*/1, /*maxSolCount=*/3,
                     /*hybridize=*/true);
  ASSERT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION);
  EXPECT_GE(pdef->getSolutionCount(), 3u);
  for (const ob::PlannerSolution& solution : pdef->getSolutions()) {
    ExpectPathValid(world, Points(*solution.path_->as<og::PathGeometric>()), start, goal,
                    "hybridized ParallelPlan: " + solution.plannerName_);
  }
  ExpectCountersConsistent(world, *checker, "hybridized ParallelPlan");
}

/// PRM's solve() runs growRoadmap()/expandRoadmap() on a thread of its own while the calling
/// thread looks for a solution in the roadmap.
void SolveWithPrmThreads(const std::shared_ptr<og::PRM>& prm, const World& world,
                         const std::shared_ptr<ob::ProblemDefinition>& pdef,
                         const CountingValidityChecker& checker, const Eigen::Vector2d& start,
                         const Eigen::Vector2d& goal) {
  prm->setProblemDefinition(pdef);
  prm->setup();
  const ob::PlannerStatus status = prm->solve(UntilSolved(pdef));
  ASSERT_EQ(status, ob::PlannerStatus::EXACT_SOLUTION) << prm->getName();
  ExpectPathValid(world, SolutionPath(*pdef), start, goal, prm->getName());
  ExpectCountersConsistent(world, checker, prm->getName());
  EXPECT_GE(prm->milestoneCount(), 2u);
}

TEST(ParallelPlanning, PrmConstructionThread) {
  const World world = MakeWorld("zigzag", 5, 0.5, envs::Robot{});
  std::shared_ptr<CountingValidityChecker> checker;
  auto si = MakeSpace(world, 31, &checker);
  auto pdef = MakeProblem(si, kZigStart, kZigGoal);
  SolveWithPrmThreads(std::make_shared<og::PRM>(si), world, pdef, *checker, kZigStart, kZigGoal);
}

TEST(ParallelPlanning, PrmAcdConstructionThread) {
  // PRM_ACD's connection strategy (its component lists and random picks) runs on PRM's
  // construction thread.
  const World world = MakeWorld("zigzag", 5, 0.5, envs::Robot::Disc(0.05));
  std::shared_ptr<CountingValidityChecker> checker;
  auto si = MakeSpace(world, 37, &checker);
  auto pdef = MakeProblem(si, kZigStart, kZigGoal);
  SolveWithPrmThreads(std::make_shared<AcdPrm>(si, world.decomposition, false, 5), world, pdef,
                      *checker, kZigStart, kZigGoal);
}

Scenario MakeScenario(const std::string& generator, std::uint64_t world_seed, PlannerType planner,
                      int samples, std::uint64_t seed) {
  Scenario scenario;
  scenario.workspace = envs::GenerateWorkspace2d(generator, world_seed, {0.4});
  scenario.workspace_label = generator;
  if (generator == "zigzag") {
    scenario.start = {kZigStart.x(), kZigStart.y()};
    scenario.goal = {kZigGoal.x(), kZigGoal.y()};
  } else {
    scenario.start = {2.5, 5.0};
    scenario.goal = {7.5, 5.0};
  }
  scenario.planner = planner;
  scenario.samples = samples;
  scenario.time_limit = kSafetyLimitS;  // PRM and RRTConnect return at their first solution.
  scenario.sampler = SamplerType::kAcd;
  scenario.collision_mode = collision::CollisionMode::kHullsExact;
  scenario.seed = seed;
  return scenario;
}

TEST(ParallelPlanning, PlanScenarioOnSeveralThreads) {
  // Sample budgets are reproducible: each must give on its thread what it gives alone.
  const std::vector<Scenario> scenarios = {
      MakeScenario("wall_gap", 1, PlannerType::kPrm, 300, 1),
      MakeScenario("zigzag", 2, PlannerType::kPrmAcd, 300, 2),
      MakeScenario("wall_gap", 3, PlannerType::kRrtConnect, 0, 3),
      MakeScenario("zigzag", 4, PlannerType::kPrm, 0, 4),
  };
  std::vector<std::future<PlanResult>> futures;
  for (const Scenario& scenario : scenarios) {
    futures.push_back(
        std::async(std::launch::async, [&scenario] { return PlanScenario(scenario); }));
  }
  std::vector<PlanResult> results;
  for (auto& future : futures) results.push_back(future.get());

  for (size_t i = 0; i < scenarios.size(); ++i) {
    const Scenario& scenario = scenarios[i];
    const PlanResult& result = results[i];
    const std::string what =
        "scenario " + std::to_string(i) + " (" + ToString(scenario.planner) + ")";
    EXPECT_TRUE(result.solved) << what;
    EXPECT_GT(result.collision_checks, 0u) << what;
    if (!result.solved) continue;
    std::vector<Eigen::Vector2d> path;
    for (const std::vector<double>& q : result.path) path.emplace_back(q[0], q[1]);
    const World world = MakeWorld(scenario.workspace_label, i + 1, 0.4, scenario.robot);
    ExpectPathValid(world, path, Eigen::Vector2d(scenario.start[0], scenario.start[1]),
                    Eigen::Vector2d(scenario.goal[0], scenario.goal[1]), what);
    if (scenario.samples > 0) {
      const PlanResult alone = PlanScenario(scenario);
      EXPECT_EQ(result.samples, alone.samples) << what;
      EXPECT_EQ(result.collision_checks, alone.collision_checks) << what;
      EXPECT_EQ(result.path, alone.path) << what;
      EXPECT_EQ(result.edges, alone.edges) << what;
    }
  }
}

}  // namespace
}  // namespace acdplan::planning
