#include "envs/load_workspace.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "acd/input_error.h"
#include "acd/read_polygons.h"
#include "envs/internal/yaml_util.h"
#include "envs/moving_ai_map.h"
#include "envs/occupancy_map.h"
#include "envs/workspace_yaml.h"

namespace acdplan::envs {

Workspace2d LoadWorkspace2d(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".yaml" || extension == ".yml") {
    if (internal::LoadYamlFile(path).root["image"]) return LoadOccupancyMap(path);
    return LoadWorkspace2dYaml(path);
  }
  if (extension == ".map") return LoadMovingAiMap(path);
  if (extension == ".poly" || extension == ".wkt" || extension == ".geojson" ||
      extension == ".json") {
    Workspace2d workspace;
    workspace.obstacles = acd::ReadPolygons(path);
    for (const acd::Polygon2d& polygon : workspace.obstacles) {
      for (const acd::Point2d& p : polygon.outer) workspace.bounds.extend(p);
    }
    const double margin = 0.1 * workspace.bounds.sizes().maxCoeff();
    workspace.bounds.min().array() -= margin;
    workspace.bounds.max().array() += margin;
    workspace.description = "obstacles from " + path;
    return workspace;
  }
  throw acd::InputError(path + ": unknown world file extension '" + extension +
                        "' (expected .yaml, .yml, .map, .poly, .wkt, .geojson or .json)");
}

}  // namespace acdplan::envs
