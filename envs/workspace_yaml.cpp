#include "envs/workspace_yaml.h"

#include <cmath>
#include <filesystem>

#include "acd/prepare_polygon.h"
#include "acd/read_polygons.h"
#include "acd/repair_polygon.h"
#include "base/file_io.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/yaml_file.h"
#include "envs/mesh_loader.h"

namespace acdplan::envs {
namespace {

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

std::string FormatRing(const acd::Ring2d& ring) {
  std::string text = "[";
  for (size_t i = 0; i < ring.size(); ++i) {
    text +=
        (i ? ", [" : "[") + FormatShortest(ring[i].x()) + ", " + FormatShortest(ring[i].y()) + "]";
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
  return file.root()["description"] ? file.String(file.root()["description"], "description")
                                    : std::string();
}

const YAML::Node Obstacles(const YamlFile& file) {
  const YAML::Node node = file.root()["obstacles"];
  if (node && !node.IsNull() && !node.IsSequence()) file.Fail("obstacles", "expected a list");
  return node;
}

}  // namespace

Workspace2d LoadWorkspace2dYaml(const std::string& path, const acd::ReadPolygonsOptions& polygons) {
  const YamlFile file = YamlFile::Load(path);
  file.CheckKeys(file.root(), "", {"description", "bounds", "obstacles"});
  if (!file.root()["bounds"]) file.Fail("bounds", "missing required key");
  const std::vector<double> b =
      file.Numbers(file.root()["bounds"], "bounds", 4, "[xmin, ymin, xmax, ymax]");
  if (!(b[0] < b[2]) || !(b[1] < b[3])) file.Fail("bounds", "expected xmin < xmax and ymin < ymax");
  Workspace2d workspace;
  workspace.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(b[0], b[1]), Eigen::Vector2d(b[2], b[3]));
  workspace.description = Description(file);
  const YAML::Node obstacles = Obstacles(file);
  for (size_t i = 0; obstacles && i < obstacles.size(); ++i) {
    const std::string key = YamlFile::Item("obstacles", i);
    const YAML::Node& entry = obstacles[i];
    file.ExpectMap(entry, key);
    file.CheckKeys(entry, key, {"file", "polygon", "holes"});
    if (!entry["file"] == !entry["polygon"]) {
      file.Fail(key, "expected exactly one of 'file' or 'polygon'");
    }
    if (entry["file"]) {
      if (entry["holes"]) file.Fail(YamlFile::Child(key, "holes"), "only allowed with 'polygon'");
      const std::string name = file.String(entry["file"], YamlFile::Child(key, "file"));
      for (acd::Polygon2d& polygon : acd::ReadPolygons(file.ResolvePath(name), nullptr, polygons)) {
        workspace.obstacles.push_back(std::move(polygon));
      }
      continue;
    }
    acd::Polygon2d polygon{ReadRing(file, entry["polygon"], YamlFile::Child(key, "polygon")), {}};
    if (const YAML::Node holes = entry["holes"]) {
      if (!holes.IsSequence()) file.Fail(YamlFile::Child(key, "holes"), "expected a list of rings");
      for (size_t h = 0; h < holes.size(); ++h) {
        polygon.holes.push_back(
            ReadRing(file, holes[h], YamlFile::Item(YamlFile::Child(key, "holes"), h)));
      }
    }
    // Rings may touch at points (OGC-valid): the obstacle may become several polygons.
    const std::string where = path + ": " + key;
    std::vector<acd::Polygon2d> prepared;
    if (polygons.repair) {
      acd::RepairedPolygon repaired = acd::RepairPolygon(polygon, where);
      if (polygons.notes) {
        polygons.notes->insert(polygons.notes->end(), repaired.changes.begin(),
                               repaired.changes.end());
      }
      prepared = std::move(repaired.polygons);
    } else {
      prepared = acd::PreparePolygons(polygon, where);
    }
    for (acd::Polygon2d& piece : prepared) workspace.obstacles.push_back(std::move(piece));
  }
  return workspace;
}

void WriteWorkspace2dYaml(const Workspace2d& workspace, const std::string& path) {
  std::string text;
  if (!workspace.description.empty())
    text += "description: " + Quoted(workspace.description) + "\n";
  const Eigen::Vector2d lo = workspace.bounds.min(), hi = workspace.bounds.max();
  text += "bounds: [" + FormatShortest(lo.x()) + ", " + FormatShortest(lo.y()) + ", " +
          FormatShortest(hi.x()) + ", " + FormatShortest(hi.y()) + "]\n";
  text += workspace.obstacles.empty() ? "obstacles: []\n" : "obstacles:\n";
  for (const acd::Polygon2d& obstacle : workspace.obstacles) {
    text += "  - polygon: " + FormatRing(obstacle.outer) + "\n";
    if (!obstacle.holes.empty()) {
      text += "    holes:\n";
      for (const acd::Ring2d& hole : obstacle.holes) text += "      - " + FormatRing(hole) + "\n";
    }
  }
  WriteFileAtomically(path, text);
}

Workspace3d LoadWorkspace3dYaml(const std::string& path) {
  const YamlFile file = YamlFile::Load(path);
  file.CheckKeys(file.root(), "", {"description", "bounds", "obstacles"});
  if (!file.root()["bounds"]) file.Fail("bounds", "missing required key");
  const std::vector<double> b =
      file.Numbers(file.root()["bounds"], "bounds", 6, "[xmin, ymin, zmin, xmax, ymax, zmax]");
  if (!(b[0] < b[3]) || !(b[1] < b[4]) || !(b[2] < b[5])) {
    file.Fail("bounds", "expected xmin < xmax, ymin < ymax and zmin < zmax");
  }
  Workspace3d workspace;
  workspace.bounds =
      Eigen::AlignedBox3d(Eigen::Vector3d(b[0], b[1], b[2]), Eigen::Vector3d(b[3], b[4], b[5]));
  workspace.description = Description(file);
  const YAML::Node obstacles = Obstacles(file);
  for (size_t i = 0; obstacles && i < obstacles.size(); ++i) {
    const std::string key = YamlFile::Item("obstacles", i);
    const YAML::Node& entry = obstacles[i];
    file.ExpectMap(entry, key);
    file.CheckKeys(entry, key, {"mesh", "translation", "scale"});
    if (!entry["mesh"]) file.Fail(YamlFile::Child(key, "mesh"), "missing required key");
    const std::string name = file.String(entry["mesh"], YamlFile::Child(key, "mesh"));
    double scale = 1.0;
    if (entry["scale"]) {
      scale = file.Number(entry["scale"], YamlFile::Child(key, "scale"));
      if (!(scale > 0.0)) file.Fail(YamlFile::Child(key, "scale"), "expected a number > 0");
    }
    Eigen::RowVector3d translation = Eigen::RowVector3d::Zero();
    if (entry["translation"]) {
      const std::vector<double> t =
          file.Numbers(entry["translation"], YamlFile::Child(key, "translation"), 3, "[x, y, z]");
      translation << t[0], t[1], t[2];
    }
    acd::TriangleMesh mesh = ReadMesh(file.ResolvePath(name));
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
      mesh.vertices.row(v) = mesh.vertices.row(v) * scale + translation;
    }
    workspace.obstacles.push_back(std::move(mesh));
  }
  return workspace;
}

void WriteWorkspace3dYaml(const Workspace3d& workspace, const std::string& path) {
  const std::filesystem::path yaml(path);
  const std::string stem = yaml.stem().string();
  std::string text;
  if (!workspace.description.empty())
    text += "description: " + Quoted(workspace.description) + "\n";
  const Eigen::Vector3d lo = workspace.bounds.min(), hi = workspace.bounds.max();
  text += "bounds: [" + FormatShortest(lo.x()) + ", " + FormatShortest(lo.y()) + ", " +
          FormatShortest(lo.z()) + ", " + FormatShortest(hi.x()) + ", " + FormatShortest(hi.y()) +
          ", " + FormatShortest(hi.z()) + "]\n";
  text += workspace.obstacles.empty() ? "obstacles: []\n" : "obstacles:\n";
  for (size_t k = 0; k < workspace.obstacles.size(); ++k) {
    const acd::TriangleMesh& mesh = workspace.obstacles[k];
    const std::string name = stem + "_" + std::to_string(k) + ".obj";
    std::string obj = "# " + stem + " obstacle " + std::to_string(k) + "\n";
    for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
      obj += "v " + FormatShortest(mesh.vertices(v, 0)) + " " +
             FormatShortest(mesh.vertices(v, 1)) + " " + FormatShortest(mesh.vertices(v, 2)) + "\n";
    }
    for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
      obj += "f " + std::to_string(mesh.triangles(f, 0) + 1) + " " +
             std::to_string(mesh.triangles(f, 1) + 1) + " " +
             std::to_string(mesh.triangles(f, 2) + 1) + "\n";
    }
    WriteFileAtomically((yaml.parent_path() / name).string(), obj);
    text += "  - mesh: " + name + "\n";
  }
  WriteFileAtomically(path, text);
}

}  // namespace acdplan::envs
