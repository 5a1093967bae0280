#include "envs/load_workspace.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "acd/read_polygons.h"
#include "base/input_error.h"
#include "base/yaml_file.h"
#include "envs/internal/file_extension.h"
#include "envs/mesh_loader.h"
#include "envs/moving_ai_map.h"
#include "envs/occupancy_map.h"
#include "envs/workspace_yaml.h"

namespace acdplan::envs {

namespace {

using internal::LowerExtension;

// A workspace YAML is 3D when its bounds have six numbers or an obstacle names a mesh; the 3D
// loader then reports any other mistake with its key path.
bool IsWorkspace3dYaml(const YamlFile& file) {
  const YAML::Node bounds = file.root()["bounds"];
  if (bounds && bounds.IsSequence() && bounds.size() == 6) return true;
  const YAML::Node obstacles = file.root()["obstacles"];
  if (!obstacles || !obstacles.IsSequence()) return false;
  for (const YAML::Node& entry : obstacles) {
    if (entry.IsMap() && entry["mesh"]) return true;
  }
  return false;
}

}  // namespace

Workspace2d LoadWorkspace2d(const std::string& path, const acd::ReadPolygonsOptions& polygons,
                            const OccupancyMapOptions& map) {
  const std::string extension = LowerExtension(path);
  if (extension == ".yaml" || extension == ".yml") {
    if (YamlFile::Load(path).root()["image"]) return LoadOccupancyMap(path, map);
    return LoadWorkspace2dYaml(path, polygons);
  }
  if (extension == ".map") return LoadMovingAiMap(path);
  if (acd::IsPolygonFile(path)) {
    Workspace2d workspace;
    workspace.obstacles = acd::ReadPolygons(path, nullptr, polygons);
    for (const acd::Polygon2d& polygon : workspace.obstacles) {
      for (const acd::Point2d& p : polygon.outer) workspace.bounds.extend(p);
    }
    const double margin = 0.1 * workspace.bounds.sizes().maxCoeff();
    workspace.bounds.min().array() -= margin;
    workspace.bounds.max().array() += margin;
    workspace.description = "obstacles from " + path;
    return workspace;
  }
  throw InputError(path + ": unknown world file extension '" + extension +
                   "' (expected .yaml, .yml, .map, " + acd::kPolygonFileExtensions + ")");
}

World LoadWorld(const std::string& path, const acd::ReadPolygonsOptions& polygons,
                const OccupancyMapOptions& map) {
  const std::string extension = LowerExtension(path);
  World world;
  if (IsMeshFile(path)) {
    world.dimension = 3;
    world.kind = "mesh";
    acd::TriangleMesh mesh = ReadMesh(path);
    Eigen::AlignedBox3d box = acd::BoundingBox(mesh);
    const double margin = 0.1 * box.sizes().maxCoeff();
    box.min().array() -= margin;
    box.max().array() += margin;
    world.workspace3d.bounds = box;
    world.workspace3d.obstacles.push_back(std::move(mesh));
    world.workspace3d.description = "the mesh " + path;
    return world;
  }
  if (extension == ".yaml" || extension == ".yml") {
    const YamlFile file = YamlFile::Load(path);
    if (file.root()["image"]) {
      world.kind = "occupancy map";
      world.workspace2d = LoadOccupancyMap(path, map);
    } else if (IsWorkspace3dYaml(file)) {
      world.dimension = 3;
      world.kind = "3D workspace";
      world.workspace3d = LoadWorkspace3dYaml(path);
    } else {
      world.kind = "workspace";
      world.workspace2d = LoadWorkspace2dYaml(path, polygons);
    }
    return world;
  }
  if (extension != ".map" && !acd::IsPolygonFile(path)) {
    throw InputError(path + ": unknown world file extension '" + extension +
                     "' (expected .yaml, .yml, .map, " + acd::kPolygonFileExtensions +
                     ", or a mesh: " + kMeshFileExtensions + ")");
  }
  world.kind = extension == ".map" ? "Moving AI map" : "polygon file";
  world.workspace2d = LoadWorkspace2d(path, polygons, map);
  return world;
}

}  // namespace acdplan::envs
