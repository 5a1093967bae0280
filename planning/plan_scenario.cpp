#include "planning/plan_scenario.h"

#include <ompl/base/Planner.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <chrono>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "acd/decompose2d.h"
#include "base/input_error.h"
#include "base/stopwatch.h"
#include "collision/collision_mode.h"
#include "collision/collision_world.h"
#include "collision/obstacle_set.h"
#include "envs/free_space2d.h"
#include "envs/world_svg.h"
#include "planning/acd_lead_sampler.h"
#include "planning/control/plan_car_scenario.h"
#include "planning/counting_validity_checker.h"
#include "planning/decomposition_cache.h"
#include "planning/internal/run_on_time_limit.h"
#include "planning/internal/scenario_setup.h"
#include "planning/plan_picture3d.h"
#include "planning/plan_scenario3d.h"
#include "planning/registry.h"
#include "planning/sample_budget_roadmap.h"
#include "planning/tau_diag.h"

namespace acdplan::planning {

namespace ob = ompl::base;

namespace {

Eigen::Isometry2d Pose(bool se2, const ob::State* state) {
  Eigen::Isometry2d pose = Eigen::Isometry2d::Identity();
  if (se2) {
    const auto* s = state->as<ob::SE2StateSpace::StateType>();
    pose.translate(Eigen::Vector2d(s->getX(), s->getY()));
    pose.rotate(s->getYaw());
  } else {
    const double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
    pose.translate(Eigen::Vector2d(v[0], v[1]));
  }
  return pose;
}

}  // namespace

acd::Decompose2dOptions ScenarioAcdOptions(const Scenario& scenario) {
  acd::Decompose2dOptions options;
  options.tau = TauOfBounds(scenario.tau_diag, scenario.workspace.bounds);
  options.measure = scenario.measure;
  return options;
}

PlanResult PlanScenario(const Scenario& scenario) {
  CheckScenario(scenario);
  if (scenario.dimension == 3) return PlanScenario3d(scenario);
  if (scenario.car) return control::PlanCarScenario(scenario);
  const Stopwatch stopwatch;
  const std::string where = scenario.path.empty() ? "scenario" : scenario.path;
  PlanResult result;
  result.sampler = scenario.sampler;
  result.planner = scenario.planner;
  result.budget = internal::BudgetLabel(scenario);

  // Free space and its ACD (the sampler's targets; decomposed for every sampler, so time_s
  // compares like with like).
  const envs::Workspace2d& workspace = scenario.workspace;
  const CachedDecomposition cached =
      DecomposeFreeSpaceCached(workspace, ScenarioAcdOptions(scenario));
  result.decomposition = *cached.decomposition;
  result.decomposition_ms = stopwatch.Milliseconds();
  result.decomposition_compute_ms = cached.compute_ms;
  result.decomposition_cached = cached.hit;
  result.components = static_cast<int>(result.decomposition.components.size());
  result.openings = static_cast<int>(result.decomposition.openings.size());

  // Collision world and the state space.
  const auto world = internal::MakeCollisionWorld(workspace, scenario);
  const bool se2 = scenario.robot.shape == envs::RobotShape::kPolygon;
  const envs::Robot robot = scenario.robot;
  const Eigen::AlignedBox2d box = workspace.bounds;
  const internal::CheckedSpace checked = internal::MakeCheckedSpace(
      box.min(), box.max(), se2, [world, robot, box, se2](const ob::State* state) {
        const Eigen::Isometry2d pose = Pose(se2, state);
        return envs::InsideBounds(robot, box, pose) && world->IsValid(pose);
      });
  const std::shared_ptr<ob::SpaceInformation>& si = checked.si;
  const std::shared_ptr<CountingValidityChecker>& checker = checked.checker;

  ob::ScopedState<> start(si), goal(si);
  for (size_t i = 0; i < scenario.start.size(); ++i) {
    // OMPL's SO(2) holds angles in [-pi, pi]; a scenario may give any yaw.
    const bool yaw = se2 && i == 2;
    start[i] = yaw ? std::remainder(scenario.start[i], 2 * M_PI) : scenario.start[i];
    goal[i] = yaw ? std::remainder(scenario.goal[i], 2 * M_PI) : scenario.goal[i];
  }
  internal::CheckEndpoints(checked, start.get(), goal.get(), where);

  AcdSamplerOptions sampler_options = scenario.sampler_options;
  sampler_options.seed = scenario.seed;
  AcdLeadQuery lead;
  lead.start = Eigen::Vector2d(scenario.start[0], scenario.start[1]);
  lead.goal = Eigen::Vector2d(scenario.goal[0], scenario.goal[1]);
  lead.robot_width = RobotWidth(scenario.robot);
  InstallSampler(scenario.sampler, si, result.decomposition, sampler_options, &lead);

  if (scenario.samples > 0) {
    SampleBudgetOptions options;
    options.samples = scenario.samples;
    options.star = scenario.planner == PlannerType::kPrmStar;
    if (scenario.planner == PlannerType::kPrmAcd) {
      options.acd_connections = &result.decomposition;
      options.seed = scenario.seed;
    }
    internal::RunSampleBudget(si, start.get(), goal.get(), options, &result);
  } else {
    ob::PlannerPtr planner =
        MakePlanner(scenario.planner, si, &result.decomposition, scenario.seed);
    internal::RunOnTimeLimit(planner, start, goal, scenario.time_limit, &result);
  }
  result.collision_checks = checker->checks();
  result.time_s = stopwatch.Seconds();
  return result;
}

void ConfigureOmpl(std::uint64_t seed, bool quiet) {
  if (quiet) ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  // OMPL's seed is 32 bits; 0 would mean "pick one".
  ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(seed % 4294967295ULL) + 1);
}

std::string PlanResultToJson(const Scenario& scenario, const PlanResult& result) {
  nlohmann::json j;
  j["format"] = "acdplan.plan/1";
  j["scenario"] = scenario.path;
  j["solved"] = result.solved;
  if (result.car) {
    // A car: its model, control planner and Syclop's regions instead of a sampler.
    const CarPlan& car = *result.car;
    j["robot"] = control::ToString(scenario.car->model);
    j["planner"] = control::ToString(car.planner);
    j["decomposition"] =
        car.decomposition ? nlohmann::json(control::ToString(*car.decomposition)) : nullptr;
    if (car.decomposition == control::DecompositionKind::kGrid) j["grid_cells"] = car.grid_cells;
    j["regions"] = car.regions;
    j["visited_regions"] = car.visited_regions;
    j["duration_s"] = car.duration_s;
  } else {
    j["sampler"] = ToString(result.sampler);
    j["planner"] = ToString(result.planner);
  }
  j["budget"] = result.budget;
  j["seed"] = scenario.seed;
  j["time_s"] = result.time_s;
  j["decomposition_ms"] = result.decomposition_ms;
  j["decomposition_compute_ms"] = result.decomposition_compute_ms;
  j["decomposition_cached"] = result.decomposition_cached;
  j["samples"] = result.samples;
  j["collision_checks"] = result.collision_checks;
  j["path_length"] = result.path_length;
  j["components"] = result.components;
  j["openings"] = result.openings;
  j["path"] = result.path;
  return j.dump(2) + "\n";
}

std::string PlanResultToSvg(const Scenario& scenario, const PlanResult& result) {
  if (scenario.dimension == 3) {
    return acd::SceneToSvg(
        PlanScene3d(scenario, result),
        {(scenario.path.empty() ? std::string("scenario") : scenario.path),
         ToString(result.sampler) + " + " + ToString(result.planner) + ", " + result.budget + ": " +
             (result.solved ? "solved" : "not solved") + " (" + std::to_string(result.samples) +
             " samples, " + std::to_string(result.components) + " components, " +
             std::to_string(result.openings) +
             " openings in orange; start green, goal purple, path red)"},
        /*z_up=*/true);
  }
  if (result.car) return control::CarPlanToSvg(scenario, result);
  envs::WorldSvg f(scenario.workspace.bounds);
  f.AddComponents(result.decomposition, /*distinct=*/false);
  f.AddObstacles(scenario.workspace.obstacles);
  f.AddOpenings(result.decomposition);
  std::ostringstream svg;
  svg << "<g id=\"roadmap-edges\" stroke=\"#4a7bd0\" stroke-width=\"0.6\" "
         "stroke-opacity=\"0.7\">\n";
  for (const auto& [a, b] : result.edges) {
    const auto& p = result.vertices[a];
    const auto& q = result.vertices[b];
    svg << "<line x1=\"" << f.X(p[0]) << "\" y1=\"" << f.Y(p[1]) << "\" x2=\"" << f.X(q[0])
        << "\" y2=\"" << f.Y(q[1]) << "\"/>\n";
  }
  svg << "</g>\n<g id=\"roadmap-vertices\" fill=\"#1f4fa0\">\n";
  for (const auto& v : result.vertices) {
    svg << "<circle cx=\"" << f.X(v[0]) << "\" cy=\"" << f.Y(v[1]) << "\" r=\"2\"/>\n";
  }
  svg << "</g>\n";
  const bool se2 = scenario.robot.shape == envs::RobotShape::kPolygon;
  auto robot_at = [&](const std::vector<double>& q, const char* colour) {
    if (!se2) return;
    Eigen::Isometry2d pose = Eigen::Isometry2d::Identity();
    pose.translate(Eigen::Vector2d(q[0], q[1]));
    pose.rotate(q[2]);
    acd::Ring2d ring;
    for (const acd::Point2d& p : scenario.robot.polygon.outer) ring.push_back(pose * p);
    svg << "<path d=\"" << f.PathData(acd::Polygon2d{ring, {}}) << "\" fill=\"" << colour
        << "\" fill-opacity=\"0.35\" stroke=\"" << colour << "\"/>\n";
  };
  if (!result.path.empty()) {
    svg << "<g id=\"path\">\n";
    for (const auto& q : result.path) robot_at(q, "#c92a2a");
    svg << "<polyline fill=\"none\" stroke=\"#e03131\" stroke-width=\"2.5\" points=\"";
    for (const auto& q : result.path) svg << f.X(q[0]) << "," << f.Y(q[1]) << " ";
    svg << "\"/>\n</g>\n";
  }
  robot_at(scenario.start, "#2b8a3e");
  robot_at(scenario.goal, "#862e9c");
  svg << "<circle id=\"start\" cx=\"" << f.X(scenario.start[0]) << "\" cy=\""
      << f.Y(scenario.start[1]) << "\" r=\"6\" fill=\"#2b8a3e\"/>\n";
  svg << "<circle id=\"goal\" cx=\"" << f.X(scenario.goal[0]) << "\" cy=\"" << f.Y(scenario.goal[1])
      << "\" r=\"6\" fill=\"#862e9c\"/>\n";
  f.Add(svg.str());
  return f.Finish(ToString(result.sampler) + " + " + ToString(result.planner) + ", " +
                  result.budget + ": " + (result.solved ? "solved" : "not solved") + " (" +
                  std::to_string(result.samples) + " samples, " +
                  std::to_string(result.components) + " components, " +
                  std::to_string(result.openings) + " openings)");
}

}  // namespace acdplan::planning
