// OMPL.app .cfg problems as scenarios: the 2D fixture becomes a footprint workspace and a
// polygon robot and plans end to end; 3D problems become SE(3) scenarios (plan_scenario3d.h).

#include "planning/scenario_cfg.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "acd/polygon2d.h"
#include "base/input_error.h"
#include "envs/ompl_app_problem.h"
#include "planning/plan_scenario.h"
#include "planning/plan_scenario3d.h"
#include "planning/scenario_moving_ai.h"
#include "tests/data_paths.h"
#include "tests/scratch_dir.h"

namespace acdplan::planning {
namespace {

const std::string kData = acdplan::test::SourceDir() + "/tests/data/ompl_app/";

TEST(ScenarioFromOmplApp, Turns2dMeshesIntoFootprints) {
  const Scenario s = LoadScenarioFile(kData + "planar.cfg");
  EXPECT_EQ(s.path, kData + "planar.cfg");
  EXPECT_EQ(s.description, "OMPL.app problem planar_fixture");
  ASSERT_EQ(s.robot.shape, envs::RobotShape::kPolygon);
  // The plate's trapezoid, shifted by its vertex mean (2, 1).
  EXPECT_NEAR(acd::Area(s.robot.polygon), 8.0, 1e-12);
  for (const acd::Point2d& p : s.robot.polygon.outer) {
    EXPECT_GE(p.x(), -2 - 1e-12);
    EXPECT_LE(p.x(), 2 + 1e-12);
    EXPECT_GE(p.y(), -1 - 1e-12);
    EXPECT_LE(p.y(), 2 + 1e-12);
  }
  ASSERT_EQ(s.workspace.obstacles.size(), 2u);
  EXPECT_NEAR(acd::Area(s.workspace.obstacles[0]) + acd::Area(s.workspace.obstacles[1]), 8.0,
              1e-12);
  EXPECT_TRUE(s.workspace.bounds.min().isApprox(Eigen::Vector2d(-3, -3)));
  EXPECT_TRUE(s.workspace.bounds.max().isApprox(Eigen::Vector2d(10, 9)));
  ASSERT_EQ(s.start.size(), 3u);
  EXPECT_EQ(s.start, (std::vector<double>{0, 6, 0}));
  ASSERT_EQ(s.goal.size(), 3u);
  EXPECT_NEAR(s.goal[0], 8, 1e-12);
  EXPECT_NEAR(s.goal[1], 0, 1e-12);
  EXPECT_NEAR(s.goal[2], M_PI / 2, 1e-12);
  EXPECT_EQ(s.planner, PlannerType::kRrtConnect);  // the first [planner] entry
  EXPECT_EQ(s.time_limit, 2.5);
  EXPECT_EQ(s.sampler, SamplerType::kBridge);
  bool first_planner_warning = false, parameter_warning = false;
  for (const std::string& warning : s.warnings) {
    first_planner_warning |=
        warning.find("runs the first planner (rrtconnect)") != std::string::npos;
    parameter_warning |=
        warning.find("planar.cfg:31: rrtconnect: planner parameters") != std::string::npos;
  }
  EXPECT_TRUE(first_planner_warning);
  EXPECT_TRUE(parameter_warning);
}

TEST(ScenarioFromOmplApp, IgnoresWorldTrianglesOutsideTheRobotsSlab) {
  envs::OmplAppProblem p = envs::ReadOmplAppProblem(kData + "planar.cfg");
  // Lift the robot above the walls (z in [2, 2]): no obstacle is left.
  p.robot.vertices.col(2).array() += 2.0;
  EXPECT_TRUE(ScenarioFromOmplApp(p).workspace.obstacles.empty());
}

TEST(ScenarioFromOmplApp, Reads3dProblemsAsSe3Scenarios) {
  const envs::OmplAppProblem p = envs::ReadOmplAppProblem(kData + "spatial.cfg");
  const Scenario s = LoadScenarioFile(kData + "spatial.cfg");
  EXPECT_EQ(s.dimension, 3);
  EXPECT_EQ(s.robot.shape, envs::RobotShape::kMesh);
  EXPECT_EQ(s.workspace3d.obstacles.size(), 1u);
  EXPECT_TRUE(s.workspace3d.bounds.isApprox(p.bounds));
  ASSERT_EQ(s.start.size(), 6u);
  ASSERT_EQ(s.goal.size(), 6u);
  // [x, y, z, roll, pitch, yaw] gives back the file's poses (theta about the axis).
  EXPECT_TRUE(PoseFromXyzRpy(s.start).isApprox(p.start, 1e-12));
  EXPECT_TRUE(PoseFromXyzRpy(s.goal).isApprox(p.goal, 1e-12));
  EXPECT_EQ(s.sampler, SamplerType::kObstacleBased);
  EXPECT_EQ(s.sampler_options.orientation, AcdOrientation::kAligned);
}

TEST(ScenarioFromOmplApp, EveryMappedPlannerIsOneOfOurs) {
  for (const auto& [ompl_app, ours] : envs::OmplAppPlannerTable()) {
    EXPECT_EQ(ToString(ParsePlannerType(ours)), ours) << ompl_app;
  }
}

TEST(ScenarioFromOmplApp, Plans2dProblemEndToEnd) {
  Scenario s = LoadScenarioFile(kData + "planar.cfg");
  s.planner = PlannerType::kPrm;
  s.samples = 300;
  s.sampler = SamplerType::kAcd;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    s.seed = seed;
    const PlanResult result = PlanScenario(s);
    EXPECT_EQ(result.samples, 300u);
    // The plate is large for the gaps; the ACD sampler connects on each of these seeds.
    EXPECT_TRUE(result.solved) << "seed " << seed;
    if (result.solved) {
      EXPECT_EQ(result.path.front(), s.start);
      EXPECT_EQ(result.path.back(), s.goal);
    }
  }
}

TEST(ScenarioFromOmplApp, ControlProblemsBecomeCarScenarios) {
  const Scenario s = LoadScenarioFile(kData + "car.cfg");
  ASSERT_TRUE(s.car.has_value());
  EXPECT_EQ(s.car->model, control::CarModel::kKinematic);
  EXPECT_EQ(s.car->planner, control::ControlPlanner::kSyclopRrt);  // the first [planner] entry
  EXPECT_EQ(s.car->decomposition, control::DecompositionKind::kAcd);
  EXPECT_DOUBLE_EQ(s.car->goal_radius, 1.0);     // [problem] threshold
  EXPECT_DOUBLE_EQ(s.car->options.length, 1.0);  // OMPL.app's car
  EXPECT_EQ(s.time_limit, 5.0);
  ASSERT_EQ(s.robot.shape, envs::RobotShape::kPolygon);  // the plate's footprint
  EXPECT_NEAR(acd::Area(s.robot.polygon), 8.0, 1e-12);
  EXPECT_EQ(s.start, (std::vector<double>{0, 6, 0}));
  // It plans as a car (the planner stops after a number of checks, not on the clock).
  Scenario budgeted = s;
  budgeted.car->termination_checks = 5000;
  ConfigureOmpl(3, true);
  const PlanResult result = PlanScenario(budgeted);
  ASSERT_TRUE(result.car.has_value());
  EXPECT_EQ(result.car->planner, control::ControlPlanner::kSyclopRrt);
  EXPECT_EQ(result.car->regions, static_cast<int>(result.decomposition.components.size()));
  EXPECT_GT(result.samples, 0u);
  // Control problems read control planners; a geometric-only name or an unsupported system is
  // an error naming the line.
  const envs::OmplAppProblem problem = envs::ReadOmplAppProblem(kData + "car.cfg");
  EXPECT_EQ(problem.control, "kinematic_car");
  ASSERT_EQ(problem.planners.size(), 2u);
  EXPECT_EQ(problem.planners[1].planner, "KPIECE1");
}

// A Moving AI problem: its map as the world, cell centres as start and goal; and the errors of
// a problem that does not fit its map.
TEST(LoadScenarioFile, PlansAMovingAiProblem) {
  const test::ScratchDir dir;
  dir.Write("maze.map", "type octile\nheight 4\nwidth 5\nmap\n@@@@@\n@.@.@\n@...@\n@@@@@\n");
  const std::string scen =
      dir.Write("maze.map.scen",
                "version 1\n2\tmaps/maze.map\t5\t4\t1\t1\t3\t1\t4.82842712\n"
                "0\tmaze.map\t5\t4\t1\t1\t2\t1\t1\n0\tmaze.map\t6\t4\t1\t1\t3\t1\t1\n");
  EXPECT_TRUE(IsMovingAiScenarioFile("x/arena.map.SCEN"));
  Scenario s = LoadScenarioFile(scen, 0);
  EXPECT_EQ(s.start, (std::vector<double>{1.5, 2.5}));
  EXPECT_EQ(s.goal, (std::vector<double>{3.5, 2.5}));
  EXPECT_EQ(s.workspace_label, dir.Path("maze.map"));
  EXPECT_EQ(s.workspace.bounds.max(), Eigen::Vector2d(5, 4));
  EXPECT_EQ(s.description,
            "Moving AI problem 0 of " + scen + " (bucket 2, optimal length on the grid 4.82843)");
  s.samples = 300;
  const PlanResult result = PlanScenario(s);
  EXPECT_TRUE(result.solved);
  EXPECT_GT(result.path_length, 2.4);  // Around the wall between the cells (straight: 2).
  auto error = [&](int problem) {
    try {
      LoadScenarioFile(scen, problem);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error(1), scen + ":3: the goal cell (2, 1) is blocked in " + dir.Path("maze.map"));
  EXPECT_EQ(error(2), scen + ":4: the map " + dir.Path("maze.map") +
                          " has 5 x 4 cells, the problem says 6 x 4");
  EXPECT_EQ(error(3), scen + ": problem 3 out of range 0..2 (the file holds 3 problem(s))");
  EXPECT_EQ(error(-1), scen +
                           ": holds 3 problem(s) (a Moving AI scenario file): choose one, "
                           "counted from 0");
  EXPECT_THROW(LoadScenarioFile(acdplan::test::SourceDir() + "/configs/demo.yaml", 0), InputError);
}

// The README's example: every problem of the repository's scenario file fits its map.
TEST(LoadScenarioFile, ReadsEveryProblemOfTheExampleScenarioFile) {
  const std::string scen = acdplan::test::SourceDir() + "/configs/maps/rooms.map.scen";
  for (int problem = 0; problem < 4; ++problem) {
    const Scenario s = LoadScenarioFile(scen, problem);
    EXPECT_EQ(s.workspace.bounds.max(), Eigen::Vector2d(32, 16)) << problem;
  }
  EXPECT_THROW(LoadScenarioFile(scen, 4), InputError);
}

TEST(LoadScenarioFile, ReadsYamlScenariosAsBefore) {
  const Scenario s = LoadScenarioFile(acdplan::test::SourceDir() + "/configs/demo.yaml");
  EXPECT_FALSE(s.workspace.obstacles.empty());
  EXPECT_FALSE(IsOmplAppProblemFile("configs/demo.yaml"));
  EXPECT_TRUE(IsOmplAppProblemFile("x/Twistycool.CFG"));
}

}  // namespace
}  // namespace acdplan::planning
