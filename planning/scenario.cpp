#include "planning/scenario.h"

#include <string>

#include "base/input_error.h"
#include "base/yaml_file.h"
#include "envs/load_workspace.h"
#include "planning/scenario_yaml.h"

namespace acdplan::planning {

void CheckScenario(const Scenario& s) {
  const std::string file = s.path.empty() ? "scenario" : s.path;
  auto fail = [&file](const std::string& key, const std::string& rule) {
    throw InputError(file + ": " + key + ": " + rule);
  };
  if (s.car) {
    if (s.dimension != 2) fail("robot.type", "a car needs a 2D world");
    if (s.samples > 0) {
      fail("planner.samples", "a car's control planner takes a time_limit, not a sample budget");
    }
    if (!(s.time_limit > 0)) fail("planner.time_limit", "expected a positive number");
    if (!(s.tau_diag >= 0)) fail("acd.tau_diag", "expected a number >= 0");
    if (s.car->grid_cells < 1) fail("decomposition.cells", "expected an integer >= 1");
    if (!(s.car->goal_radius > 0)) fail("goal_radius", "expected a positive number");
    if (s.robot.shape == envs::RobotShape::kMesh) {
      fail("robot.shape", "a car's body is 2D: point, disc or polygon");
    }
    try {
      control::CheckCarOptions(s.car->options);
    } catch (const InputError& error) {
      fail("robot", error.what());
    }
    const std::string form = "[x, y, yaw] (a car plans in SE(2), yaw in rad)";
    if (s.start.size() != 3) fail("start", "expected " + form);
    if (s.goal.size() != 3) fail("goal", "expected " + form);
    return;
  }
  if (s.samples > 0 && !HonoursSampleBudget(s.planner)) {
    fail("planner.samples",
         "a sample budget (the Figure-4 protocol) needs PRM, PRM_ACD or PRMstar, not " +
             ToString(s.planner) + "; use time_limit");
  }
  if (s.samples <= 0 && !(s.time_limit > 0))
    fail("planner.time_limit", "expected a positive number");
  if (!(s.tau_diag >= 0)) fail("acd.tau_diag", "expected a number >= 0");
  const bool mesh = s.robot.shape == envs::RobotShape::kMesh;
  if (s.dimension == 3 && !mesh && s.robot.shape != envs::RobotShape::kPoint) {
    fail("robot.shape",
         "a 3D world needs a point or a mesh robot, not a " + envs::ToString(s.robot.shape));
  }
  if (s.dimension == 2 && mesh) fail("robot.shape", "a mesh robot needs a 3D world");
  size_t dims = s.robot.shape == envs::RobotShape::kPolygon ? 3 : 2;
  std::string form = dims == 3 ? "[x, y, yaw] (a polygon robot plans in SE(2))" : "[x, y]";
  if (s.dimension == 3) {
    dims = mesh ? 6 : 3;
    form = mesh ? "[x, y, z, roll, pitch, yaw] (a mesh robot plans in SE(3))"
                : "[x, y, z] (a point in a 3D world)";
  }
  if (s.start.size() != dims) fail("start", "expected " + form);
  if (s.goal.size() != dims) fail("goal", "expected " + form);
  try {
    CheckAcdSamplerOptions(s.sampler_options);
  } catch (const InputError& error) {
    fail("sampler", error.what());
  }
}

namespace {

/// planner.name: a control planner for a car, a geometric one otherwise; the message says
/// which kind the name is when it is the wrong one.
void ReadPlannerName(const YamlFile& file, const YAML::Node& node, Scenario* s) {
  const std::string name = file.String(node, "planner.name");
  auto is_control = [&name] {
    try {
      control::ParseControlPlanner(name);
      return true;
    } catch (const InputError&) {
      return false;
    }
  };
  auto is_geometric = [&name] {
    try {
      ParsePlannerType(name);
      return true;
    } catch (const InputError&) {
      return false;
    }
  };
  if (s->car) {
    if (!is_control() && is_geometric()) {
      file.Fail("planner.name",
                name + " is a geometric planner; a car (robot.type " +
                    control::ToString(s->car->model) +
                    ") needs a control planner: " + JoinNames(control::ControlPlannerNames()));
    }
    s->car->planner = file.Parsed(node, "planner.name", control::ParseControlPlanner);
  } else {
    if (!is_geometric() && is_control()) {
      file.Fail("planner.name", name +
                                    " is a control planner: it needs a car robot (robot.type: "
                                    "kinematic_car | dynamic_car)");
    }
    s->planner = file.Parsed(node, "planner.name", ParsePlannerType);
  }
}

}  // namespace

Scenario LoadScenario(const std::string& path) {
  const YamlFile file = YamlFile::Load(path);
  const YAML::Node& root = file.root();
  file.CheckKeys(root, "",
                 {"description", "workspace", "repair", "unknown", "robot", "start", "goal", "acd",
                  "planner", "sampler", "collision", "seed", "decomposition", "goal_radius"});
  Scenario s;
  s.path = path;
  if (root["description"]) s.description = file.String(root["description"], "description");
  if (root["seed"]) s.seed = file.Integer(root["seed"], "seed", "an integer >= 0", 0);

  if (!root["workspace"]) file.Fail("workspace", "required");
  if (root["repair"] && !root["workspace"].IsScalar()) {
    file.Fail("repair", "only for a workspace file (generated worlds are always valid)");
  }
  if (root["unknown"] && !root["workspace"].IsScalar()) {
    file.Fail("unknown", "only for an occupancy map world (this one is generated)");
  }
  const YAML::Node& workspace = root["workspace"];
  if (workspace.IsScalar()) {
    s.workspace_label = file.ResolvePath(workspace.Scalar());
    acd::ReadPolygonsOptions polygons;
    polygons.repair = root["repair"] && file.Bool(root["repair"], "repair");
    polygons.notes = &s.warnings;
    envs::OccupancyMapOptions map;
    map.notes = &s.warnings;
    if (root["unknown"])
      map.unknown = file.Parsed(root["unknown"], "unknown", envs::ParseUnknownCells);
    envs::World world = envs::LoadWorld(s.workspace_label, polygons, map);
    if (root["unknown"] && world.kind != "occupancy map") {
      file.Fail("unknown", "only for an occupancy map world (" + s.workspace_label + " is a " +
                               world.kind + ")");
    }
    s.dimension = world.dimension;
    s.workspace = std::move(world.workspace2d);
    s.workspace3d = std::move(world.workspace3d);
  } else if (NamesGenerator3d(workspace)) {
    s.dimension = 3;
    s.workspace3d = ReadGeneratedWorkspace3d(file, workspace, "workspace", &s.workspace_label);
  } else if (workspace.IsMap()) {
    s.workspace = ReadGeneratedWorkspace(file, workspace, "workspace", &s.workspace_label);
  } else {
    file.Fail("workspace",
              "expected a file name or {generator: ...}, got " + YamlFile::Shown(workspace));
  }

  if (root["robot"] && NamesCarRobot(root["robot"])) {
    CarRobot car = ReadCarRobot(file, root["robot"], "robot");
    s.robot = car.body;
    s.car.emplace();
    s.car->model = car.model;
    s.car->options = car.options;
    if (s.dimension != 2) file.Fail("robot.type", "a car needs a 2D world");
  } else {
    s.robot = root["robot"] ? ReadRobot(file, root["robot"], "robot") : envs::Robot::Point();
  }
  for (const char* key : {"decomposition", "goal_radius"}) {
    if (root[key] && !s.car) {
      file.Fail(key, "only for a car (robot.type: kinematic_car | dynamic_car)");
    }
  }
  if (s.car && root["sampler"]) {
    file.Fail("sampler",
              "a car is planned by a control planner, which takes no sampler (Syclop's guide "
              "is `decomposition`)");
  }
  if (s.car && root["goal_radius"]) {
    s.car->goal_radius =
        file.Number(root["goal_radius"], "goal_radius", "a positive number", Positive);
  }
  if (!root["start"]) file.Fail("start", "required");
  if (!root["goal"]) file.Fail("goal", "required");
  s.start = file.Numbers(root["start"], "start", "[x, y], [x, y, yaw] or [x, y, z, ...]");
  s.goal = file.Numbers(root["goal"], "goal", "[x, y], [x, y, yaw] or [x, y, z, ...]");

  if (const YAML::Node& acd = root["acd"]) {
    file.CheckKeys(acd, "acd", {"tau_diag", "tau_rel", "measure"});
    s.tau_diag = ReadTauDiag(file, acd, "acd", s.tau_diag, &s.warnings);
    if (acd["measure"]) {
      s.measure = file.Parsed(acd["measure"], "acd.measure", acd::ParseConcavityMeasure);
    }
  }
  if (const YAML::Node& planner = root["planner"]) {
    file.CheckKeys(planner, "planner", {"name", "time_limit", "samples"});
    if (planner["name"]) ReadPlannerName(file, planner["name"], &s);
    if (planner["time_limit"] && planner["samples"]) {
      file.Fail("planner", "give time_limit or samples, not both");
    }
    if (planner["time_limit"]) {
      s.time_limit =
          file.Number(planner["time_limit"], "planner.time_limit", "a positive number", Positive);
    }
    if (planner["samples"]) {
      s.samples = static_cast<int>(
          file.Integer(planner["samples"], "planner.samples", "an integer >= 1", 1));
    }
  }
  if (const YAML::Node& decomposition = root["decomposition"]) {
    file.CheckKeys(decomposition, "decomposition", {"name", "cells"});
    if (decomposition["name"]) {
      s.car->decomposition =
          file.Parsed(decomposition["name"], "decomposition.name", control::ParseDecompositionKind);
    }
    if (decomposition["cells"]) {
      if (s.car->decomposition != control::DecompositionKind::kGrid) {
        file.Fail("decomposition.cells", "only for name: grid (the ACD's regions are its own)");
      }
      const long long cells = file.Integer(decomposition["cells"], "decomposition.cells",
                                           "an integer >= 1 (cells per side)", 1);
      // OMPL's grid allocates its cells: a bound keeps a typo from exhausting memory.
      if (cells > 1000) file.Fail("decomposition.cells", "expected at most 1000 cells per side");
      s.car->grid_cells = static_cast<int>(cells);
    }
    if (s.car->planner != control::ControlPlanner::kSyclopRrt &&
        s.car->planner != control::ControlPlanner::kSyclopEst) {
      s.warnings.push_back(file.path() + ": decomposition: unused by " +
                           control::ToString(s.car->planner) +
                           " (only SyclopRRT and SyclopEST follow a decomposition)");
    }
  }
  if (const YAML::Node& sampler = root["sampler"]) {
    file.CheckKeys(sampler, "sampler",
                   {"name", "lead", "uniform_share", "orientation", "opening_weight",
                    "centroid_spread", "opening_spread", "max_attempts", "aligned_jitter"});
    if (sampler["name"]) s.sampler = file.Parsed(sampler["name"], "sampler.name", ParseSamplerType);
    if (sampler["lead"] && file.Bool(sampler["lead"], "sampler.lead")) {
      if (s.sampler != SamplerType::kAcd && s.sampler != SamplerType::kAcdLead) {
        file.Fail("sampler.lead", "only for the acd sampler (the lead is its decomposition)");
      }
      s.sampler = SamplerType::kAcdLead;
    }
    ReadAcdSamplerOptions(file, sampler, "sampler", &s.sampler_options);
  }
  // A rigid body in 3D passes an opening lengthwise: aligned unless the file says otherwise.
  if (s.dimension == 3 && s.robot.shape == envs::RobotShape::kMesh &&
      !(root["sampler"] && root["sampler"]["orientation"])) {
    s.sampler_options.orientation = AcdOrientation::kAligned;
  }
  if (const YAML::Node& collision = root["collision"]) {
    file.CheckKeys(collision, "collision", {"mode"});
    if (collision["mode"]) {
      s.collision_mode =
          file.Parsed(collision["mode"], "collision.mode", collision::ParseCollisionMode);
    }
  }
  CheckScenario(s);
  return s;
}

}  // namespace acdplan::planning
