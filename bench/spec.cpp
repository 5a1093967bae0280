#include "bench/spec.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "base/format.h"
#include "base/input_error.h"
#include "base/random.h"
#include "base/yaml_file.h"
#include "bench/summary.h"
#include "envs/load_workspace.h"
#include "planning/registry.h"
#include "planning/scenario_cfg.h"
#include "planning/scenario_moving_ai.h"
#include "planning/scenario_yaml.h"

namespace acdplan::bench {

namespace {

using planning::AcdSamplerOptions;
using planning::PlannerType;
using planning::SamplerType;
using planning::Scenario;

bool SafeName(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
}

/// A length as names and labels show it ("0.05", "1e-05").
std::string Shortest(double x) { return FormatSignificant(x, 6); }

/// Reads `acd: {tau_diag (or tau_rel), measure}` into `scenario`.
void ReadAcd(const YamlFile& file, const YAML::Node& node, const std::string& key, Scenario* s) {
  file.CheckKeys(node, key, {"tau_diag", "tau_rel", "measure"});
  s->tau_diag = planning::ReadTauDiag(file, node, key, s->tau_diag, &s->warnings);
  if (node["measure"]) {
    s->measure =
        file.Parsed(node["measure"], YamlFile::Child(key, "measure"), acd::ParseConcavityMeasure);
  }
}

/// Reads `acd_sampler: {...}` (also a robot's `orientation`).
void ReadSamplerOptions(const YamlFile& file, const YAML::Node& node, const std::string& key,
                        AcdSamplerOptions* o) {
  file.CheckKeys(node, key,
                 {"uniform_share", "opening_weight", "centroid_spread", "opening_spread",
                  "max_attempts", "orientation"});
  planning::ReadAcdSamplerOptions(file, node, key, o);
}

/// Reads worlds[i] (one world, or several for a `passage_widths` or `problems` sweep).
void ReadWorld(const YamlFile& file, const YAML::Node& node, const std::string& key,
               const Scenario& defaults, std::vector<BenchWorld>* worlds) {
  file.CheckKeys(node, key,
                 {"name", "scenario", "problem", "problems", "workspace", "start", "goal", "acd",
                  "collision", "passage_width", "passage_widths"});
  auto child = [&](const char* name) { return YamlFile::Child(key, name); };
  if (const YAML::Node& problems = node["problems"]) {
    // A sweep over problems of a Moving AI .scen file: one world each, of one family.
    if (node["problem"]) file.Fail(child("problems"), "give problems or problem, not both");
    if (!problems.IsSequence() || problems.size() == 0) {
      file.Fail(child("problems"),
                "expected a non-empty list of problem numbers, got " + YamlFile::Shown(problems));
    }
    for (size_t i = 0; i < problems.size(); ++i) {
      const long long problem =
          file.Integer(problems[i], YamlFile::Item(child("problems"), i), "an integer >= 0", 0);
      YAML::Node one = YAML::Clone(node);
      one.remove("problems");
      one["problem"] = problem;
      ReadWorld(file, one, key, defaults, worlds);
      BenchWorld& world = worlds->back();  // Named <stem>_<problem>, or <name>.
      if (node["name"]) {
        world.family = world.name;
        world.name += "_" + std::to_string(problem);
      } else {
        world.family = world.name.substr(0, world.name.rfind('_'));
      }
    }
    return;
  }
  BenchWorld world;
  world.scenario = defaults;
  YAML::Node workspace_node;
  if (node["scenario"]) {
    for (const char* k : {"workspace", "start", "goal"}) {
      if (node[k]) file.Fail(child(k), "give either scenario or workspace, start and goal");
    }
    const std::string path = file.ResolvePath(file.String(node["scenario"], child("scenario")));
    // A Moving AI .scen file holds many problems: `problem` chooses one.
    const int problem = node["problem"]
                            ? static_cast<int>(file.Integer(node["problem"], child("problem"),
                                                            "an integer >= 0", 0))
                            : -1;
    try {
      world.scenario = planning::LoadScenarioFile(path, problem);
    } catch (const InputError& error) {
      file.Fail(child("scenario"), error.what());
    }
    world.name = std::filesystem::path(path).stem().string() +
                 (problem >= 0 ? "_" + std::to_string(problem) : "");
    // The generator's passage width, for the plots (the scenario keeps only the workspace).
    const bool yaml =
        !planning::IsOmplAppProblemFile(path) && !planning::IsMovingAiScenarioFile(path);
    const YAML::Node generated = yaml ? YamlFile::Load(path).root()["workspace"] : YAML::Node();
    if (generated.IsMap() && generated["passage_width"]) {
      double width = 0;
      if (YAML::convert<double>::decode(generated["passage_width"], width)) {
        world.passage_width = width;
      }
    }
  } else {
    if (node["problem"])
      file.Fail(child("problem"), "only with a scenario (a Moving AI .scen file)");
    for (const char* k : {"workspace", "start", "goal"}) {
      if (!node[k]) file.Fail(child(k), "required (or give a scenario file)");
    }
    workspace_node = node["workspace"];
    if (workspace_node.IsScalar()) {
      const std::string path = file.ResolvePath(workspace_node.Scalar());
      world.scenario.workspace_label = path;
      try {
        acd::ReadPolygonsOptions polygons;
        polygons.notes = &world.scenario.warnings;
        envs::OccupancyMapOptions map;
        map.notes = &world.scenario.warnings;
        world.scenario.workspace = envs::LoadWorkspace2d(path, polygons, map);
      } catch (const InputError& error) {
        file.Fail(child("workspace"), error.what());
      }
    } else if (workspace_node.IsMap()) {
      if (!node["passage_widths"]) {
        world.scenario.workspace = planning::ReadGeneratedWorkspace(
            file, workspace_node, child("workspace"), &world.scenario.workspace_label);
      }
      if (workspace_node["passage_width"]) {
        world.passage_width = workspace_node["passage_width"].as<double>();
      }
    } else {
      file.Fail(child("workspace"),
                "expected a file name or {generator: ...}, got " + YamlFile::Shown(workspace_node));
    }
    world.scenario.start = file.Numbers(node["start"], child("start"), "[x, y] or [x, y, yaw]");
    world.scenario.goal = file.Numbers(node["goal"], child("goal"), "[x, y] or [x, y, yaw]");
    for (const auto* q : {&world.scenario.start, &world.scenario.goal}) {
      if (q->size() != 2 && q->size() != 3) {
        file.Fail(child(q == &world.scenario.start ? "start" : "goal"),
                  "expected [x, y] or [x, y, yaw]");
      }
    }
  }
  if (node["acd"]) ReadAcd(file, node["acd"], child("acd"), &world.scenario);
  if (node["collision"]) {
    file.CheckKeys(node["collision"], child("collision"), {"mode"});
    if (node["collision"]["mode"]) {
      world.scenario.collision_mode = file.Parsed(
          node["collision"]["mode"], child("collision") + ".mode", collision::ParseCollisionMode);
    }
  }
  if (node["name"]) world.name = file.String(node["name"], child("name"));
  if (world.name.empty()) file.Fail(child("name"), "required");
  if (!SafeName(world.name)) {
    file.Fail(child("name"), "expected letters, digits, '_', '-' or '.', got '" + world.name + "'");
  }
  world.family = world.name;
  if (node["passage_width"]) {
    world.passage_width =
        file.Number(node["passage_width"], child("passage_width"), "a positive number", Positive);
  }

  if (!node["passage_widths"]) {
    world.workspace_width = world.scenario.dimension == 3
                                ? world.scenario.workspace3d.bounds.sizes().x()
                                : world.scenario.workspace.bounds.sizes().x();
    worlds->push_back(world);
    return;
  }
  // A sweep: the same generator at each width.
  if (!workspace_node || !workspace_node.IsMap()) {
    file.Fail(child("passage_widths"), "needs an inline workspace: {generator: ...}");
  }
  if (workspace_node["passage_width"]) {
    file.Fail(child("workspace") + ".passage_width",
              "give passage_widths or passage_width, not both");
  }
  const std::vector<double> widths =
      file.Numbers(node["passage_widths"], child("passage_widths"), "a list of widths");
  if (widths.empty()) file.Fail(child("passage_widths"), "expected at least one width");
  for (size_t i = 0; i < widths.size(); ++i) {
    const std::string item = YamlFile::Item(child("passage_widths"), i);
    if (!(widths[i] > 0)) file.Fail(item, "expected a positive number, got " + Shortest(widths[i]));
    YAML::Node generated = YAML::Clone(workspace_node);
    generated["passage_width"] = widths[i];
    BenchWorld w = world;
    w.scenario.workspace =
        planning::ReadGeneratedWorkspace(file, generated, item, &w.scenario.workspace_label);
    w.passage_width = widths[i];
    w.name = world.name + "_w" + Shortest(widths[i]);
    w.workspace_width = w.scenario.workspace.bounds.sizes().x();
    worlds->push_back(w);
  }
}

std::string FamilyOf(const BenchWorld& world) { return world.family; }
std::string FamilyOf(const BenchRobot& robot) { return robot.name; }

/// The indices of `names` among `items` (all when the node is absent).
template <typename T>
std::vector<int> Subset(const YamlFile& file, const YAML::Node& node, const std::string& key,
                        const std::vector<T>& items) {
  std::vector<int> indices;
  if (!node) {
    for (size_t i = 0; i < items.size(); ++i) indices.push_back(static_cast<int>(i));
    return indices;
  }
  const std::vector<std::string> names = file.Strings(node, key);
  if (names.empty()) file.Fail(key, "expected at least one name");
  for (size_t i = 0; i < names.size(); ++i) {
    bool found = false;
    for (size_t j = 0; j < items.size(); ++j) {
      // A sweep's worlds are selected by the family name too.
      if (items[j].name == names[i] || FamilyOf(items[j]) == names[i]) {
        indices.push_back(static_cast<int>(j));
        found = true;
      }
    }
    if (!found) {
      std::vector<std::string> known;
      for (const T& item : items) known.push_back(item.name);
      file.Fail(YamlFile::Item(key, i), UnknownName("name", names[i], known));
    }
  }
  return indices;
}

/// The list of names at `key`, each parsed by `parse` (a planner or sampler name).
template <typename Parse>
auto ParsedList(const YamlFile& file, const YAML::Node& node, const std::string& key, Parse parse) {
  if (!node) file.Fail(key, "required");
  const std::vector<std::string> names = file.Strings(node, key);
  if (names.empty()) file.Fail(key, "expected at least one name");
  std::vector<decltype(parse(names[0]))> values;
  for (size_t i = 0; i < names.size(); ++i) {
    values.push_back(file.Parsed(node[i], YamlFile::Item(key, i), parse));
  }
  return values;
}

/// "acd" or "grid<cells>" (cells >= 1). @throws InputError otherwise.
/// The group's `budgets`: a non-empty list of {time_limit} or {samples}; `on_samples(key)` vets
/// a sample budget (and fails where the group's planners cannot honour one).
template <typename OnSamples>
std::vector<BenchBudget> ReadBudgets(const YamlFile& file, const YAML::Node& group,
                                     const std::string& key, OnSamples on_samples) {
  const YAML::Node& budgets = group["budgets"];
  if (!budgets) file.Fail(key + ".budgets", "required");
  if (!budgets.IsSequence() || budgets.size() == 0) {
    file.Fail(key + ".budgets", "expected a non-empty list, got " + YamlFile::Shown(budgets));
  }
  std::vector<BenchBudget> list;
  for (size_t b = 0; b < budgets.size(); ++b) {
    const std::string bkey = YamlFile::Item(key + ".budgets", b);
    const YAML::Node& node = budgets[b];
    file.CheckKeys(node, bkey, {"time_limit", "samples"});
    if (node["samples"]) on_samples(bkey);
    if (node["time_limit"] && node["samples"]) {
      file.Fail(bkey, "give time_limit or samples, not both");
    }
    BenchBudget budget;
    if (node["time_limit"]) {
      budget.time_limit =
          file.Number(node["time_limit"], bkey + ".time_limit", "a positive number", Positive);
    } else if (node["samples"]) {
      budget.samples =
          static_cast<int>(file.Integer(node["samples"], bkey + ".samples", "an integer >= 1", 1));
    } else {
      file.Fail(bkey, "expected time_limit or samples");
    }
    list.push_back(budget);
  }
  return list;
}

/// Appends `c` to `spec`, refusing a case that is already there.
void AddCase(const YamlFile& file, const std::string& key, const BenchCase& c, BenchSpec* spec) {
  const std::string k = c.Key(*spec);
  for (const BenchCase& other : spec->cases) {
    if (other.Key(*spec) == k) file.Fail(key, "case " + k + " appears twice");
  }
  spec->cases.push_back(c);
}

BenchDecomposition ParseBenchDecomposition(const std::string& name) {
  BenchDecomposition d;
  if (name == "acd") return d;
  const std::string digits = name.substr(std::min<size_t>(4, name.size()));
  if (name.rfind("grid", 0) == 0 && !digits.empty() && digits.size() <= 4 &&
      std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }) &&
      std::stoi(digits) >= 1 && std::stoi(digits) <= 1000) {
    d.kind = planning::control::DecompositionKind::kGrid;
    d.cells = std::stoi(digits);
    return d;
  }
  throw InputError("unknown decomposition '" + name +
                   "' (expected acd or grid<cells per side, 1-1000>, e.g. grid20)");
}

/// A group of `cases` whose robots are cars: control planners x decompositions (Syclop) x
/// time budgets.
void ReadCarCases(const YamlFile& file, const YAML::Node& group, const std::string& key,
                  const std::vector<int>& world_ids, const std::vector<int>& robot_ids,
                  BenchSpec* spec) {
  using planning::control::ControlPlanner;
  if (group["samplers"]) {
    file.Fail(key + ".samplers",
              "a car is planned by control planners, which take no sampler (Syclop's guide is "
              "`decompositions`)");
  }
  const std::vector<ControlPlanner> planners = ParsedList(
      file, group["planners"], key + ".planners", planning::control::ParseControlPlanner);
  std::vector<BenchDecomposition> decompositions = {BenchDecomposition{}};
  if (group["decompositions"]) {
    decompositions =
        ParsedList(file, group["decompositions"], key + ".decompositions", ParseBenchDecomposition);
  }
  const std::vector<BenchBudget> budget_list =
      ReadBudgets(file, group, key, [&file](const std::string& bkey) {
        file.Fail(bkey, "a car's control planner takes a time_limit, not a sample budget");
      });
  for (int w : world_ids) {
    for (int rb : robot_ids) {
      for (ControlPlanner planner : planners) {
        const bool syclop =
            planner == ControlPlanner::kSyclopRrt || planner == ControlPlanner::kSyclopEst;
        std::vector<std::optional<BenchDecomposition>> guides;
        if (syclop) {
          guides.assign(decompositions.begin(), decompositions.end());
        } else {
          guides.push_back(std::nullopt);  // RRT, KPIECE1, EST, PDST follow no decomposition.
        }
        for (const auto& guide : guides) {
          for (const BenchBudget& budget : budget_list) {
            BenchCase c;
            c.index = static_cast<int>(spec->cases.size());
            c.world = w;
            c.robot = rb;
            c.control = true;
            c.control_planner = planner;
            c.decomposition = guide;
            c.budget = budget;
            AddCase(file, key, c, spec);
          }
        }
      }
    }
  }
}

}  // namespace

std::string BenchBudget::Label() const {
  return samples > 0 ? std::to_string(samples) + " samples" : Shortest(time_limit) + " s";
}

std::string BenchDecomposition::Label() const {
  return kind == planning::control::DecompositionKind::kAcd ? "acd"
                                                            : "grid" + std::to_string(cells);
}

std::string BenchCase::SamplerLabel() const {
  if (!control) return planning::ToString(sampler);
  return decomposition ? decomposition->Label() : "none";
}

std::string BenchCase::PlannerLabel() const {
  return control ? planning::control::ToString(control_planner) : planning::ToString(planner);
}

std::string BenchCase::Key(const BenchSpec& spec) const {
  return spec.worlds[world].name + "/" + spec.robots[robot].name + "/" + SamplerLabel() + "/" +
         PlannerLabel() + "/" + budget.Label();
}

BenchSpec LoadBenchSpec(const std::string& path) {
  const YamlFile file = YamlFile::Load(path);
  const YAML::Node& root = file.root();
  file.CheckKeys(root, "",
                 {"name", "description", "seed", "runs", "acd", "acd_sampler", "worlds", "robots",
                  "cases", "targets"});
  BenchSpec spec;
  spec.path = path;
  if (!root["name"]) file.Fail("name", "required");
  spec.name = file.String(root["name"], "name");
  if (!SafeName(spec.name)) {
    file.Fail("name", "expected letters, digits, '_', '-' or '.', got '" + spec.name + "'");
  }
  if (root["description"]) spec.description = file.String(root["description"], "description");
  if (root["seed"]) spec.seed = file.Integer(root["seed"], "seed", "an integer >= 0", 0);
  if (root["runs"]) {
    spec.runs = static_cast<int>(file.Integer(root["runs"], "runs", "an integer >= 1", 1));
  }

  Scenario defaults;
  if (root["acd"]) ReadAcd(file, root["acd"], "acd", &defaults);
  spec.warnings = defaults.warnings;
  defaults.warnings.clear();
  AcdSamplerOptions sampler_options;
  if (root["acd_sampler"])
    ReadSamplerOptions(file, root["acd_sampler"], "acd_sampler", &sampler_options);

  const YAML::Node& worlds = root["worlds"];
  if (!worlds) file.Fail("worlds", "required");
  if (!worlds.IsSequence() || worlds.size() == 0) {
    file.Fail("worlds", "expected a non-empty list, got " + YamlFile::Shown(worlds));
  }
  for (size_t i = 0; i < worlds.size(); ++i) {
    const size_t before = spec.worlds.size();
    ReadWorld(file, worlds[i], YamlFile::Item("worlds", i), defaults, &spec.worlds);
    for (size_t j = before; j < spec.worlds.size(); ++j) {
      for (size_t k = 0; k < before; ++k) {
        if (spec.worlds[k].name == spec.worlds[j].name) {
          file.Fail(YamlFile::Item("worlds", i) + ".name",
                    "duplicate world name '" + spec.worlds[j].name + "'");
        }
      }
    }
  }

  if (const YAML::Node& robots = root["robots"]) {
    if (!robots.IsSequence() || robots.size() == 0) {
      file.Fail("robots", "expected a non-empty list, got " + YamlFile::Shown(robots));
    }
    for (size_t i = 0; i < robots.size(); ++i) {
      const std::string key = YamlFile::Item("robots", i);
      const YAML::Node& node = robots[i];
      if (!node.IsMap()) file.Fail(key, "expected a mapping, got " + YamlFile::Shown(node));
      BenchRobot robot;
      robot.acd_options = sampler_options;
      YAML::Node shape;  // The robot keys ReadRobot() knows.
      for (const auto& entry : node) {
        // A key may be any YAML node ("{[a]: 1}"); as<std::string>() would throw yaml-cpp's own
        // exception on a non-scalar.
        if (!entry.first.IsScalar()) {
          file.Fail(key, "expected a mapping with string keys, got " +
                             YamlFile::Shown(entry.first) + " as a key");
        }
        const std::string k = entry.first.Scalar();
        if (k == "name") {
          robot.name = file.String(entry.second, key + ".name");
        } else if (k == "orientation") {
          YAML::Node o;
          o["orientation"] = entry.second;
          ReadSamplerOptions(file, o, key, &robot.acd_options);
        } else if (k == "shape" || k == "radius" || k == "polygon" || k == "type" ||
                   k == "length" || k == "width" || k == "max_speed" || k == "max_steer" ||
                   k == "max_accel" || k == "max_steer_rate" || k == "step" ||
                   k == "min_control_steps" || k == "max_control_steps") {
          shape[k] = entry.second;
        } else {
          file.Fail(key + "." + k,
                    "unknown key (expected one of: name, shape, radius, polygon, orientation; a "
                    "car: type, length, width, max_speed, max_steer, max_accel, max_steer_rate, "
                    "step, min_control_steps, max_control_steps)");
        }
      }
      if (!SafeName(robot.name)) {
        file.Fail(key + ".name",
                  robot.name.empty()
                      ? "required"
                      : "expected letters, digits, '_', '-' or '.', got '" + robot.name + "'");
      }
      robot.from_scenario =
          shape["shape"] && shape["shape"].IsScalar() && shape["shape"].Scalar() == "scenario";
      if (robot.from_scenario) {
        for (const char* k : {"radius", "polygon", "type"}) {
          if (shape[k]) file.Fail(key + "." + k, "not with shape: scenario");
        }
      } else if (planning::NamesCarRobot(shape)) {
        robot.car = planning::ReadCarRobot(file, shape, key);
        robot.robot = robot.car->body;
      } else {
        robot.robot = planning::ReadRobot(
            file, shape.IsNull() ? YAML::Node(YAML::NodeType::Map) : shape, key);
      }
      for (const BenchRobot& other : spec.robots) {
        if (other.name == robot.name)
          file.Fail(key + ".name", "duplicate robot name '" + robot.name + "'");
      }
      spec.robots.push_back(robot);
    }
  } else {
    BenchRobot point;
    point.name = "point";
    point.acd_options = sampler_options;
    spec.robots.push_back(point);
  }

  const YAML::Node& cases = root["cases"];
  if (!cases) file.Fail("cases", "required");
  if (!cases.IsSequence() || cases.size() == 0) {
    file.Fail("cases", "expected a non-empty list, got " + YamlFile::Shown(cases));
  }
  for (size_t g = 0; g < cases.size(); ++g) {
    const std::string key = YamlFile::Item("cases", g);
    const YAML::Node& group = cases[g];
    file.CheckKeys(group, key,
                   {"worlds", "robots", "samplers", "planners", "decompositions", "budgets"});
    const std::vector<int> world_ids = Subset(file, group["worlds"], key + ".worlds", spec.worlds);
    const std::vector<int> robot_ids = Subset(file, group["robots"], key + ".robots", spec.robots);
    const bool cars = spec.robots[robot_ids.front()].car.has_value();
    for (int r : robot_ids) {
      if (spec.robots[r].car.has_value() != cars) {
        file.Fail(key + ".robots",
                  "mixes cars (control planners) and rigid robots (samplers and geometric "
                  "planners): give them cases of their own");
      }
    }
    if (cars) {
      ReadCarCases(file, group, key, world_ids, robot_ids, &spec);
      continue;
    }
    if (group["decompositions"]) {
      file.Fail(key + ".decompositions", "only for car robots (Syclop's regions)");
    }
    const std::vector<SamplerType> samplers =
        ParsedList(file, group["samplers"], key + ".samplers", planning::ParseSamplerType);
    const std::vector<PlannerType> planners =
        ParsedList(file, group["planners"], key + ".planners", planning::ParsePlannerType);
    const std::vector<BenchBudget> budget_list =
        ReadBudgets(file, group, key, [&file, &planners](const std::string& bkey) {
          for (PlannerType planner : planners) {
            if (!planning::HonoursSampleBudget(planner)) {
              file.Fail(bkey + ".samples",
                        "a sample budget (the Figure-4 protocol) needs PRM, PRM_ACD or PRMstar, "
                        "not " +
                            planning::ToString(planner) + "; use time_limit");
            }
          }
        });
    for (int w : world_ids) {
      for (int rb : robot_ids) {
        for (SamplerType sampler : samplers) {
          for (PlannerType planner : planners) {
            for (const BenchBudget& budget : budget_list) {
              BenchCase c;
              c.index = static_cast<int>(spec.cases.size());
              c.world = w;
              c.robot = rb;
              c.sampler = sampler;
              c.planner = planner;
              c.budget = budget;
              AddCase(file, key, c, &spec);
            }
          }
        }
      }
    }
  }
  if (root["targets"]) {
    spec.targets = ReadTargets(file, root["targets"], "targets", PlanningTargetVocabulary());
  }
  return spec;
}

BenchShard ParseBenchShard(const std::string& text) {
  BenchShard shard;
  const size_t slash = text.find('/');
  try {
    if (slash == std::string::npos) throw std::invalid_argument("no slash");
    size_t used = 0;
    shard.index = std::stoi(text.substr(0, slash), &used);
    if (used != slash) throw std::invalid_argument("trailing");
    const std::string rest = text.substr(slash + 1);
    shard.count = std::stoi(rest, &used);
    if (used != rest.size()) throw std::invalid_argument("trailing");
  } catch (const std::exception&) {
    throw InputError("expected I/N (e.g. 2/8), got '" + text + "'");
  }
  if (shard.count < 1 || shard.index < 1 || shard.index > shard.count) {
    throw InputError("expected I/N with 1 <= I <= N, got '" + text + "'");
  }
  return shard;
}

std::uint64_t BenchRunSeed(std::uint64_t base_seed, const std::string& case_key, int run) {
  std::uint64_t h = 0xCBF29CE484222325ULL;  // FNV-1a, 64 bit.
  for (unsigned char c : case_key) {
    h ^= c;
    h *= 0x100000001B3ULL;
  }
  // Kept below 2^53 so the seed survives a round trip through JSON and spreadsheets.
  return SplitMix64(SplitMix64(base_seed) ^ SplitMix64(h + static_cast<std::uint64_t>(run))) >> 11;
}

std::vector<BenchRunId> BenchRunsOfShard(const BenchSpec& spec, int runs, const BenchShard& shard) {
  std::vector<BenchRunId> ids;
  for (const BenchCase& c : spec.cases) {
    const std::string key = c.Key(spec);
    for (int k = 0; k < runs; ++k) {
      BenchRunId id;
      id.case_index = c.index;
      id.run = k;
      id.global = static_cast<std::uint64_t>(c.index) * static_cast<std::uint64_t>(runs) +
                  static_cast<std::uint64_t>(k);
      if (id.global % static_cast<std::uint64_t>(shard.count) !=
          static_cast<std::uint64_t>(shard.index - 1)) {
        continue;
      }
      id.seed = BenchRunSeed(spec.seed, key, k);
      ids.push_back(id);
    }
  }
  return ids;
}

}  // namespace acdplan::bench
