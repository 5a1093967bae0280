#pragma once
// A 3D workspace: a bounds box and obstacle triangle meshes.

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::envs {

/// A 3D planning world: free space is `bounds` minus the solids bounded by `obstacles`.
struct Workspace3d {
  Eigen::AlignedBox3d bounds;  ///< The world box [units]; non-empty.
  std::vector<acd::TriangleMesh>
      obstacles;            ///< Obstacle surfaces (closed meshes for point location).
  std::string description;  ///< One line saying what the world is for; may be empty.
};

}  // namespace acdplan::envs
