#pragma once
// yaml-cpp helpers whose errors name the file and the key path (private to envs).

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <vector>

namespace acdplan::envs::internal {

/// A YAML document and the file it came from, for messages "<file>: <key path>: <rule>".
struct YamlFile {
  std::string path;
  YAML::Node root;

  /// Throws acd::InputError "<path>: <key>: <rule>".
  [[noreturn]] void Fail(const std::string& key, const std::string& rule) const;
};

/// Parses `path`. @throws acd::InputError for an unreadable file, a syntax error
/// ("<path>:<line>: YAML syntax error: <reason>") or a document that is not a mapping.
YamlFile LoadYamlFile(const std::string& path);

/// Fails on the first key of mapping `node` (at `key`, "" for the root) not in `allowed`.
void CheckKeys(const YamlFile& file, const YAML::Node& node, const std::string& key,
               std::initializer_list<const char*> allowed);

/// A required mapping (fails if `node` is not one).
void ExpectMap(const YamlFile& file, const YAML::Node& node, const std::string& key);

/// A finite number.
double Number(const YamlFile& file, const YAML::Node& node, const std::string& key);

/// A list of exactly `count` finite numbers; `what` names it in the message, e.g.
/// "[xmin, ymin, xmax, ymax]".
std::vector<double> Numbers(const YamlFile& file, const YAML::Node& node, const std::string& key,
                            size_t count, const std::string& what);

/// A string scalar.
std::string String(const YamlFile& file, const YAML::Node& node, const std::string& key);

/// `relative` resolved against the folder of `yaml_path` (absolute paths are kept).
std::string ResolvePath(const std::string& yaml_path, const std::string& relative);

/// "key.child" (or "child" at the root) and "key[i]".
std::string Child(const std::string& key, const std::string& child);
std::string Item(const std::string& key, size_t index);

}  // namespace acdplan::envs::internal
