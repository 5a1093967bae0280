// Car scenarios (Scenario::car): every new YAML key's errors, the fields a car file sets, and a
// kinematic car through the bug trap end to end from YAML with both of Syclop's decompositions
// (the ACD's regions and OMPL's grid). The planner stops after a fixed number of
// termination-condition checks, not on a clock, so a run depends on its seed only.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "acd/decomposition2d.h"
#include "base/input_error.h"
#include "collision/collision_world.h"
#include "collision/obstacle_set.h"
#include "planning/plan_scenario.h"
#include "planning/scenario.h"
#include "tests/data_paths.h"
#include "tests/input_error_of.h"
#include "tests/scratch_dir.h"

namespace acdplan::planning {
namespace {

using acdplan::test::kConfigs;

/// Writes `text` to a scenario file in the process's scratch folder and returns its path.
std::string Write(const std::string& name, const std::string& text) {
  static const test::ScratchDir dir("acdplan_car_scenario_test");  // Removed at exit.
  return dir.Write(name, text);
}

const std::string kWorld = "workspace: {generator: bug_trap, seed: 1}\n";
const std::string kCar = "robot: {type: kinematic_car, length: 0.3, width: 0.15}\n";
const std::string kPoses = "start: [5, 5, 0]\ngoal: [9, 5, 0]\n";

/// The message LoadScenario() throws for `text`; "" if it does not throw.
std::string ErrorOf(const std::string& text) {
  return test::InputErrorOf([&] { LoadScenario(Write("bad.yaml", text)); });
}

void ExpectError(const std::string& text, const std::string& expected) {
  const std::string error = ErrorOf(text);
  EXPECT_NE(error.find(expected), std::string::npos)
      << "expected '" << expected << "' in '" << error << "'";
  EXPECT_EQ(error.rfind(Write("bad.yaml", ""), 0), 0u) << "names the file: " << error;
}

TEST(CarScenario, EveryNewKeyIsValidatedWithTheKeyPath) {
  ExpectError(kWorld + "robot: {type: bicycle}\n" + kPoses,
              "robot.type: unknown car 'bicycle' (expected one of: kinematic_car, dynamic_car)");
  ExpectError(kWorld + kCar + kPoses + "planner: {name: PRM}\n",
              "planner.name: PRM is a geometric planner; a car (robot.type kinematic_car) needs a "
              "control planner: SyclopRRT, SyclopEST, RRT, KPIECE1, EST, PDST");
  ExpectError(kWorld + "start: [5, 5]\ngoal: [9, 5]\nplanner: {name: SyclopEST}\n",
              "planner.name: SyclopEST is a control planner: it needs a car robot");
  ExpectError(kWorld + kCar + kPoses + "planner: {name: Syclop}\n",
              "planner.name: unknown control planner 'Syclop'");
  ExpectError(kWorld + "start: [5, 5]\ngoal: [9, 5]\ndecomposition: {name: acd}\n",
              "decomposition: only for a car");
  ExpectError(kWorld + "start: [5, 5]\ngoal: [9, 5]\ngoal_radius: 1\n",
              "goal_radius: only for a car");
  ExpectError(kWorld + kCar + kPoses + "decomposition: {name: voronoi}\n",
              "decomposition.name: unknown decomposition 'voronoi' (expected one of: acd, grid)");
  ExpectError(kWorld + kCar + kPoses + "decomposition: {name: acd, cells: 10}\n",
              "decomposition.cells: only for name: grid");
  ExpectError(kWorld + kCar + kPoses + "decomposition: {name: grid, cells: 0}\n",
              "decomposition.cells: expected an integer >= 1 (cells per side), got '0'");
  ExpectError(kWorld + kCar + kPoses + "decomposition: {name: grid, cells: 5000000000}\n",
              "decomposition.cells: expected at most 1000 cells per side");
  ExpectError(kWorld + kCar + kPoses + "decomposition: {name: grid, size: 3}\n",
              "decomposition.size: unknown key");
  ExpectError(kWorld + kCar + kPoses + "sampler: {name: acd}\n",
              "sampler: a car is planned by a control planner, which takes no sampler");
  ExpectError(kWorld + kCar + "start: [5, 5]\ngoal: [9, 5, 0]\n",
              "start: expected [x, y, yaw] (a car plans in SE(2), yaw in rad)");
  ExpectError(kWorld + kCar + kPoses + "planner: {name: RRT, samples: 100}\n",
              "planner.samples: a car's control planner takes a time_limit");
  ExpectError(kWorld + kCar + kPoses + "goal_radius: -1\n",
              "goal_radius: expected a positive number, got '-1'");
  ExpectError(kWorld + "robot: {type: kinematic_car, max_accel: 1}\n" + kPoses,
              "robot.max_accel: only for type dynamic_car");
  ExpectError(kWorld + "robot: {type: kinematic_car, max_steer: 2}\n" + kPoses,
              "robot.max_steer: expected a number in (0, pi/2) [rad], got '2'");
  ExpectError(kWorld + "robot: {type: dynamic_car, length: 0}\n" + kPoses,
              "robot.length: expected a positive number, got '0'");
  ExpectError(kWorld +
                  "robot: {type: kinematic_car, min_control_steps: 5, "
                  "max_control_steps: 2}\n" +
                  kPoses,
              "robot.max_control_steps: expected >= min_control_steps (5), got 2");
  ExpectError(
      kWorld + "robot: {type: kinematic_car, shape: disc, radius: 0.1, width: 0.2}\n" + kPoses,
      "robot.width: not with shape");
  ExpectError(kWorld + "robot: {type: kinematic_car, wheels: 4}\n" + kPoses,
              "robot.wheels: unknown key");
  ExpectError(kWorld + kCar +
                  "start: [5, 5, 0]\ngoal: [9, 5, 0]\nplanner: {name: KPIECE1, "
                  "time_limit: 0}\n",
              "planner.time_limit: expected a positive number, got '0'");
}

TEST(CarScenario, FieldsAndDefaults) {
  const Scenario s = LoadScenario(Write(
      "car.yaml", kWorld +
                      "robot: {type: dynamic_car, length: 0.4, max_speed: 2, max_steer: 0.5, "
                      "max_accel: 1, max_steer_rate: 0.2, step: 0.1, max_control_steps: 10}\n" +
                      kPoses +
                      "planner: {name: SyclopEST, time_limit: 3}\ndecomposition: {name: grid, "
                      "cells: 16}\ngoal_radius: 0.25\n"));
  ASSERT_TRUE(s.car.has_value());
  EXPECT_EQ(s.car->model, control::CarModel::kDynamic);
  EXPECT_EQ(s.car->planner, control::ControlPlanner::kSyclopEst);
  EXPECT_EQ(s.car->decomposition, control::DecompositionKind::kGrid);
  EXPECT_EQ(s.car->grid_cells, 16);
  EXPECT_DOUBLE_EQ(s.car->goal_radius, 0.25);
  EXPECT_DOUBLE_EQ(s.car->options.length, 0.4);
  EXPECT_DOUBLE_EQ(s.car->options.max_speed, 2.0);
  EXPECT_DOUBLE_EQ(s.car->options.max_steer, 0.5);
  EXPECT_DOUBLE_EQ(s.car->options.max_accel, 1.0);
  EXPECT_DOUBLE_EQ(s.car->options.max_steer_rate, 0.2);
  EXPECT_DOUBLE_EQ(s.car->options.step, 0.1);
  EXPECT_EQ(s.car->options.max_control_steps, 10u);
  EXPECT_DOUBLE_EQ(s.time_limit, 3.0);
  // The default body: the length x width rectangle (width = length / 2), centred.
  ASSERT_EQ(s.robot.shape, envs::RobotShape::kPolygon);
  EXPECT_NEAR(std::abs(acd::SignedArea(s.robot.polygon.outer)), 0.4 * 0.2, 1e-12);
  // OMPL.app's defaults.
  const Scenario k =
      LoadScenario(Write("k.yaml", kWorld + "robot: {type: kinematic_car}\n" + kPoses));
  EXPECT_EQ(k.car->planner, control::ControlPlanner::kSyclopRrt);
  EXPECT_EQ(k.car->decomposition, control::DecompositionKind::kAcd);
  EXPECT_DOUBLE_EQ(k.car->options.length, 1.0);
  EXPECT_NEAR(k.car->options.max_steer, 30 * M_PI / 180, 1e-12);
  // A decomposition with a planner that does not follow one: accepted with a warning.
  const Scenario w = LoadScenario(Write("w.yaml", kWorld + kCar + kPoses +
                                                      "planner: {name: KPIECE1}\ndecomposition: "
                                                      "{name: grid}\n"));
  ASSERT_EQ(w.warnings.size(), 1u);
  EXPECT_NE(w.warnings[0].find("decomposition: unused by KPIECE1"), std::string::npos);
}

TEST(CarScenario, ShippedCarConfigsLoad) {
  for (const char* name : {"car_bug_trap.yaml", "car_maze.yaml"}) {
    const Scenario s = LoadScenario(kConfigs + "/" + name);
    EXPECT_TRUE(s.car.has_value()) << name;
  }
}

/// Every state of the car's trajectory is a free pose inside the bounds, consecutive states are
/// close (a propagation step apart), it starts at the start and ends within the goal radius.
void ExpectValidTrajectory(const Scenario& s, const PlanResult& result) {
  ASSERT_TRUE(result.car.has_value());
  const auto& trajectory = result.car->trajectory;
  ASSERT_GE(trajectory.size(), 2u);
  const collision::CollisionWorld world(
      std::make_shared<const collision::ObstacleSet>(collision::BuildObstacleSet(s.workspace)),
      s.robot, {});
  const double step = s.car->options.max_speed * s.car->options.step;
  for (size_t i = 0; i < trajectory.size(); ++i) {
    const auto& q = trajectory[i];
    Eigen::Isometry2d pose = Eigen::Isometry2d::Identity();
    pose.translate(Eigen::Vector2d(q[0], q[1]));
    pose.rotate(q[2]);
    ASSERT_TRUE(envs::InsideBounds(s.robot, s.workspace.bounds, pose) && world.IsValid(pose))
        << "state " << i << " at (" << q[0] << ", " << q[1] << ", " << q[2] << ")";
    if (i > 0) {
      EXPECT_LE(std::hypot(q[0] - trajectory[i - 1][0], q[1] - trajectory[i - 1][1]),
                step * (1 + 1e-9))
          << "state " << i;
    }
  }
  EXPECT_NEAR(trajectory.front()[0], s.start[0], 1e-12);
  EXPECT_NEAR(trajectory.front()[1], s.start[1], 1e-12);
  EXPECT_LE(std::hypot(trajectory.back()[0] - s.goal[0], trajectory.back()[1] - s.goal[1]),
            s.car->goal_radius);
}

/// The car of configs/car_bug_trap.yaml with `decomposition` and a budget of checks.
Scenario BugTrapCar(const std::string& decomposition) {
  Scenario s = LoadScenario(
      Write("car.yaml", "workspace: " + kConfigs + "/../envs/2d/bug_trap.yaml\n" + kCar + kPoses +
                            "planner: {name: SyclopRRT}\ndecomposition: " + decomposition + "\n"));
  s.car->termination_checks = 200000;
  return s;
}

TEST(CarScenario, KinematicCarLeavesTheBugTrapOnTheAcdRegions) {
  const Scenario s = BugTrapCar("{name: acd}");
  ConfigureOmpl(7, true);
  const PlanResult result = PlanScenario(s);
  ASSERT_TRUE(result.solved);
  ExpectValidTrajectory(s, result);
  const CarPlan& car = *result.car;
  EXPECT_EQ(car.decomposition, control::DecompositionKind::kAcd);
  EXPECT_EQ(car.regions, static_cast<int>(result.decomposition.components.size()));
  EXPECT_GT(result.path_length, 0.0);  // The duration [s].
  // The regions passed through form a chain of adjacent ACD components from the start's to
  // the goal's: the lead the tree followed.
  ASSERT_GE(car.visited_regions.size(), 2u);
  const auto graph = acd::ComponentGraph(result.decomposition);
  for (size_t i = 1; i < car.visited_regions.size(); ++i) {
    const auto& next = graph[car.visited_regions[i - 1]];
    EXPECT_NE(std::find(next.begin(), next.end(), car.visited_regions[i]), next.end())
        << "regions " << car.visited_regions[i - 1] << " and " << car.visited_regions[i]
        << " are not adjacent";
  }
  // The picture shades exactly those regions and shows the trajectory.
  const std::string svg = PlanResultToSvg(s, result);
  for (int region : car.visited_regions) {
    EXPECT_NE(svg.find("id=\"lead-region-" + std::to_string(region) + "\""), std::string::npos)
        << region;
  }
  EXPECT_EQ(svg.find("id=\"lead-region-" + std::to_string(car.regions) + "\""), std::string::npos);
  EXPECT_NE(svg.find("id=\"trajectory\""), std::string::npos);
  // The JSON names the car's planner and decomposition.
  const std::string json = PlanResultToJson(s, result);
  EXPECT_NE(json.find("\"planner\": \"SyclopRRT\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"decomposition\": \"acd\""), std::string::npos) << json;
  // Same seed, same run.
  ConfigureOmpl(7, true);
  const PlanResult again = PlanScenario(s);
  EXPECT_EQ(again.car->trajectory, car.trajectory);
}

TEST(CarScenario, KinematicCarLeavesTheBugTrapOnAGrid) {
  const Scenario s = BugTrapCar("{name: grid, cells: 20}");
  ConfigureOmpl(7, true);
  const PlanResult result = PlanScenario(s);
  ASSERT_TRUE(result.solved);
  ExpectValidTrajectory(s, result);
  EXPECT_EQ(result.car->regions, 400);
  EXPECT_GE(result.car->visited_regions.size(), 2u);
  const std::string svg = PlanResultToSvg(s, result);
  EXPECT_NE(svg.find("id=\"grid\""), std::string::npos);
  // The start's cell (5, 5) / 0.5 per cell = (10, 10) is shaded.
  EXPECT_NE(svg.find("id=\"lead-cell-10-10\""), std::string::npos);
}

TEST(CarScenario, GoalInCollisionIsAnInputError) {
  Scenario s = BugTrapCar("{name: acd}");
  s.goal = {-3, 5, 0};
  try {
    PlanScenario(s);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("car.yaml: goal: the robot is in collision"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace acdplan::planning
