#include "envs/workspace_yaml.h"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "acd/input_error.h"
#include "acd/prepare_polygon.h"
#include "acd/read_polygons.h"
#include "envs/internal/yaml_util.h"
#include "envs/mesh_loader.h"

namespace acdplan::envs {
namespace {

using internal::Child;
using internal::Item;
using internal::YamlFile;

acd::Ring2d ReadRing(const YamlFile& file, const YAML::Node& node, const std::string& key) {
  const std::string rule = "expected a list of [x, y] pairs";
  if (!node.IsSequence() || node.size() < 3) file.Fail(key, rule + " (at least 3)");
  acd::Ring2d ring;
  for (size_t i = 0; i < node.size(); ++i) {
    const YAML::Node& pair = node[i];
    double x = 0.0, y = 0.0;
    if (!pair.IsSequence() || pair.size() != 2 || !pair[0].IsScalar() || !pair[1].IsScalar() ||
        !YAML::convert<double>::decode(pair[0], x) || !YAML::convert<double>::decode(pair[1], y) ||
        !std::isfinite(x) || !std::isfinite(y)) {
      file.Fail(key, rule + ": element " + std::to_string(i) + " is not a pair of finite numbers");
    }
    ring.emplace_back(x, y);
  }
  return ring;
}

std::string FormatNumber(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string FormatRing(const acd::Ring2d& ring) {
  std::string text = "[";
  for (size_t i = 0; i < ring.size(); ++i) {
    text += (i ? ", [" : "[") + FormatNumber(ring[i].x()) + ", " + FormatNumber(ring[i].y()) + "]";
  }
  return text + "]";
}

std::string Quoted(const std::string& text) {
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c == '\n' ? ' ' : c;
  }
  return quoted + "\"";
}

std::string Description(const YamlFile& file) {
  return file.root["description"] ? internal::String(file, file.root["description"], "description")
                                  : std::string();
}

const YAML::Node Obstacles(const YamlFile& file) {
  const YAML::Node node = file.root["obstacles"];
  if (node && !node.IsNull() && !node.IsSequence()) file.Fail("obstacles", "expected a list");
  return node;
}

}  // namespace

Workspace2d LoadWorkspace2dYaml(const std::string& path) {
  const YamlFile file = internal::LoadYamlFile(path);
  internal::CheckKeys(file, file.root, "", {"description", "bounds", "obstacles"});
  if (!file.root["bounds"]) file.Fail("bounds", "missing required key");
  const std::vector<double> b =
      internal::Numbers(file, file.root["bounds"], "bounds", 4, "[xmin, ymin, xmax, ymax]");
  if (!(b[0] < b[2]) || !(b[1] < b[3])) file.Fail("bounds", "expected xmin < xmax and ymin < ymax");
  Workspace2d workspace;
  workspace.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(b[0], b[1]), Eigen::Vector2d(b[2], b[3]));
  workspace.description = Description(file);
  const YAML::Node obstacles = Obstacles(file);
  for (size_t i = 0; obstacles && i < obstacles.size(); ++i) {
    const std::string key = Item("obstacles", i);
    const YAML::Node& entry = obstacles[i];
    internal::ExpectMap(file, entry, key);
    internal::CheckKeys(file, entry, key, {"file", "polygon", "holes"});
    if (!entry["file"] == !entry["polygon"]) {
      file.Fail(key, "expected exactly one of 'file' or 'polygon'");
    }
    if (entry["file"]) {
      if (entry["holes"]) file.Fail(Child(key, "holes"), "only allowed with 'polygon'");
      const std::string name = internal::String(file, entry["file"], Child(key, "file"));
      for (acd::Polygon2d& polygon : acd::ReadPolygons(internal::ResolvePath(path, name))) {
        workspace.obstacles.push_back(std::move(polygon));
      }
      continue;
    }
    acd::Polygon2d polygon{ReadRing(file, entry["polygon"], Child(key, "polygon")), {}};
    if (const YAML::Node holes = entry["holes"]) {
      if (!holes.IsSequence()) file.Fail(Child(key, "holes"), "expected a list of rings");
      for (size_t h = 0; h < holes.size(); ++h) {
        polygon.holes.push_back(ReadRing(file, holes[h], Item(Child(key, "holes"), h)));
      }
    }
    workspace.obstacles.push_back(acd::PreparePolygon(polygon, path + ": " + key));
  }
  return workspace;
}

void WriteWorkspace2dYaml(const Workspace2d& workspace, const std::string& path) {
  std::string text;
  if (!workspace.description.empty())
    text += "description: " + Quoted(workspace.description) + "\n";
  const Eigen::Vector2d lo = workspace.bounds.min(), hi = workspace.bounds.max();
  text += "bounds: [" + FormatNumber(lo.x()) + ", " + FormatNumber(lo.y()) + ", " +
          FormatNumber(hi.x()) + ", " + FormatNumber(hi.y()) + "]\n";
  text += workspace.obstacles.empty() ? "obstacles: []\n" : "obstacles:\n";
  for (const acd::Polygon2d& obstacle : workspace.obstacles) {
    text += "  - polygon: " + FormatRing(obstacle.outer) + "\n";
    if (!obstacle.holes.empty()) {
      text += "    holes:\n";
      for (const acd::Ring2d& hole : obstacle.holes) text += "      - " + FormatRing(hole) + "\n";
    }
  }
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw acd::InputError(path + ": cannot write file: " + std::strerror(errno));
    out << text;
    out.close();
    if (!out) throw acd::InputError(path + ": cannot write file: write error");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw acd::InputError(path + ": cannot write file: " + reason);
  }
}

Workspace3d LoadWorkspace3dYaml(const std::string& path) {
  const YamlFile file = internal::LoadYamlFile(path);
  internal::CheckKeys(file, file.root, "", {"description", "bounds", "obstacles"});
  if (!file.root["bounds"]) file.Fail("bounds", "missing required key");
  const std::vector<double> b = internal::Numbers(file, file.root["bounds"], "bounds", 6,
                                                  "[xmin, ymin, zmin, xmax, ymax, zmax]");
  if (!(b[0] < b[3]) || !(b[1] < b[4]) || !(b[2] < b[5])) {
    file.Fail("bounds", "expected xmin < xmax, ymin < ymax and zmin < zmax");
  }
  Workspace3d workspace;
  workspace.bounds =
      Eigen::AlignedBox3d(Eigen::Vector3d(b[0], b[1], b[2]), Eigen::Vector3d(b[3], b[4], b[5]));
  workspace.description = Description(file);
  const YAML::Node obstacles = Obstacles(file);
  for (size_t i = 0; obstacles && i < obstacles.size(); ++i) {
    const std::string key = Item("obstacles", i);
    const YAML::Node& entry = obstacles[i];
    internal::ExpectMap(file, entry, key);
    internal::CheckKeys(file, entry, key, {"mesh", "translation", "scale"});
    if (!entry["mesh"]) file.Fail(Child(key, "mesh"), "missing required key");
    const std::string name = internal::String(file, entry["mesh"], Child(key, "mesh"));
    double scale = 1.0;
    if (entry["scale"]) {
      scale = internal::Number(file, entry["scale"], Child(key, "scale"));
      if (!(scale > 0.0)) file.Fail(Child(key, "scale"), "expected a number > 0");
    }
    Eigen::RowVector3d translation = Eigen::RowVector3d::Zero();
    if (entry["translation"]) {
      const std::vector<double> t =
          internal::Numbers(file, entry["translation"], Child(key, "translation"), 3, "[x, y, z]");
      translation << t[0], t[1], t[2];
    }
    TriangleMesh mesh = ReadMesh(internal::ResolvePath(path, name));
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
      mesh.vertices.row(v) = mesh.vertices.row(v) * scale + translation;
    }
    workspace.obstacles.push_back(std::move(mesh));
  }
  return workspace;
}

}  // namespace acdplan::envs
