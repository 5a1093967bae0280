#pragma once
// Reading validated values out of a YAML file, with errors "<file>: <key path>: <rule>".

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "base/input_error.h"

namespace acdplan {

/// A YAML document and the file it came from. Every accessor checks one value at a key path
/// ("planner.time_limit", "obstacles[2].polygon") and throws InputError
/// "<file>: <key path>: expected <rule>, got <what was there>" when it breaks the rule.
class YamlFile {
 public:
  /// Reads and parses `path`; its root must be a mapping.
  /// @throws InputError "<path>: cannot read the file: <reason>",
  ///         "<path>:<line>: YAML syntax error: <reason>" or
  ///         "<path>: expected a mapping of keys, got <what>".
  static YamlFile Load(const std::string& path);

  /// Parses `text` as if read from a file named `path` (for tests and embedded documents).
  static YamlFile Parse(const std::string& text, const std::string& path);

  const std::string& path() const { return path_; }
  const YAML::Node& root() const { return root_; }

  /// Throws InputError "<path>: <key>: <rule>" ("<path>: <rule>" for the root, key "").
  [[noreturn]] void Fail(const std::string& key, const std::string& rule) const;

  /// How a node is shown in a message: 'text', "a list", "a mapping" or "nothing".
  static std::string Shown(const YAML::Node& node);

  /// Fails unless `node` is a mapping ("expected a mapping of keys, got ...").
  void ExpectMap(const YAML::Node& node, const std::string& key) const;
  /// Fails unless `node` is a mapping whose keys are all in `allowed`
  /// ("<key>.<name>: unknown key (expected one of: ...)").
  void CheckKeys(const YAML::Node& node, const std::string& key,
                 std::initializer_list<const char*> allowed) const;

  /// A finite number for which `accept` holds (any finite number when null); else
  /// "expected <rule>, got <node>".
  double Number(const YAML::Node& node, const std::string& key,
                const std::string& rule = "a finite number",
                bool (*accept)(double) = nullptr) const;
  /// An integer >= `min`; else "expected <rule>, got <node>".
  long long Integer(const YAML::Node& node, const std::string& key, const std::string& rule,
                    long long min) const;
  /// A string scalar.
  std::string String(const YAML::Node& node, const std::string& key) const;
  /// true or false (YAML's spellings: true/false, yes/no, on/off).
  bool Bool(const YAML::Node& node, const std::string& key) const;
  /// A list of finite numbers of any length; `what` describes it in the message.
  std::vector<double> Numbers(const YAML::Node& node, const std::string& key,
                              const std::string& what) const;
  /// A list of exactly `count` finite numbers; `what` names it in the message, e.g.
  /// "[xmin, ymin, xmax, ymax]" gives "expected [xmin, ymin, xmax, ymax] (4 finite numbers)".
  std::vector<double> Numbers(const YAML::Node& node, const std::string& key, size_t count,
                              const std::string& what) const;
  /// A list of strings.
  std::vector<std::string> Strings(const YAML::Node& node, const std::string& key) const;

  /// `parse(String(node, key))` for a name parser such as ParseConcavityMeasure(); its
  /// InputError is reported at `key` ("<path>: <key>: unknown ... (expected one of: ...)").
  template <typename Parse>
  auto Parsed(const YAML::Node& node, const std::string& key, Parse parse) const {
    const std::string name = String(node, key);
    try {
      return parse(name);
    } catch (const InputError& error) {
      Fail(key, error.what());
    }
  }

  /// `relative` resolved against this file's folder (absolute paths are kept).
  std::string ResolvePath(const std::string& relative) const;

  /// "key.child" ("child" at the root) and "key[i]".
  static std::string Child(const std::string& key, const std::string& child);
  static std::string Item(const std::string& key, size_t index);

 private:
  YamlFile(std::string path, YAML::Node root) : path_(std::move(path)), root_(std::move(root)) {}

  std::string path_;
  YAML::Node root_;
};

/// Predicates for YamlFile::Number().
bool Positive(double x);
bool NonNegative(double x);
bool UnitInterval(double x);

}  // namespace acdplan
