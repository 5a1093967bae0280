#include "planning/internal/yaml_reader.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "acd/input_error.h"
#include "envs/generators.h"

namespace acdplan::planning::internal {

void YamlReader::Fail(const std::string& key, const std::string& rule) const {
  throw acd::InputError(file + ": " + key + ": " + rule);
}

std::string YamlReader::Shown(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

void YamlReader::CheckKeys(const YAML::Node& node, const std::string& key,
                           std::initializer_list<const char*> allowed) const {
  if (!node.IsMap()) Fail(key.empty() ? "(root)" : key, "expected a mapping, got " + Shown(node));
  for (const auto& entry : node) {
    const std::string name = entry.first.as<std::string>();
    if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return name == a; })) {
      std::string known;
      for (const char* a : allowed) known += (known.empty() ? "" : ", ") + std::string(a);
      Fail(Child(key, name), "unknown key (known: " + known + ")");
    }
  }
}

double YamlReader::Number(const YAML::Node& node, const std::string& key, const std::string& rule,
                          bool (*accept)(double)) const {
  double value = 0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value) ||
      !accept(value)) {
    Fail(key, "expected " + rule + ", got " + Shown(node));
  }
  return value;
}

long long YamlReader::Integer(const YAML::Node& node, const std::string& key,
                              const std::string& rule, long long min) const {
  long long value = 0;
  if (!node.IsScalar() || !YAML::convert<long long>::decode(node, value) || value < min) {
    Fail(key, "expected " + rule + ", got " + Shown(node));
  }
  return value;
}

std::string YamlReader::String(const YAML::Node& node, const std::string& key) const {
  if (!node.IsScalar()) Fail(key, "expected a string, got " + Shown(node));
  return node.Scalar();
}

std::vector<double> YamlReader::Numbers(const YAML::Node& node, const std::string& key,
                                        const std::string& what) const {
  if (!node.IsSequence()) Fail(key, "expected " + what + ", got " + Shown(node));
  std::vector<double> values;
  for (size_t i = 0; i < node.size(); ++i) {
    values.push_back(Number(node[i], Item(key, i), "a number", [](double x) { return x == x; }));
  }
  return values;
}

std::vector<std::string> YamlReader::Strings(const YAML::Node& node, const std::string& key) const {
  if (!node.IsSequence()) Fail(key, "expected a list of names, got " + Shown(node));
  std::vector<std::string> values;
  for (size_t i = 0; i < node.size(); ++i) values.push_back(String(node[i], Item(key, i)));
  return values;
}

std::string YamlReader::Child(const std::string& key, const std::string& child) {
  return key.empty() ? child : key + "." + child;
}

std::string YamlReader::Item(const std::string& key, size_t i) {
  return key + "[" + std::to_string(i) + "]";
}

YAML::Node LoadYamlFile(const std::string& path) {
  try {
    return YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw acd::InputError(path + ": cannot read the file");
  } catch (const YAML::ParserException& error) {
    std::ostringstream out;
    out << path << ":" << error.mark.line + 1 << ": YAML syntax error: " << error.msg;
    throw acd::InputError(out.str());
  }
}

bool Positive(double x) { return x > 0; }
bool NonNegative(double x) { return x >= 0; }
bool UnitInterval(double x) { return x >= 0 && x <= 1; }

envs::Workspace2d ReadGeneratedWorkspace(const YamlReader& r, const YAML::Node& node,
                                         const std::string& key, std::string* label) {
  using R = YamlReader;
  r.CheckKeys(node, key, {"generator", "seed", "passage_width", "wall_thickness"});
  if (!node["generator"]) r.Fail(R::Child(key, "generator"), "required (or give a file name)");
  const std::string name = r.String(node["generator"], R::Child(key, "generator"));
  const std::uint64_t seed =
      node["seed"] ? r.Integer(node["seed"], R::Child(key, "seed"), "an integer >= 0", 0) : 1;
  const double width = node["passage_width"]
                           ? r.Number(node["passage_width"], R::Child(key, "passage_width"),
                                      "a positive number", Positive)
                           : 0.0;
  *label = "generator " + name + " (seed " + std::to_string(seed) + ")";
  if (!node["wall_thickness"]) {
    try {
      return envs::GenerateWorkspace2d(name, seed, width);
    } catch (const acd::InputError& error) {
      r.Fail(key, error.what());
    }
  }
  const double wall = r.Number(node["wall_thickness"], R::Child(key, "wall_thickness"),
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
    r.Fail(key, error.what());
  }
  r.Fail(R::Child(key, "wall_thickness"), "not an option of generator '" + name + "'");
}

void ReadAcdSamplerOptions(const YamlReader& r, const YAML::Node& node, const std::string& key,
                           AcdSamplerOptions* o) {
  auto child = [&key](const char* name) { return YamlReader::Child(key, name); };
  if (node["uniform_share"]) {
    o->uniform_share = r.Number(node["uniform_share"], child("uniform_share"), "a number in [0, 1]",
                                UnitInterval);
  }
  if (node["opening_weight"]) {
    o->opening_weight = r.Number(node["opening_weight"], child("opening_weight"), "a number >= 0",
                                 NonNegative);
  }
  if (node["centroid_spread"]) {
    o->centroid_spread = r.Number(node["centroid_spread"], child("centroid_spread"),
                                  "a positive number", Positive);
  }
  if (node["opening_spread"]) {
    o->opening_spread = r.Number(node["opening_spread"], child("opening_spread"),
                                 "a positive number", Positive);
  }
  if (node["max_attempts"]) {
    o->max_attempts = static_cast<int>(
        r.Integer(node["max_attempts"], child("max_attempts"), "an integer >= 1", 1));
  }
  if (node["orientation"]) {
    try {
      o->orientation = ParseAcdOrientation(r.String(node["orientation"], child("orientation")));
    } catch (const acd::InputError& error) {
      r.Fail(child("orientation"), error.what());
    }
  }
}

envs::Robot ReadRobot(const YamlReader& r, const YAML::Node& node, const std::string& key) {
  using R = YamlReader;
  r.CheckKeys(node, key, {"shape", "radius", "polygon"});
  const std::string shape =
      node["shape"] ? r.String(node["shape"], R::Child(key, "shape")) : "point";
  const std::string radius_key = R::Child(key, "radius");
  const std::string polygon_key = R::Child(key, "polygon");
  try {
    if (shape == "point") {
      if (node["radius"]) r.Fail(radius_key, "only for shape disc");
      if (node["polygon"]) r.Fail(polygon_key, "only for shape polygon");
      return envs::Robot::Point();
    }
    if (shape == "disc") {
      if (!node["radius"]) r.Fail(radius_key, "required for shape disc");
      if (node["polygon"]) r.Fail(polygon_key, "only for shape polygon");
      return envs::Robot::Disc(r.Number(node["radius"], radius_key, "a positive number", Positive));
    }
    if (shape == "polygon") {
      if (!node["polygon"]) r.Fail(polygon_key, "required for shape polygon");
      if (node["radius"]) r.Fail(radius_key, "only for shape disc");
      const YAML::Node& list = node["polygon"];
      if (!list.IsSequence() || list.size() < 3) {
        r.Fail(polygon_key, "expected a list of at least 3 [x, y] pairs");
      }
      acd::Polygon2d outline;
      for (size_t i = 0; i < list.size(); ++i) {
        const std::vector<double> xy =
            r.Numbers(list[i], R::Item(polygon_key, i), "an [x, y] pair");
        if (xy.size() != 2) r.Fail(R::Item(polygon_key, i), "expected an [x, y] pair");
        outline.outer.emplace_back(xy[0], xy[1]);
      }
      if (acd::SignedArea(outline.outer) < 0) outline.outer = acd::Reversed(outline.outer);
      return envs::Robot::Polygon(outline);
    }
  } catch (const acd::InputError& error) {
    const std::string what = error.what();
    if (what.rfind(r.file + ": ", 0) == 0) throw;
    r.Fail(key, what);
  }
  r.Fail(R::Child(key, "shape"), "expected point, disc or polygon, got '" + shape + "'");
}

}  // namespace acdplan::planning::internal
