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

Scenario LoadScenario(const std::string& path) {
  const YamlFile file = YamlFile::Load(path);
  const YAML::Node& root = file.root();
  file.CheckKeys(root, "",
                 {"description", "workspace", "repair", "robot", "start", "goal", "acd", "planner",
                  "sampler", "collision", "seed"});
  Scenario s;
  s.path = path;
  if (root["description"]) s.description = file.String(root["description"], "description");
  if (root["seed"]) s.seed = file.Integer(root["seed"], "seed", "an integer >= 0", 0);

  if (!root["workspace"]) file.Fail("workspace", "required");
  if (root["repair"] && !root["workspace"].IsScalar()) {
    file.Fail("repair", "only for a workspace file (generated worlds are always valid)");
  }
  const YAML::Node& workspace = root["workspace"];
  if (workspace.IsScalar()) {
    s.workspace_label = file.ResolvePath(workspace.Scalar());
    acd::ReadPolygonsOptions polygons;
    polygons.repair = root["repair"] && file.Bool(root["repair"], "repair");
    polygons.notes = &s.warnings;
    envs::World world = envs::LoadWorld(s.workspace_label, polygons);
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

  s.robot = root["robot"] ? ReadRobot(file, root["robot"], "robot") : envs::Robot::Point();
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
    if (planner["name"]) s.planner = file.Parsed(planner["name"], "planner.name", ParsePlannerType);
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
