#include "bench/spec.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "acd/input_error.h"
#include "bench/summary.h"
#include "envs/load_workspace.h"
#include "planning/internal/yaml_reader.h"
#include "planning/registry.h"

namespace acdplan::bench {

namespace {

namespace internal = planning::internal;
using planning::AcdSamplerOptions;
using planning::Scenario;
using Reader = internal::YamlReader;

bool SafeName(const std::string& name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
}

std::string Shortest(double x) {
  std::ostringstream out;
  out.precision(6);
  out << x;
  return out.str();
}

std::string Joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

/// Reads `acd: {tau_rel, measure}` into `scenario`.
void ReadAcd(const Reader& r, const YAML::Node& node, const std::string& key, Scenario* s) {
  r.CheckKeys(node, key, {"tau_rel", "measure"});
  if (node["tau_rel"]) {
    s->tau_rel = r.Number(node["tau_rel"], Reader::Child(key, "tau_rel"), "a number >= 0",
                          internal::NonNegative);
  }
  if (node["measure"]) {
    const std::string name = r.String(node["measure"], Reader::Child(key, "measure"));
    try {
      s->measure = acd::ParseConcavityMeasure(name);
    } catch (const acd::InputError& error) {
      r.Fail(Reader::Child(key, "measure"), error.what());
    }
  }
}

/// Reads `acd_sampler: {...}` (also a robot's `orientation`).
void ReadSamplerOptions(const Reader& r, const YAML::Node& node, const std::string& key,
                        AcdSamplerOptions* o) {
  r.CheckKeys(node, key,
              {"uniform_share", "opening_weight", "centroid_spread", "opening_spread",
               "max_attempts", "orientation"});
  internal::ReadAcdSamplerOptions(r, node, key, o);
}

std::string Resolved(const std::string& base_file, const std::string& file) {
  const std::filesystem::path p(file);
  return p.is_absolute() ? p.string()
                         : (std::filesystem::path(base_file).parent_path() / p).string();
}

/// Reads worlds[i] (one world, or several for a `passage_widths` sweep).
void ReadWorld(const Reader& r, const YAML::Node& node, const std::string& key,
               const Scenario& defaults, std::vector<BenchWorld>* worlds) {
  r.CheckKeys(node, key,
              {"name", "scenario", "workspace", "start", "goal", "acd", "collision",
               "passage_width", "passage_widths"});
  auto child = [&](const char* name) { return Reader::Child(key, name); };
  BenchWorld world;
  world.scenario = defaults;
  YAML::Node workspace_node;
  if (node["scenario"]) {
    for (const char* k : {"workspace", "start", "goal"}) {
      if (node[k]) r.Fail(child(k), "give either scenario or workspace, start and goal");
    }
    const std::string file = Resolved(r.file, r.String(node["scenario"], child("scenario")));
    try {
      world.scenario = planning::LoadScenario(file);
    } catch (const acd::InputError& error) {
      r.Fail(child("scenario"), error.what());
    }
    world.name = std::filesystem::path(file).stem().string();
    // The generator's passage width, for the plots (the scenario keeps only the workspace).
    const YAML::Node scenario_root = internal::LoadYamlFile(file);
    const YAML::Node generated = scenario_root["workspace"];
    if (generated.IsMap() && generated["passage_width"]) {
      double width = 0;
      if (YAML::convert<double>::decode(generated["passage_width"], width)) {
        world.passage_width = width;
      }
    }
  } else {
    for (const char* k : {"workspace", "start", "goal"}) {
      if (!node[k]) r.Fail(child(k), "required (or give a scenario file)");
    }
    workspace_node = node["workspace"];
    if (workspace_node.IsScalar()) {
      const std::string file = Resolved(r.file, workspace_node.Scalar());
      world.scenario.workspace_label = file;
      try {
        world.scenario.workspace = envs::LoadWorkspace2d(file);
      } catch (const acd::InputError& error) {
        r.Fail(child("workspace"), error.what());
      }
    } else if (workspace_node.IsMap()) {
      if (!node["passage_widths"]) {
        world.scenario.workspace = internal::ReadGeneratedWorkspace(
            r, workspace_node, child("workspace"), &world.scenario.workspace_label);
      }
      if (workspace_node["passage_width"]) {
        world.passage_width = workspace_node["passage_width"].as<double>();
      }
    } else {
      r.Fail(child("workspace"),
             "expected a file name or {generator: ...}, got " + Reader::Shown(workspace_node));
    }
    world.scenario.start = r.Numbers(node["start"], child("start"), "[x, y] or [x, y, yaw]");
    world.scenario.goal = r.Numbers(node["goal"], child("goal"), "[x, y] or [x, y, yaw]");
    for (const auto* q : {&world.scenario.start, &world.scenario.goal}) {
      if (q->size() != 2 && q->size() != 3) {
        r.Fail(child(q == &world.scenario.start ? "start" : "goal"),
               "expected [x, y] or [x, y, yaw]");
      }
    }
  }
  if (node["acd"]) ReadAcd(r, node["acd"], child("acd"), &world.scenario);
  if (node["collision"]) {
    r.CheckKeys(node["collision"], child("collision"), {"mode"});
    if (node["collision"]["mode"]) {
      const std::string mode = r.String(node["collision"]["mode"], child("collision") + ".mode");
      if (mode != "bvh" && mode != "hulls" && mode != "hulls+exact") {
        r.Fail(child("collision") + ".mode",
               "expected bvh, hulls or hulls+exact, got '" + mode + "'");
      }
      world.scenario.collision_mode = mode;
    }
  }
  if (node["name"]) world.name = r.String(node["name"], child("name"));
  if (world.name.empty()) r.Fail(child("name"), "required");
  if (!SafeName(world.name)) {
    r.Fail(child("name"), "expected letters, digits, '_', '-' or '.', got '" + world.name + "'");
  }
  world.family = world.name;
  if (node["passage_width"]) {
    world.passage_width = r.Number(node["passage_width"], child("passage_width"),
                                   "a positive number", internal::Positive);
  }

  if (!node["passage_widths"]) {
    world.workspace_width = world.scenario.workspace.bounds.sizes().x();
    worlds->push_back(world);
    return;
  }
  // A sweep: the same generator at each width.
  if (!workspace_node || !workspace_node.IsMap()) {
    r.Fail(child("passage_widths"), "needs an inline workspace: {generator: ...}");
  }
  if (workspace_node["passage_width"]) {
    r.Fail(child("workspace") + ".passage_width", "give passage_widths or passage_width, not both");
  }
  const std::vector<double> widths =
      r.Numbers(node["passage_widths"], child("passage_widths"), "a list of widths");
  if (widths.empty()) r.Fail(child("passage_widths"), "expected at least one width");
  for (size_t i = 0; i < widths.size(); ++i) {
    const std::string item = Reader::Item(child("passage_widths"), i);
    if (!(widths[i] > 0)) r.Fail(item, "expected a positive number, got " + Shortest(widths[i]));
    YAML::Node generated = YAML::Clone(workspace_node);
    generated["passage_width"] = widths[i];
    BenchWorld w = world;
    w.scenario.workspace =
        internal::ReadGeneratedWorkspace(r, generated, item, &w.scenario.workspace_label);
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
std::vector<int> Subset(const Reader& r, const YAML::Node& node, const std::string& key,
                        const std::vector<T>& items) {
  std::vector<int> indices;
  if (!node) {
    for (size_t i = 0; i < items.size(); ++i) indices.push_back(static_cast<int>(i));
    return indices;
  }
  const std::vector<std::string> names = r.Strings(node, key);
  if (names.empty()) r.Fail(key, "expected at least one name");
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
      r.Fail(Reader::Item(key, i),
             "unknown name '" + names[i] + "' (known: " + Joined(known) + ")");
    }
  }
  return indices;
}

std::vector<std::string> Names(const Reader& r, const YAML::Node& node, const std::string& key,
                               const std::vector<std::string>& known, const char* what) {
  if (!node) r.Fail(key, "required");
  const std::vector<std::string> names = r.Strings(node, key);
  if (names.empty()) r.Fail(key, "expected at least one name");
  for (size_t i = 0; i < names.size(); ++i) {
    if (std::find(known.begin(), known.end(), names[i]) == known.end()) {
      r.Fail(Reader::Item(key, i),
             std::string("unknown ") + what + " '" + names[i] + "' (known: " + Joined(known) + ")");
    }
  }
  return names;
}

}  // namespace

std::string BenchBudget::Label() const {
  return samples > 0 ? std::to_string(samples) + " samples" : Shortest(time_limit) + " s";
}

std::string BenchCase::Key(const BenchSpec& spec) const {
  return spec.worlds[world].name + "/" + spec.robots[robot].name + "/" + sampler + "/" + planner +
         "/" + budget.Label();
}

BenchSpec LoadBenchSpec(const std::string& path) {
  const Reader r{path};
  const YAML::Node root = internal::LoadYamlFile(path);
  r.CheckKeys(root, "",
              {"name", "description", "seed", "runs", "acd", "acd_sampler", "worlds", "robots",
               "cases", "targets"});
  BenchSpec spec;
  spec.path = path;
  if (!root["name"]) r.Fail("name", "required");
  spec.name = r.String(root["name"], "name");
  if (!SafeName(spec.name)) {
    r.Fail("name", "expected letters, digits, '_', '-' or '.', got '" + spec.name + "'");
  }
  if (root["description"]) spec.description = r.String(root["description"], "description");
  if (root["seed"]) spec.seed = r.Integer(root["seed"], "seed", "an integer >= 0", 0);
  if (root["runs"]) {
    spec.runs = static_cast<int>(r.Integer(root["runs"], "runs", "an integer >= 1", 1));
  }

  Scenario defaults;
  if (root["acd"]) ReadAcd(r, root["acd"], "acd", &defaults);
  AcdSamplerOptions sampler_options;
  if (root["acd_sampler"])
    ReadSamplerOptions(r, root["acd_sampler"], "acd_sampler", &sampler_options);

  const YAML::Node& worlds = root["worlds"];
  if (!worlds) r.Fail("worlds", "required");
  if (!worlds.IsSequence() || worlds.size() == 0) {
    r.Fail("worlds", "expected a non-empty list, got " + Reader::Shown(worlds));
  }
  for (size_t i = 0; i < worlds.size(); ++i) {
    const size_t before = spec.worlds.size();
    ReadWorld(r, worlds[i], Reader::Item("worlds", i), defaults, &spec.worlds);
    for (size_t j = before; j < spec.worlds.size(); ++j) {
      for (size_t k = 0; k < before; ++k) {
        if (spec.worlds[k].name == spec.worlds[j].name) {
          r.Fail(Reader::Item("worlds", i) + ".name",
                 "duplicate world name '" + spec.worlds[j].name + "'");
        }
      }
    }
  }

  if (const YAML::Node& robots = root["robots"]) {
    if (!robots.IsSequence() || robots.size() == 0) {
      r.Fail("robots", "expected a non-empty list, got " + Reader::Shown(robots));
    }
    for (size_t i = 0; i < robots.size(); ++i) {
      const std::string key = Reader::Item("robots", i);
      const YAML::Node& node = robots[i];
      if (!node.IsMap()) r.Fail(key, "expected a mapping, got " + Reader::Shown(node));
      BenchRobot robot;
      robot.acd_options = sampler_options;
      YAML::Node shape;  // The robot keys ReadRobot() knows.
      for (const auto& entry : node) {
        const std::string k = entry.first.as<std::string>();
        if (k == "name") {
          robot.name = r.String(entry.second, key + ".name");
        } else if (k == "orientation") {
          YAML::Node o;
          o["orientation"] = entry.second;
          ReadSamplerOptions(r, o, key, &robot.acd_options);
        } else if (k == "shape" || k == "radius" || k == "polygon") {
          shape[k] = entry.second;
        } else {
          r.Fail(key + "." + k, "unknown key (known: name, shape, radius, polygon, orientation)");
        }
      }
      if (!SafeName(robot.name)) {
        r.Fail(key + ".name",
               robot.name.empty()
                   ? "required"
                   : "expected letters, digits, '_', '-' or '.', got '" + robot.name + "'");
      }
      robot.robot =
          internal::ReadRobot(r, shape.IsNull() ? YAML::Node(YAML::NodeType::Map) : shape, key);
      for (const BenchRobot& other : spec.robots) {
        if (other.name == robot.name)
          r.Fail(key + ".name", "duplicate robot name '" + robot.name + "'");
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
  if (!cases) r.Fail("cases", "required");
  if (!cases.IsSequence() || cases.size() == 0) {
    r.Fail("cases", "expected a non-empty list, got " + Reader::Shown(cases));
  }
  for (size_t g = 0; g < cases.size(); ++g) {
    const std::string key = Reader::Item("cases", g);
    const YAML::Node& group = cases[g];
    r.CheckKeys(group, key, {"worlds", "robots", "samplers", "planners", "budgets"});
    const std::vector<int> world_ids = Subset(r, group["worlds"], key + ".worlds", spec.worlds);
    const std::vector<int> robot_ids = Subset(r, group["robots"], key + ".robots", spec.robots);
    const std::vector<std::string> samplers =
        Names(r, group["samplers"], key + ".samplers", planning::SamplerNames(), "sampler");
    const std::vector<std::string> planners =
        Names(r, group["planners"], key + ".planners", planning::PlannerNames(), "planner");
    const YAML::Node& budgets = group["budgets"];
    if (!budgets) r.Fail(key + ".budgets", "required");
    if (!budgets.IsSequence() || budgets.size() == 0) {
      r.Fail(key + ".budgets", "expected a non-empty list, got " + Reader::Shown(budgets));
    }
    std::vector<BenchBudget> budget_list;
    for (size_t b = 0; b < budgets.size(); ++b) {
      const std::string bkey = Reader::Item(key + ".budgets", b);
      r.CheckKeys(budgets[b], bkey, {"time_limit", "samples"});
      BenchBudget budget;
      if (budgets[b]["time_limit"] && budgets[b]["samples"]) {
        r.Fail(bkey, "give time_limit or samples, not both");
      }
      if (budgets[b]["time_limit"]) {
        budget.time_limit = r.Number(budgets[b]["time_limit"], bkey + ".time_limit",
                                     "a positive number", internal::Positive);
      } else if (budgets[b]["samples"]) {
        budget.samples = static_cast<int>(
            r.Integer(budgets[b]["samples"], bkey + ".samples", "an integer >= 1", 1));
        for (const std::string& planner : planners) {
          if (!planning::SupportsSampleBudget(planner)) {
            r.Fail(bkey + ".samples",
                   "a sample budget (the Figure-4 protocol) needs PRM, PRM_ACD or PRMstar, "
                   "not " +
                       planner + "; use time_limit");
          }
        }
      } else {
        r.Fail(bkey, "expected time_limit or samples");
      }
      budget_list.push_back(budget);
    }
    for (int w : world_ids) {
      for (int rb : robot_ids) {
        for (const std::string& sampler : samplers) {
          for (const std::string& planner : planners) {
            for (const BenchBudget& budget : budget_list) {
              BenchCase c;
              c.index = static_cast<int>(spec.cases.size());
              c.world = w;
              c.robot = rb;
              c.sampler = sampler;
              c.planner = planner;
              c.budget = budget;
              const std::string k = c.Key(spec);
              for (const BenchCase& other : spec.cases) {
                if (other.Key(spec) == k) r.Fail(key, "case " + k + " appears twice");
              }
              spec.cases.push_back(c);
            }
          }
        }
      }
    }
  }
  if (root["targets"]) {
    spec.targets = ReadTargets(path, root["targets"], "targets", PlanningTargetVocabulary());
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
    throw acd::InputError("expected I/N (e.g. 2/8), got '" + text + "'");
  }
  if (shard.count < 1 || shard.index < 1 || shard.index > shard.count) {
    throw acd::InputError("expected I/N with 1 <= I <= N, got '" + text + "'");
  }
  return shard;
}

namespace {

std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

}  // namespace

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
