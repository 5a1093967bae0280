#pragma once
// One entry point that loads a 2D world of any supported kind.

#include <string>

#include "acd/read_polygons.h"
#include "envs/occupancy_map.h"
#include "envs/workspace2d.h"
#include "envs/workspace3d.h"

namespace acdplan::envs {

/// Loads a 2D world from `path`, chosen by extension and content:
///  - `.yaml` / `.yml` with an `image` key: a ROS occupancy map (envs/occupancy_map.h);
///  - other `.yaml` / `.yml`: a workspace file (envs/workspace_yaml.h);
///  - `.map`: a Moving AI grid (envs/moving_ai_map.h);
///  - a polygon file (acd::IsPolygonFile()): its polygons as obstacles inside their bounding
///    box grown by 10% of its larger side on every side.
/// `polygons` says how obstacle polygons (from polygon files, inline in a workspace YAML or
/// files it names) are read: strictly by default; with `repair`, invalid ones are made valid
/// (acd::RepairPolygon) and each change is a line of `notes`. `map` says how an occupancy map
/// is read (its unknown cells blocked by default).
/// @throws InputError from the loader, or for an unknown extension.
Workspace2d LoadWorkspace2d(const std::string& path, const acd::ReadPolygonsOptions& polygons = {},
                            const OccupancyMapOptions& map = {});

/// A world of either dimension, and what kind of file it came from.
struct World {
  int dimension = 2;  ///< 2: `workspace2d` holds it; 3: `workspace3d`.
  std::string kind;   ///< "workspace", "occupancy map", "Moving AI map",
                      ///< "polygon file", "3D workspace" or "mesh".
  Workspace2d workspace2d;
  Workspace3d workspace3d;
};

/// Loads any world file: everything LoadWorkspace2d() reads, a 3D workspace YAML (six bounds
/// numbers or `mesh` obstacles, envs/workspace_yaml.h), or a single mesh that ReadMesh() reads
/// (.obj, .stl, .ply, .off, .dae, .gltf, .glb) as the one obstacle inside its bounding box grown
/// by 10% of its larger side.
/// `polygons` and `map` as for LoadWorkspace2d().
/// @throws InputError from the loader, or for an unknown extension.
World LoadWorld(const std::string& path, const acd::ReadPolygonsOptions& polygons = {},
                const OccupancyMapOptions& map = {});

}  // namespace acdplan::envs
