#pragma once
// OMPL.app problem files (`.cfg`, envs/ompl_app_problem.h) as planning scenarios.

#include <string>

#include "envs/ompl_app_problem.h"
#include "planning/scenario.h"

namespace acdplan::planning {

/// The scenario of a 2D (SE(2)) OMPL.app problem: the world mesh's footprint (triangles that
/// reach the robot's z-slab, envs::Footprint) inside the volume's xy bounds is the workspace,
/// the robot mesh's footprint (shifted by OMPL.app's robot centre) is a polygon robot, start
/// and goal are [x, y, theta]. The first [planner] entry is the planner (PRM when there is
/// none; the others, and planner parameters, are named in `warnings`), [benchmark] time_limit
/// the budget, the file's sampler the sampler (acd when it names none).
/// A 3D (SE(3)) problem: the world mesh unmoved as the one obstacle inside the volume bounds
/// (envs::OmplAppWorkspace3d), the robot mesh about OMPL.app's robot centre, start and goal as
/// [x, y, z, roll, pitch, yaw], the 3D ACD samplers with aligned orientations
/// (planning/plan_scenario3d.h).
/// @throws InputError for the footprint's or the workspace's errors naming the mesh file.
Scenario ScenarioFromOmplApp(const envs::OmplAppProblem& problem);

/// Whether `path` names an OMPL.app problem file (extension `.cfg`, any case).
bool IsOmplAppProblemFile(const std::string& path);

/// LoadScenario() for a YAML scenario, ScenarioFromOmplApp(envs::ReadOmplAppProblem()) for a
/// `.cfg` file, ScenarioFromMovingAi(path, problem) for a Moving AI `.scen` file (which holds
/// many problems: `problem` chooses one, counted from 0); what the command line and benchmark
/// specs call.
/// @throws InputError from any of them; "<path>: holds N problem(s) (a Moving AI scenario
///         file): choose one, counted from 0" for a `.scen` file without `problem` (< 0);
///         "<path>: a problem number is only for a Moving AI .scen file" for another file with
///         one.
Scenario LoadScenarioFile(const std::string& path, int problem = -1);

}  // namespace acdplan::planning
