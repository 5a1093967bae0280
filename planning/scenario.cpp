#include "planning/scenario.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <sstream>

#include "acd/input_error.h"
#include "envs/generators.h"
#include "envs/load_workspace.h"
#include "planning/internal/yaml_reader.h"
#include "planning/registry.h"

namespace acdplan::planning {

namespace {

using Reader = internal::YamlReader;
using internal::NonNegative;
using internal::Positive;
using internal::UnitInterval;

}  // namespace

void CheckScenario(const Scenario& s) {
  const Reader r{s.path.empty() ? "scenario" : s.path};
  const std::vector<std::string> planners = PlannerNames();
  if (std::find(planners.begin(), planners.end(), s.planner) == planners.end()) {
    std::string known;
    for (const std::string& n : planners) known += (known.empty() ? "" : ", ") + n;
    r.Fail("planner.name", "unknown planner '" + s.planner + "' (known: " + known + ")");
  }
  const std::vector<std::string> samplers = SamplerNames();
  if (std::find(samplers.begin(), samplers.end(), s.sampler) == samplers.end()) {
    std::string known;
    for (const std::string& n : samplers) known += (known.empty() ? "" : ", ") + n;
    r.Fail("sampler.name", "unknown sampler '" + s.sampler + "' (known: " + known + ")");
  }
  if (s.samples > 0 && !SupportsSampleBudget(s.planner)) {
    r.Fail("planner.samples",
           "a sample budget (the Figure-4 protocol) needs PRM, PRM_ACD or PRMstar, not " +
               s.planner + "; use time_limit");
  }
  if (s.samples <= 0 && !(s.time_limit > 0)) {
    r.Fail("planner.time_limit", "expected a positive number");
  }
  const size_t dims = s.robot.shape == envs::RobotShape::kPolygon ? 3 : 2;
  const std::string form = dims == 3 ? "[x, y, yaw] (a polygon robot plans in SE(2))" : "[x, y]";
  if (s.start.size() != dims) r.Fail("start", "expected " + form);
  if (s.goal.size() != dims) r.Fail("goal", "expected " + form);
  try {
    CheckAcdSamplerOptions(s.sampler_options);
  } catch (const acd::InputError& error) {
    r.Fail("sampler", error.what());
  }
}

Scenario LoadScenario(const std::string& path) {
  const Reader r{path};
  const YAML::Node root = internal::LoadYamlFile(path);
  r.CheckKeys(root, "", {"description", "workspace", "robot", "start", "goal", "acd", "planner",
                         "sampler", "collision", "seed"});
  Scenario s;
  s.path = path;
  if (root["description"]) s.description = r.String(root["description"], "description");
  if (root["seed"]) s.seed = r.Integer(root["seed"], "seed", "an integer >= 0", 0);

  if (!root["workspace"]) r.Fail("workspace", "required");
  const YAML::Node& workspace = root["workspace"];
  if (workspace.IsScalar()) {
    const std::filesystem::path file(workspace.Scalar());
    const std::string resolved =
        file.is_absolute() ? file.string()
                           : (std::filesystem::path(path).parent_path() / file).string();
    s.workspace_label = resolved;
    s.workspace = envs::LoadWorkspace2d(resolved);
  } else if (workspace.IsMap()) {
    s.workspace = internal::ReadGeneratedWorkspace(r, workspace, "workspace", &s.workspace_label);
  } else {
    r.Fail("workspace", "expected a file name or {generator: ...}, got " + Reader::Shown(workspace));
  }

  s.robot = root["robot"] ? internal::ReadRobot(r, root["robot"], "robot") : envs::Robot::Point();
  if (!root["start"]) r.Fail("start", "required");
  if (!root["goal"]) r.Fail("goal", "required");
  s.start = r.Numbers(root["start"], "start", "[x, y] or [x, y, yaw]");
  s.goal = r.Numbers(root["goal"], "goal", "[x, y] or [x, y, yaw]");

  if (const YAML::Node& acd = root["acd"]) {
    r.CheckKeys(acd, "acd", {"tau_rel", "measure"});
    if (acd["tau_rel"]) {
      s.tau_rel = r.Number(acd["tau_rel"], "acd.tau_rel", "a number >= 0", NonNegative);
    }
    if (acd["measure"]) {
      const std::string name = r.String(acd["measure"], "acd.measure");
      try {
        s.measure = acd::ParseConcavityMeasure(name);
      } catch (const acd::InputError& error) {
        r.Fail("acd.measure", error.what());
      }
    }
  }
  if (const YAML::Node& planner = root["planner"]) {
    r.CheckKeys(planner, "planner", {"name", "time_limit", "samples"});
    if (planner["name"]) s.planner = r.String(planner["name"], "planner.name");
    if (planner["time_limit"] && planner["samples"]) {
      r.Fail("planner", "give time_limit or samples, not both");
    }
    if (planner["time_limit"]) {
      s.time_limit =
          r.Number(planner["time_limit"], "planner.time_limit", "a positive number", Positive);
    }
    if (planner["samples"]) {
      s.samples = static_cast<int>(
          r.Integer(planner["samples"], "planner.samples", "an integer >= 1", 1));
    }
  }
  if (const YAML::Node& sampler = root["sampler"]) {
    r.CheckKeys(sampler, "sampler",
                {"name", "uniform_share", "orientation", "opening_weight", "centroid_spread",
                 "opening_spread", "max_attempts"});
    if (sampler["name"]) s.sampler = r.String(sampler["name"], "sampler.name");
    internal::ReadAcdSamplerOptions(r, sampler, "sampler", &s.sampler_options);
  }
  if (const YAML::Node& collision = root["collision"]) {
    r.CheckKeys(collision, "collision", {"mode"});
    if (collision["mode"]) {
      s.collision_mode = r.String(collision["mode"], "collision.mode");
      if (s.collision_mode != "bvh" && s.collision_mode != "hulls" &&
          s.collision_mode != "hulls+exact") {
        r.Fail("collision.mode", "expected bvh, hulls or hulls+exact, got '" +
                                     s.collision_mode + "'");
      }
    }
  }
  CheckScenario(s);
  return s;
}

}  // namespace acdplan::planning
