#include "planning/scenario_moving_ai.h"

#include <filesystem>
#include <sstream>
#include <tuple>

#include "acd/internal/text_parsing.h"
#include "base/input_error.h"
#include "envs/moving_ai_map.h"
#include "envs/moving_ai_scenario.h"
#include "envs/occupancy_grid.h"

namespace acdplan::planning {

bool IsMovingAiScenarioFile(const std::string& path) {
  return acd::internal::ToLower(std::filesystem::path(path).extension().string()) == ".scen";
}

Scenario ScenarioFromMovingAi(const std::string& path, int problem) {
  const std::vector<envs::MovingAiProblem> problems = envs::ReadMovingAiScenario(path);
  const int count = static_cast<int>(problems.size());
  if (problem < 0 || problem >= count) {
    throw InputError(path + ": problem " + std::to_string(problem) + " out of range 0.." +
                     std::to_string(count - 1) + " (the file holds " + std::to_string(count) +
                     " problem(s))");
  }
  const envs::MovingAiProblem& p = problems[static_cast<size_t>(problem)];
  const std::string where = path + ":" + std::to_string(p.line) + ": ";
  const envs::OccupancyGrid grid = envs::ReadMovingAiMap(p.map_path);
  if (grid.width != p.map_width || grid.height != p.map_height) {
    throw InputError(where + "the map " + p.map_path + " has " + std::to_string(grid.width) +
                     " x " + std::to_string(grid.height) + " cells, the problem says " +
                     std::to_string(p.map_width) + " x " + std::to_string(p.map_height));
  }
  Scenario s;
  s.path = path;
  for (const auto& [cell, name, q] :
       {std::tuple{p.start, "start", &s.start}, std::tuple{p.goal, "goal", &s.goal}}) {
    if (grid.Blocked(cell.y(), cell.x())) {
      throw InputError(where + "the " + name + " cell (" + std::to_string(cell.x()) + ", " +
                       std::to_string(cell.y()) + ") is blocked in " + p.map_path);
    }
    const Eigen::Vector2d centre = envs::MovingAiCellCentre(cell, grid.height);
    *q = {centre.x(), centre.y()};
  }
  std::ostringstream description;
  description << "Moving AI problem " << problem << " of " << path << " (bucket " << p.bucket
              << ", optimal length on the grid " << p.optimal_length << ")";
  s.description = description.str();
  s.workspace = envs::GridWorkspace(grid);
  s.workspace.description = "Moving AI map " + p.map_path;
  s.workspace_label = p.map_path;
  CheckScenario(s);
  return s;
}

}  // namespace acdplan::planning
