#include "planning/scenario_cfg.h"

#include <cmath>
#include <filesystem>

#include "acd/internal/text_parsing.h"
#include "base/input_error.h"
#include "envs/mesh_footprint.h"
#include "envs/moving_ai_scenario.h"
#include "planning/scenario_moving_ai.h"

namespace acdplan::planning {
namespace {

/// The yaw of a rotation about z.
double Yaw(const Eigen::Isometry3d& pose) {
  const Eigen::Vector3d x = pose.linear() * Eigen::Vector3d::UnitX();
  return std::atan2(x.y(), x.x());
}

}  // namespace

Scenario ScenarioFromOmplApp(const envs::OmplAppProblem& problem) {
  Scenario s;
  s.path = problem.path;
  s.description = "OMPL.app problem " + problem.name;
  s.warnings = problem.warnings;
  if (problem.dimension == 3) {
    // SE(3): the world mesh unmoved, the robot mesh about its centre, poses as x, y, z, roll,
    // pitch, yaw (planning/plan_scenario3d.h PoseFromXyzRpy), the 3D ACD samplers aligned.
    s.dimension = 3;
    s.workspace3d = envs::OmplAppWorkspace3d(problem);
    s.workspace_label = problem.world_path.empty() ? "empty world" : problem.world_path;
    s.robot = envs::Robot::Mesh(problem.robot);
    s.sampler_options.orientation = AcdOrientation::kAligned;
    for (const Eigen::Isometry3d* pose : {&problem.start, &problem.goal}) {
      std::vector<double>& q = pose == &problem.start ? s.start : s.goal;
      const Eigen::Vector3d t = pose->translation();
      const Eigen::Vector3d ypr = pose->linear().eulerAngles(2, 1, 0);  // yaw, pitch, roll.
      q = {t.x(), t.y(), t.z(), ypr[2], ypr[1], ypr[0]};
    }
  }

  if (s.dimension == 2) {
    s.robot = envs::Robot::Polygon(envs::FootprintOutline(problem.robot, problem.robot_path));
    envs::Workspace2d raw;
    raw.bounds =
        Eigen::AlignedBox2d(problem.bounds.min().head<2>(), problem.bounds.max().head<2>());
    raw.description = s.description;
    if (problem.world.vertices.rows() > 0) {
      // OMPL.app checks collisions in 3D with the robot at z = 0: a world triangle entirely
      // above or below the robot's slab never touches it.
      envs::FootprintOptions slab;
      slab.z_min = problem.robot.vertices.col(2).minCoeff();
      slab.z_max = problem.robot.vertices.col(2).maxCoeff();
      raw.obstacles = envs::Footprint(problem.world, problem.world_path, slab);
      s.workspace_label = problem.world_path + " (footprint)";
    } else {
      s.workspace_label = "empty world";
    }
    s.workspace = envs::PrepareWorkspace2d(raw, problem.path);

    for (const Eigen::Isometry3d* pose : {&problem.start, &problem.goal}) {
      std::vector<double>& q = pose == &problem.start ? s.start : s.goal;
      q = {pose->translation().x(), pose->translation().y(), Yaw(*pose)};
    }
  }

  if (!problem.control.empty()) {
    // A car (OMPL.app's KinematicCarPlanning / DynamicCarPlanning, their default bounds and
    // wheelbase 1): the robot mesh's footprint as its body, Syclop on the ACD by default.
    s.car.emplace();
    s.car->model = control::ParseCarModel(problem.control);
    if (problem.goal_threshold > 0) s.car->goal_radius = problem.goal_threshold;
    if (!problem.sampler.empty()) {
      s.warnings.push_back(problem.path +
                           ": sampler: ignored for a car (a control planner takes "
                           "no valid-state sampler)");
    }
  }
  if (!problem.planners.empty()) {
    const envs::OmplAppPlanner& first = problem.planners.front();
    if (s.car) {
      s.car->planner = control::ParseControlPlanner(first.planner);
    } else {
      s.planner = ParsePlannerType(first.planner);
    }
    if (problem.planners.size() > 1) {
      s.warnings.push_back(problem.path + ":" + std::to_string(first.line) +
                           ": acdplan plan runs the first planner (" + first.ompl_app_name +
                           "); `acdplan bench` compares planners");
    }
    for (const envs::OmplAppPlanner& planner : problem.planners) {
      if (!planner.parameters.empty() || !planner.context.empty()) {
        s.warnings.push_back(problem.path + ":" + std::to_string(planner.line) + ": " +
                             planner.ompl_app_name +
                             ": planner parameters and problem.* settings are ignored (OMPL's "
                             "defaults are used)");
      }
    }
  }
  if (problem.time_limit > 0) s.time_limit = problem.time_limit;
  if (!problem.sampler.empty() && !s.car) s.sampler = ParseSamplerType(problem.sampler);
  CheckScenario(s);
  return s;
}

bool IsOmplAppProblemFile(const std::string& path) {
  return acd::internal::ToLower(std::filesystem::path(path).extension().string()) == ".cfg";
}

Scenario LoadScenarioFile(const std::string& path, int problem) {
  if (IsMovingAiScenarioFile(path)) {
    if (problem < 0) {
      throw InputError(path + ": holds " + std::to_string(envs::ReadMovingAiScenario(path).size()) +
                       " problem(s) (a Moving AI scenario file): choose one, counted from 0");
    }
    return ScenarioFromMovingAi(path, problem);
  }
  if (problem >= 0) {
    throw InputError(path + ": a problem number is only for a Moving AI .scen file");
  }
  if (IsOmplAppProblemFile(path)) return ScenarioFromOmplApp(envs::ReadOmplAppProblem(path));
  return LoadScenario(path);
}

}  // namespace acdplan::planning
