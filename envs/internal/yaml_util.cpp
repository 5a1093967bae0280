#include "envs/internal/yaml_util.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "acd/input_error.h"

namespace acdplan::envs::internal {

void YamlFile::Fail(const std::string& key, const std::string& rule) const {
  throw acd::InputError(path + ": " + (key.empty() ? "" : key + ": ") + rule);
}

YamlFile LoadYamlFile(const std::string& path) {
  if (std::filesystem::is_directory(path)) {
    throw acd::InputError(path + ": cannot read file: it is a directory");
  }
  std::ifstream in(path);
  if (!in) throw acd::InputError(path + ": cannot read file: " + std::strerror(errno));
  std::stringstream text;
  text << in.rdbuf();
  YamlFile file{path, {}};
  try {
    file.root = YAML::Load(text.str());
  } catch (const YAML::Exception& error) {
    throw acd::InputError(path + ":" + std::to_string(error.mark.line + 1) +
                          ": YAML syntax error: " + error.msg);
  }
  if (!file.root.IsMap()) throw acd::InputError(path + ": expected a YAML mapping of keys");
  return file;
}

void CheckKeys(const YamlFile& file, const YAML::Node& node, const std::string& key,
               std::initializer_list<const char*> allowed) {
  for (const auto& entry : node) {
    const std::string name = entry.first.Scalar();
    bool known = false;
    std::string list;
    for (const char* a : allowed) {
      known = known || name == a;
      list += (list.empty() ? "" : ", ") + std::string(a);
    }
    if (!known) file.Fail(Child(key, name), "unknown key (expected one of: " + list + ")");
  }
}

void ExpectMap(const YamlFile& file, const YAML::Node& node, const std::string& key) {
  if (!node.IsMap()) file.Fail(key, "expected a mapping of keys");
}

double Number(const YamlFile& file, const YAML::Node& node, const std::string& key) {
  double value = 0.0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
    file.Fail(key, "expected a finite number");
  }
  return value;
}

std::vector<double> Numbers(const YamlFile& file, const YAML::Node& node, const std::string& key,
                            size_t count, const std::string& what) {
  std::vector<double> values;
  bool ok = node.IsSequence() && node.size() == count;
  for (size_t i = 0; ok && i < count; ++i) {
    double value = 0.0;
    ok =
        node[i].IsScalar() && YAML::convert<double>::decode(node[i], value) && std::isfinite(value);
    values.push_back(value);
  }
  if (!ok) file.Fail(key, "expected " + what + " (" + std::to_string(count) + " finite numbers)");
  return values;
}

std::string String(const YamlFile& file, const YAML::Node& node, const std::string& key) {
  if (!node.IsScalar()) file.Fail(key, "expected a string");
  return node.Scalar();
}

std::string ResolvePath(const std::string& yaml_path, const std::string& relative) {
  const std::filesystem::path p(relative);
  if (p.is_absolute()) return relative;
  const std::filesystem::path folder = std::filesystem::path(yaml_path).parent_path();
  return (folder / p).lexically_normal().string();
}

std::string Child(const std::string& key, const std::string& child) {
  return key.empty() ? child : key + "." + child;
}

std::string Item(const std::string& key, size_t index) {
  return key + "[" + std::to_string(index) + "]";
}

}  // namespace acdplan::envs::internal
