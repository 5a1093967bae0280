#pragma once
// The time-budget half of PlanScenario() and PlanScenario3d(): one planner, one query.

#include <ompl/base/Planner.h>
#include <ompl/base/ScopedState.h>

#include "planning/plan_scenario.h"

namespace acdplan::planning::internal {

/// Runs `planner` (not yet set up) from `start` to `goal` for `time_limit` seconds and fills
/// `result`: solved (exact solutions only), path_length and the raw path states, samples (the
/// planner data's vertices) and the vertices and edges for pictures.
void RunOnTimeLimit(const ompl::base::PlannerPtr& planner, const ompl::base::ScopedState<>& start,
                    const ompl::base::ScopedState<>& goal, double time_limit, PlanResult* result);

}  // namespace acdplan::planning::internal
