#pragma once
// The workspace YAML format (2D and 3D).

#include <string>

#include "acd/read_polygons.h"
#include "envs/workspace2d.h"
#include "envs/workspace3d.h"

namespace acdplan::envs {

/// Reads a 2D workspace file:
///   description: "one line"                      # optional
///   bounds: [xmin, ymin, xmax, ymax]
///   obstacles:                                   # optional
///     - file: rocks.poly                         # every polygon of a polygon file
///     - polygon: [[x, y], [x, y], [x, y], ...]   # inline outer ring (either orientation)
///       holes: [[[x, y], ...], ...]              # optional
/// Relative paths are resolved against the YAML file's folder.
/// @throws InputError naming the file and the key path, e.g. "world.yaml:
///         obstacles[2].polygon: expected a list of [x, y] pairs", for YAML syntax errors
///         (with the line), unknown keys, wrong types, empty bounds and invalid polygons.
Workspace2d LoadWorkspace2dYaml(const std::string& path,
                                const acd::ReadPolygonsOptions& polygons = {});

/// Writes `workspace` in the format LoadWorkspace2dYaml() reads, inline polygons with
/// shortest round-trip numbers; atomically (a temporary file renamed into place).
/// @throws std::runtime_error "<path>: cannot write the file: <reason>" (base/file_io.h).
void WriteWorkspace2dYaml(const Workspace2d& workspace, const std::string& path);

/// Reads a 3D workspace file:
///   description: "one line"                        # optional
///   bounds: [xmin, ymin, zmin, xmax, ymax, zmax]
///   obstacles:                                     # optional
///     - mesh: chair.obj                            # any format ReadMesh() reads
///       translation: [x, y, z]                     # optional, applied after scale
///       scale: 1.0                                 # optional, > 0
/// @throws InputError as LoadWorkspace2dYaml().
Workspace3d LoadWorkspace3dYaml(const std::string& path);

/// Writes `workspace` in the format LoadWorkspace3dYaml() reads: obstacle k as the OBJ file
/// "<stem>_<k>.obj" beside `path` (shortest round-trip numbers, triangles as given), then the
/// YAML naming them; each file atomically.
/// @throws std::runtime_error "<path>: cannot write the file: <reason>" (base/file_io.h).
void WriteWorkspace3dYaml(const Workspace3d& workspace, const std::string& path);

}  // namespace acdplan::envs
