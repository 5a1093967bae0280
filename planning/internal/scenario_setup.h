#pragma once
// What planning a geometric scenario in 2D and in 3D share: the budget's label, the collision
// world, the bounded state space with its counting validity checker, and the start/goal check.

#include <ompl/base/SpaceInformation.h>

#include <Eigen/Core>
#include <memory>
#include <string>

#include "collision/collision_world.h"
#include "collision/obstacle_set.h"
#include "planning/counting_validity_checker.h"
#include "planning/plan_scenario.h"
#include "planning/sample_budget_roadmap.h"
#include "planning/scenario.h"

namespace acdplan::planning::internal {

/// "N samples" or "T s": the scenario's budget as PlanResult::budget says it.
std::string BudgetLabel(const Scenario& scenario);

/// The collision world of `workspace` (Workspace2d or Workspace3d) and the scenario's robot, in
/// the scenario's collision mode.
template <typename Workspace>
std::shared_ptr<const collision::CollisionWorld> MakeCollisionWorld(const Workspace& workspace,
                                                                    const Scenario& scenario) {
  auto obstacles =
      std::make_shared<const collision::ObstacleSet>(collision::BuildObstacleSet(workspace));
  collision::CollisionWorldOptions options;
  options.mode = scenario.collision_mode;
  return std::make_shared<const collision::CollisionWorld>(obstacles, scenario.robot, options);
}

/// A space information and the checker counting its validity checks.
struct CheckedSpace {
  std::shared_ptr<ompl::base::SpaceInformation> si;
  std::shared_ptr<CountingValidityChecker> checker;
};

/// SE(d) for a rigid body (`rigid`), else R^d, d = low.size() (2 or 3), its position bounded by
/// [low, high]; validity is `valid`, counted; motions are checked every 0.2% of the space's
/// extent (OMPL's default is 1%: too coarse for the thinnest walls of the built-in worlds, 0.25
/// in a 10-unit maze). Set up.
CheckedSpace MakeCheckedSpace(const Eigen::VectorXd& low, const Eigen::VectorXd& high, bool rigid,
                              CountingValidityChecker::Predicate valid);

/// @throws InputError "<where>: start: the robot is in collision or out of bounds there" (and
///         likewise for the goal) unless both are in the bounds and valid. Then zeroes the
///         checker's count, so that the run counts only the planner's checks.
void CheckEndpoints(const CheckedSpace& space, const ompl::base::State* start,
                    const ompl::base::State* goal, const std::string& where);

/// Builds the sample-budget roadmap (BuildSampleBudgetRoadmap()) from `start` to `goal` and
/// moves what it found (solved, samples, path and its length, the roadmap) into `result`.
void RunSampleBudget(const std::shared_ptr<ompl::base::SpaceInformation>& si,
                     const ompl::base::State* start, const ompl::base::State* goal,
                     const SampleBudgetOptions& options, PlanResult* result);

}  // namespace acdplan::planning::internal
