#pragma once
// Pictures of a 3D plan: the world, the free space's openings, the robot along the path.

#include <vector>

#include "acd/decomposition3d_io.h"
#include "planning/plan_scenario.h"
#include "planning/scenario.h"

namespace acdplan::planning {

/// The scene of a 3D plan for acd::SceneToObj / SceneToGlb / SceneToSvg: the obstacles
/// (translucent grey, "obstacle_<i>"), the openings of the free space's 3D ACD (flat orange
/// polygons, "opening_<i>"), the path as a thin red tube ("path"), and the robot at the start
/// (green), the goal (purple) and up to 8 poses along the path (red, "robot_<k>"); a point
/// robot is a small cube. Without a solution: no path and no poses along it.
std::vector<acd::SceneMesh3d> PlanScene3d(const Scenario& scenario, const PlanResult& result);

}  // namespace acdplan::planning
