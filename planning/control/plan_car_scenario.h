#pragma once
// Runs a car scenario (Scenario::car): PlanCar() on the scenario's world, body and query.

#include <string>

#include "planning/plan_scenario.h"

namespace acdplan::planning::control {

/// Plans the car of `scenario` (scenario.car set) with PlanCar(): its model and bounds, its
/// control planner and (Syclop) decomposition, the scenario's ACD options and collision mode,
/// on scenario.time_limit. OMPL's global seed is the caller's (ConfigureOmpl()).
/// @throws InputError if the start or the goal pose is in collision or out of bounds.
PlanResult PlanCarScenario(const Scenario& scenario);

/// The SVG picture of a car plan: Syclop's regions (the ACD's components, or the grid), the
/// regions the trajectory passes through shaded (ids "lead-region-<i>" / "lead-cell-<i>-<j>"),
/// obstacles, the trajectory and the car's body along it, start and goal (with its radius).
std::string CarPlanToSvg(const Scenario& scenario, const PlanResult& result);

}  // namespace acdplan::planning::control
