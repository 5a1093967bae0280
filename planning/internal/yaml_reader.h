#pragma once
// Reading validated values out of YAML with errors "<file>: <key path>: <rule>" (private to
// planning: the scenario and benchmark loaders share it).

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "envs/robot.h"
#include "envs/workspace2d.h"
#include "planning/acd_sampler_options.h"

namespace acdplan::planning::internal {

/// Reads values of one file; every failure throws acd::InputError "<file>: <key>: <rule>".
struct YamlReader {
  std::string file;

  [[noreturn]] void Fail(const std::string& key, const std::string& rule) const;

  /// How a node is shown in a message: 'text', "a list", "a mapping" or "nothing".
  static std::string Shown(const YAML::Node& node);

  /// Fails unless `node` is a mapping whose keys are all in `allowed` (the message lists them).
  void CheckKeys(const YAML::Node& node, const std::string& key,
                 std::initializer_list<const char*> allowed) const;

  /// A finite number for which `accept` holds; else "expected <rule>, got <node>".
  double Number(const YAML::Node& node, const std::string& key, const std::string& rule,
                bool (*accept)(double)) const;
  /// An integer >= `min`; else "expected <rule>, got <node>".
  long long Integer(const YAML::Node& node, const std::string& key, const std::string& rule,
                    long long min) const;
  std::string String(const YAML::Node& node, const std::string& key) const;
  /// A list of numbers (any length); `what` describes the expected list in the message.
  std::vector<double> Numbers(const YAML::Node& node, const std::string& key,
                              const std::string& what) const;
  /// A list of strings.
  std::vector<std::string> Strings(const YAML::Node& node, const std::string& key) const;

  /// "key.child" ("child" at the root).
  static std::string Child(const std::string& key, const std::string& child);
  /// "key[i]".
  static std::string Item(const std::string& key, size_t i);
};

/// Loads a YAML file. @throws acd::InputError "<path>: cannot read the file" or
/// "<path>:<line>: YAML syntax error: <message>".
YAML::Node LoadYamlFile(const std::string& path);

bool Positive(double x);
bool NonNegative(double x);
bool UnitInterval(double x);

/// A generated workspace from `{generator, seed, passage_width, wall_thickness}` at `key`;
/// `*label` becomes "generator <name> (seed s)".
envs::Workspace2d ReadGeneratedWorkspace(const YamlReader& r, const YAML::Node& node,
                                         const std::string& key, std::string* label);

/// The ACD sampler options present in mapping `node` at `key` (uniform_share, opening_weight,
/// centroid_spread, opening_spread, max_attempts, orientation) into `*o`; the
/// caller checks which keys the mapping may hold.
void ReadAcdSamplerOptions(const YamlReader& r, const YAML::Node& node, const std::string& key,
                           AcdSamplerOptions* o);

/// A robot from `{shape: point | disc (radius) | polygon (polygon: [[x, y], ...])}` at `key`.
envs::Robot ReadRobot(const YamlReader& r, const YAML::Node& node, const std::string& key);

}  // namespace acdplan::planning::internal
