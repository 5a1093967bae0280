#include "planning/scenario.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <sstream>

#include "acd/input_error.h"
#include "envs/generators.h"
#include "envs/load_workspace.h"
#include "planning/registry.h"

namespace acdplan::planning {

namespace {

/// Errors "<file>: <key>: <rule>".
struct Reader {
  std::string file;

  [[noreturn]] void Fail(const std::string& key, const std::string& rule) const {
    throw acd::InputError(file + ": " + key + ": " + rule);
  }

  static std::string Shown(const YAML::Node& node) {
    if (node.IsScalar()) return "'" + node.Scalar() + "'";
    if (node.IsSequence()) return "a list";
    if (node.IsMap()) return "a mapping";
    return "nothing";
  }

  void CheckKeys(const YAML::Node& node, const std::string& key,
                 std::initializer_list<const char*> allowed) const {
    if (!node.IsMap()) Fail(key.empty() ? "(root)" : key, "expected a mapping, got " + Shown(node));
    for (const auto& entry : node) {
      const std::string name = entry.first.as<std::string>();
      if (std::none_of(allowed.begin(), allowed.end(),
                       [&](const char* a) { return name == a; })) {
        std::string known;
        for (const char* a : allowed) known += (known.empty() ? "" : ", ") + std::string(a);
        Fail(Child(key, name), "unknown key (known: " + known + ")");
      }
    }
  }

  double Number(const YAML::Node& node, const std::string& key, const std::string& rule,
                bool (*accept)(double)) const {
    double value = 0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) ||
        !std::isfinite(value) || !accept(value)) {
      Fail(key, "expected " + rule + ", got " + Shown(node));
    }
    return value;
  }

  long long Integer(const YAML::Node& node, const std::string& key, const std::string& rule,
                    long long min) const {
    long long value = 0;
    if (!node.IsScalar() || !YAML::convert<long long>::decode(node, value) || value < min) {
      Fail(key, "expected " + rule + ", got " + Shown(node));
    }
    return value;
  }

  std::string String(const YAML::Node& node, const std::string& key) const {
    if (!node.IsScalar()) Fail(key, "expected a string, got " + Shown(node));
    return node.Scalar();
  }

  std::vector<double> Numbers(const YAML::Node& node, const std::string& key,
                              const std::string& what) const {
    if (!node.IsSequence()) Fail(key, "expected " + what + ", got " + Shown(node));
    std::vector<double> values;
    for (size_t i = 0; i < node.size(); ++i) {
      values.push_back(Number(node[i], Item(key, i), "a number", [](double x) { return x == x; }));
    }
    return values;
  }

  static std::string Child(const std::string& key, const std::string& child) {
    return key.empty() ? child : key + "." + child;
  }
  static std::string Item(const std::string& key, size_t i) {
    return key + "[" + std::to_string(i) + "]";
  }
};

bool Positive(double x) { return x > 0; }
bool NonNegative(double x) { return x >= 0; }
bool UnitInterval(double x) { return x >= 0 && x <= 1; }

envs::Workspace2d Generate(const Reader& r, const YAML::Node& node, std::string* label) {
  r.CheckKeys(node, "workspace", {"generator", "seed", "passage_width", "wall_thickness"});
  if (!node["generator"]) r.Fail("workspace.generator", "required (or give a file name)");
  const std::string name = r.String(node["generator"], "workspace.generator");
  const std::uint64_t seed =
      node["seed"] ? r.Integer(node["seed"], "workspace.seed", "an integer >= 0", 0) : 1;
  const double width = node["passage_width"]
                           ? r.Number(node["passage_width"], "workspace.passage_width",
                                      "a positive number", Positive)
                           : 0.0;
  *label = "generator " + name + " (seed " + std::to_string(seed) + ")";
  if (!node["wall_thickness"]) {
    try {
      return envs::GenerateWorkspace2d(name, seed, width);
    } catch (const acd::InputError& error) {
      r.Fail("workspace", error.what());
    }
  }
  const double wall = r.Number(node["wall_thickness"], "workspace.wall_thickness",
                               "a positive number", Positive);
  try {
    if (name == "wall_gap") {
      envs::WallGapOptions o;
      o.wall_thickness = wall;
      if (width > 0) o.passage_width = width;
      return envs::MakeWallWithGap(seed, o);
    }
    if (name == "bug_trap") {
      envs::BugTrapOptions o;
      o.wall_thickness = wall;
      if (width > 0) o.passage_width = width;
      return envs::MakeBugTrap(seed, o);
    }
    if (name == "two_rooms") {
      envs::TwoRoomsOptions o;
      o.wall_thickness = wall;
      if (width > 0) o.passage_width = width;
      return envs::MakeTwoRooms(seed, o);
    }
    if (name == "spiral") {
      envs::SpiralOptions o;
      o.wall_thickness = wall;
      if (width > 0) o.passage_width = width;
      return envs::MakeSpiral(seed, o);
    }
    if (name == "maze") {
      envs::MazeOptions o;
      o.wall_thickness = wall;
      if (width > 0) o.passage_width = width;
      return envs::MakeMaze(seed, o);
    }
  } catch (const acd::InputError& error) {
    r.Fail("workspace", error.what());
  }
  r.Fail("workspace.wall_thickness", "not an option of generator '" + name + "'");
}

envs::Robot ReadRobot(const Reader& r, const YAML::Node& node) {
  r.CheckKeys(node, "robot", {"shape", "radius", "polygon"});
  const std::string shape = node["shape"] ? r.String(node["shape"], "robot.shape") : "point";
  try {
    if (shape == "point") {
      if (node["radius"]) r.Fail("robot.radius", "only for shape disc");
      if (node["polygon"]) r.Fail("robot.polygon", "only for shape polygon");
      return envs::Robot::Point();
    }
    if (shape == "disc") {
      if (!node["radius"]) r.Fail("robot.radius", "required for shape disc");
      if (node["polygon"]) r.Fail("robot.polygon", "only for shape polygon");
      return envs::Robot::Disc(
          r.Number(node["radius"], "robot.radius", "a positive number", Positive));
    }
    if (shape == "polygon") {
      if (!node["polygon"]) r.Fail("robot.polygon", "required for shape polygon");
      if (node["radius"]) r.Fail("robot.radius", "only for shape disc");
      const YAML::Node& list = node["polygon"];
      if (!list.IsSequence() || list.size() < 3) {
        r.Fail("robot.polygon", "expected a list of at least 3 [x, y] pairs");
      }
      acd::Polygon2d outline;
      for (size_t i = 0; i < list.size(); ++i) {
        const std::vector<double> xy =
            r.Numbers(list[i], Reader::Item("robot.polygon", i), "an [x, y] pair");
        if (xy.size() != 2) r.Fail(Reader::Item("robot.polygon", i), "expected an [x, y] pair");
        outline.outer.emplace_back(xy[0], xy[1]);
      }
      if (acd::SignedArea(outline.outer) < 0) outline.outer = acd::Reversed(outline.outer);
      return envs::Robot::Polygon(outline);
    }
  } catch (const acd::InputError& error) {
    const std::string what = error.what();
    if (what.rfind(r.file + ": ", 0) == 0) throw;
    r.Fail("robot", what);
  }
  r.Fail("robot.shape", "expected point, disc or polygon, got '" + shape + "'");
}

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
           "a sample budget (the Figure-4 protocol) needs PRM or PRMstar, not " + s.planner +
               "; use time_limit");
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
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw acd::InputError(path + ": cannot read the file");
  } catch (const YAML::ParserException& error) {
    std::ostringstream out;
    out << path << ":" << error.mark.line + 1 << ": YAML syntax error: " << error.msg;
    throw acd::InputError(out.str());
  }
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
    s.workspace = Generate(r, workspace, &s.workspace_label);
  } else {
    r.Fail("workspace", "expected a file name or {generator: ...}, got " + Reader::Shown(workspace));
  }

  s.robot = root["robot"] ? ReadRobot(r, root["robot"]) : envs::Robot::Point();
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
    AcdSamplerOptions& o = s.sampler_options;
    if (sampler["name"]) s.sampler = r.String(sampler["name"], "sampler.name");
    if (sampler["uniform_share"]) {
      o.uniform_share = r.Number(sampler["uniform_share"], "sampler.uniform_share",
                                 "a number in [0, 1]", UnitInterval);
    }
    if (sampler["orientation"]) {
      try {
        o.orientation =
            ParseAcdOrientation(r.String(sampler["orientation"], "sampler.orientation"));
      } catch (const acd::InputError& error) {
        r.Fail("sampler.orientation", error.what());
      }
    }
    if (sampler["opening_weight"]) {
      o.opening_weight = r.Number(sampler["opening_weight"], "sampler.opening_weight",
                                  "a number >= 0", NonNegative);
    }
    if (sampler["centroid_spread"]) {
      o.centroid_spread = r.Number(sampler["centroid_spread"], "sampler.centroid_spread",
                                   "a positive number", Positive);
    }
    if (sampler["opening_spread"]) {
      o.opening_spread = r.Number(sampler["opening_spread"], "sampler.opening_spread",
                                  "a positive number", Positive);
    }
    if (sampler["max_attempts"]) {
      o.max_attempts = static_cast<int>(
          r.Integer(sampler["max_attempts"], "sampler.max_attempts", "an integer >= 1", 1));
    }
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
