#include "planning/control/plan_car_scenario.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <utility>

#include "base/format.h"
#include "base/input_error.h"
#include "envs/world_svg.h"
#include "planning/control/plan_car.h"

namespace acdplan::planning::control {

namespace {

bool IsSyclop(ControlPlanner planner) {
  return planner == ControlPlanner::kSyclopRrt || planner == ControlPlanner::kSyclopEst;
}

Eigen::Vector3d Pose3(const std::vector<double>& q) { return {q[0], q[1], q[2]}; }

}  // namespace

PlanResult PlanCarScenario(const Scenario& scenario) {
  const CarScenario& car = *scenario.car;
  CarQuery query;
  query.workspace = scenario.workspace;
  query.robot = scenario.robot;
  query.model = car.model;
  query.car = car.options;
  query.start = Pose3(scenario.start);
  query.goal = Pose3(scenario.goal);
  query.goal_radius = car.goal_radius;
  query.planner = car.planner;
  query.decomposition = car.decomposition;
  query.grid_cells = car.grid_cells;
  query.tau_diag = scenario.tau_diag;
  query.measure = scenario.measure;
  query.collision_mode = scenario.collision_mode;
  query.time_limit = scenario.time_limit;
  query.termination_checks = car.termination_checks;
  CarResult planned;
  try {
    planned = PlanCar(query);
  } catch (const InputError& error) {
    // "PlanCar(): start: ..." -> "<file>: start: ...".
    std::string what = error.what();
    const std::string prefix = "PlanCar(): ";
    if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
    throw InputError((scenario.path.empty() ? "scenario" : scenario.path) + ": " + what);
  }

  PlanResult result;
  result.solved = planned.solved;
  result.budget = car.termination_checks > 0 ? std::to_string(car.termination_checks) + " checks"
                                             : FormatSignificant(scenario.time_limit, 6) + " s";
  result.time_s = planned.time_s;
  result.decomposition_compute_ms = planned.decomposition_ms;
  result.samples = planned.tree_states;
  result.collision_checks = planned.collision_checks;
  result.path_length = planned.path_duration;
  result.path = std::move(planned.path);
  result.decomposition = std::move(planned.decomposition);
  result.components = planned.regions;
  result.openings = static_cast<int>(result.decomposition.openings.size());
  CarPlan plan;
  plan.planner = car.planner;
  if (IsSyclop(car.planner)) {
    plan.decomposition = car.decomposition;
    if (car.decomposition == DecompositionKind::kGrid) plan.grid_cells = car.grid_cells;
  }
  plan.regions = planned.regions;
  plan.visited_regions = std::move(planned.visited_regions);
  plan.trajectory = std::move(planned.trajectory);
  plan.duration_s = planned.path_duration;
  result.car = std::move(plan);
  return result;
}

std::string CarPlanToSvg(const Scenario& scenario, const PlanResult& result) {
  const CarPlan& plan = *result.car;
  const Eigen::AlignedBox2d& box = scenario.workspace.bounds;
  envs::WorldSvg f(box);
  std::ostringstream svg;
  const char* lead_fill = "fill=\"#f59f00\" fill-opacity=\"0.45\" stroke=\"#e67700\"";
  if (plan.decomposition == DecompositionKind::kAcd) {
    f.AddComponents(result.decomposition, /*distinct=*/false);
    svg << "<g id=\"lead\">\n";
    for (int region : plan.visited_regions) {
      svg << "<path id=\"lead-region-" << region << "\" d=\""
          << f.PathData(result.decomposition.components[region].polygon) << "\" " << lead_fill
          << "/>\n";
    }
    svg << "</g>\n";
  } else if (plan.decomposition == DecompositionKind::kGrid) {
    // The cells the trajectory passes through, located as OMPL's grid does (equal cells over
    // the bounds, the last row and column closed).
    const int n = plan.grid_cells;
    const Eigen::Vector2d cell = box.sizes() / n;
    std::vector<std::pair<int, int>> cells;
    std::set<std::pair<int, int>> seen;
    for (const auto& q : plan.trajectory) {
      const int i = std::clamp(static_cast<int>((q[0] - box.min().x()) / cell.x()), 0, n - 1);
      const int j = std::clamp(static_cast<int>((q[1] - box.min().y()) / cell.y()), 0, n - 1);
      if (seen.insert({i, j}).second) cells.emplace_back(i, j);
    }
    svg << "<g id=\"lead\">\n";
    for (const auto& [i, j] : cells) {
      const Eigen::Vector2d lo = box.min() + Eigen::Vector2d(i * cell.x(), j * cell.y());
      const Eigen::Vector2d hi = lo + cell;
      acd::Polygon2d rect;
      rect.outer = {{lo.x(), lo.y()}, {hi.x(), lo.y()}, {hi.x(), hi.y()}, {lo.x(), hi.y()}};
      svg << "<path id=\"lead-cell-" << i << "-" << j << "\" d=\"" << f.PathData(rect) << "\" "
          << lead_fill << "/>\n";
    }
    svg << "</g>\n<g id=\"grid\" stroke=\"#adb5bd\" stroke-width=\"0.5\">\n";
    for (int k = 0; k <= n; ++k) {
      const double x = box.min().x() + k * cell.x(), y = box.min().y() + k * cell.y();
      svg << "<line x1=\"" << f.X(x) << "\" y1=\"" << f.Y(box.min().y()) << "\" x2=\"" << f.X(x)
          << "\" y2=\"" << f.Y(box.max().y()) << "\"/>\n";
      svg << "<line x1=\"" << f.X(box.min().x()) << "\" y1=\"" << f.Y(y) << "\" x2=\""
          << f.X(box.max().x()) << "\" y2=\"" << f.Y(y) << "\"/>\n";
    }
    svg << "</g>\n";
  }
  f.Add(svg.str());
  f.AddObstacles(scenario.workspace.obstacles);
  if (plan.decomposition == DecompositionKind::kAcd) f.AddOpenings(result.decomposition);

  svg.str("");
  auto body_at = [&](const std::vector<double>& q, const char* colour, double opacity) {
    Eigen::Isometry2d pose = Eigen::Isometry2d::Identity();
    pose.translate(Eigen::Vector2d(q[0], q[1]));
    pose.rotate(q[2]);
    if (scenario.robot.shape == envs::RobotShape::kPolygon) {
      acd::Ring2d ring;
      for (const acd::Point2d& p : scenario.robot.polygon.outer) ring.push_back(pose * p);
      svg << "<path d=\"" << f.PathData(acd::Polygon2d{ring, {}}) << "\" fill=\"" << colour
          << "\" fill-opacity=\"" << opacity << "\" stroke=\"" << colour << "\"/>\n";
    } else if (scenario.robot.shape == envs::RobotShape::kDisc) {
      const Eigen::Vector2d rim = pose * Eigen::Vector2d(scenario.robot.radius, 0.0);
      svg << "<path d=\"M" << f.X(q[0]) << " " << f.Y(q[1]) << " L" << f.X(rim.x()) << " "
          << f.Y(rim.y()) << "\" stroke=\"" << colour << "\"/>\n";
    }
  };
  if (!plan.trajectory.empty()) {
    svg << "<g id=\"trajectory\">\n";
    const size_t every = std::max<size_t>(1, plan.trajectory.size() / 40);
    for (size_t k = 0; k < plan.trajectory.size(); k += every) {
      body_at(plan.trajectory[k], "#c92a2a", 0.15);
    }
    svg << "<polyline fill=\"none\" stroke=\"" << (result.solved ? "#e03131" : "#868e96")
        << "\" stroke-width=\"2.5\" points=\"";
    for (const auto& q : plan.trajectory) svg << f.X(q[0]) << "," << f.Y(q[1]) << " ";
    svg << "\"/>\n</g>\n";
  }
  body_at(scenario.start, "#2b8a3e", 0.5);
  body_at(scenario.goal, "#862e9c", 0.5);
  const double radius_px = std::abs(std::stod(f.X(box.min().x() + scenario.car->goal_radius)) -
                                    std::stod(f.X(box.min().x())));
  svg << "<circle id=\"goal-radius\" cx=\"" << f.X(scenario.goal[0]) << "\" cy=\""
      << f.Y(scenario.goal[1]) << "\" r=\"" << radius_px
      << "\" fill=\"none\" stroke=\"#862e9c\" stroke-dasharray=\"4 3\"/>\n";
  svg << "<circle id=\"start\" cx=\"" << f.X(scenario.start[0]) << "\" cy=\""
      << f.Y(scenario.start[1]) << "\" r=\"6\" fill=\"#2b8a3e\"/>\n";
  svg << "<circle id=\"goal\" cx=\"" << f.X(scenario.goal[0]) << "\" cy=\"" << f.Y(scenario.goal[1])
      << "\" r=\"6\" fill=\"#862e9c\"/>\n";
  f.Add(svg.str());
  const std::string regions =
      !plan.decomposition ? "no decomposition"
      : *plan.decomposition == DecompositionKind::kAcd
          ? std::to_string(plan.regions) + " ACD regions"
          : std::to_string(plan.grid_cells) + " x " + std::to_string(plan.grid_cells) + " grid";
  return f.Finish(
      ToString(scenario.car->model) + ", " + ToString(plan.planner) + " (" + regions + ", " +
      std::to_string(plan.visited_regions.size()) + " passed through, shaded), " + result.budget +
      ": " + (result.solved ? "solved" : "not solved") + " (" + std::to_string(result.samples) +
      " tree states, duration " + FormatSignificant(plan.duration_s, 4) + " s)");
}

}  // namespace acdplan::planning::control
