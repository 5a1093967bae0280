#pragma once
// One entry point that loads a 2D world of any supported kind.

#include <string>

#include "envs/workspace2d.h"

namespace acdplan::envs {

/// Loads a 2D world from `path`, chosen by extension and content:
///  - `.yaml` / `.yml` with an `image` key: a ROS occupancy map (envs/occupancy_map.h);
///  - other `.yaml` / `.yml`: a workspace file (envs/workspace_yaml.h);
///  - `.map`: a Moving AI grid (envs/moving_ai_map.h);
///  - `.poly`, `.wkt`, `.geojson`, `.json`: the file's polygons as obstacles inside their
///    bounding box grown by 10% of its larger side on every side.
/// @throws acd::InputError from the loader, or for an unknown extension.
Workspace2d LoadWorkspace2d(const std::string& path);

}  // namespace acdplan::envs
