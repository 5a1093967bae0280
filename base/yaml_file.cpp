#include "base/yaml_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "base/file_io.h"
#include "base/input_error.h"

namespace acdplan {
namespace {

// yaml-cpp throws on the type query of an invalid node (a missing key of a const mapping);
// here a missing value is simply not of the type asked for.
bool IsScalar(const YAML::Node& node) { return node.IsDefined() && node.IsScalar(); }
bool IsSequence(const YAML::Node& node) { return node.IsDefined() && node.IsSequence(); }
bool IsMap(const YAML::Node& node) { return node.IsDefined() && node.IsMap(); }

}  // namespace

YamlFile YamlFile::Load(const std::string& path) { return Parse(ReadFile(path), path); }

YamlFile YamlFile::Parse(const std::string& text, const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& error) {
    throw InputError(path + ":" + std::to_string(error.mark.line + 1) +
                     ": YAML syntax error: " + error.msg);
  }
  YamlFile file(path, root);
  file.ExpectMap(root, "");
  return file;
}

void YamlFile::Fail(const std::string& key, const std::string& rule) const {
  throw InputError(path_ + ": " + (key.empty() ? "" : key + ": ") + rule);
}

std::string YamlFile::Shown(const YAML::Node& node) {
  if (IsScalar(node)) return "'" + node.Scalar() + "'";
  if (IsSequence(node)) return "a list";
  if (IsMap(node)) return "a mapping";
  return "nothing";
}

void YamlFile::ExpectMap(const YAML::Node& node, const std::string& key) const {
  if (!IsMap(node)) Fail(key, "expected a mapping of keys, got " + Shown(node));
}

void YamlFile::CheckKeys(const YAML::Node& node, const std::string& key,
                         std::initializer_list<const char*> allowed) const {
  ExpectMap(node, key);
  for (const auto& entry : node) {
    const std::string name = entry.first.Scalar();
    if (std::none_of(allowed.begin(), allowed.end(), [&](const char* a) { return name == a; })) {
      Fail(Child(key, name),
           "unknown key (expected one of: " + JoinNames({allowed.begin(), allowed.end()}) + ")");
    }
  }
}

double YamlFile::Number(const YAML::Node& node, const std::string& key, const std::string& rule,
                        bool (*accept)(double)) const {
  double value = 0;
  if (!IsScalar(node) || !YAML::convert<double>::decode(node, value) || !std::isfinite(value) ||
      (accept && !accept(value))) {
    Fail(key, "expected " + rule + ", got " + Shown(node));
  }
  return value;
}

long long YamlFile::Integer(const YAML::Node& node, const std::string& key, const std::string& rule,
                            long long min) const {
  long long value = 0;
  if (!IsScalar(node) || !YAML::convert<long long>::decode(node, value) || value < min) {
    Fail(key, "expected " + rule + ", got " + Shown(node));
  }
  return value;
}

std::string YamlFile::String(const YAML::Node& node, const std::string& key) const {
  if (!IsScalar(node)) Fail(key, "expected a string, got " + Shown(node));
  return node.Scalar();
}

bool YamlFile::Bool(const YAML::Node& node, const std::string& key) const {
  bool value = false;
  if (!IsScalar(node) || !YAML::convert<bool>::decode(node, value)) {
    Fail(key, "expected true or false, got " + Shown(node));
  }
  return value;
}

std::vector<double> YamlFile::Numbers(const YAML::Node& node, const std::string& key,
                                      const std::string& what) const {
  if (!IsSequence(node)) Fail(key, "expected " + what + ", got " + Shown(node));
  std::vector<double> values;
  for (size_t i = 0; i < node.size(); ++i) values.push_back(Number(node[i], Item(key, i)));
  return values;
}

std::vector<double> YamlFile::Numbers(const YAML::Node& node, const std::string& key, size_t count,
                                      const std::string& what) const {
  std::vector<double> values;
  bool ok = IsSequence(node) && node.size() == count;
  for (size_t i = 0; ok && i < count; ++i) {
    double value = 0.0;
    ok = IsScalar(node[i]) && YAML::convert<double>::decode(node[i], value) && std::isfinite(value);
    values.push_back(value);
  }
  if (!ok) {
    Fail(key, "expected " + what + " (" + std::to_string(count) + " finite numbers), got " +
                  Shown(node));
  }
  return values;
}

std::vector<std::string> YamlFile::Strings(const YAML::Node& node, const std::string& key) const {
  if (!IsSequence(node)) Fail(key, "expected a list of names, got " + Shown(node));
  std::vector<std::string> values;
  for (size_t i = 0; i < node.size(); ++i) values.push_back(String(node[i], Item(key, i)));
  return values;
}

std::string YamlFile::ResolvePath(const std::string& relative) const {
  const std::filesystem::path p(relative);
  if (p.is_absolute()) return relative;
  return (std::filesystem::path(path_).parent_path() / p).lexically_normal().string();
}

std::string YamlFile::Child(const std::string& key, const std::string& child) {
  return key.empty() ? child : key + "." + child;
}

std::string YamlFile::Item(const std::string& key, size_t index) {
  return key + "[" + std::to_string(index) + "]";
}

bool Positive(double x) { return x > 0; }
bool NonNegative(double x) { return x >= 0; }
bool UnitInterval(double x) { return x >= 0 && x <= 1; }

}  // namespace acdplan
