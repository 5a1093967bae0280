#pragma once
// Small 3D worlds built in code for the envs and planning tests.

#include <Eigen/Geometry>

#include "acd/triangle_mesh.h"
#include "envs/workspace3d.h"

namespace acdplan::envs::testing {

/// The closed box [low, high], faces counter-clockwise seen from outside.
inline acd::TriangleMesh BoxMesh(const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
  acd::TriangleMesh mesh = acd::Cube(1.0);
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) {
    for (int k = 0; k < 3; ++k) mesh.vertices(i, k) = mesh.vertices(i, k) < 0 ? low[k] : high[k];
  }
  return mesh;
}

/// Bounds [0, 10]^3 split by a wall x in [4.5, 5.5] with a square window of side `side`
/// centred at (5, 5, 5), the wall built of four boxes that touch along faces and touch the
/// bounds.
inline Workspace3d WindowWall(double side) {
  Workspace3d world;
  world.bounds = Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 10, 10));
  const double lo = 5 - side / 2, hi = 5 + side / 2;
  world.obstacles.push_back(BoxMesh({4.5, 0, 0}, {5.5, 10, lo}));    // Below the window.
  world.obstacles.push_back(BoxMesh({4.5, 0, hi}, {5.5, 10, 10}));   // Above.
  world.obstacles.push_back(BoxMesh({4.5, 0, lo}, {5.5, lo, hi}));   // Left.
  world.obstacles.push_back(BoxMesh({4.5, hi, lo}, {5.5, 10, hi}));  // Right.
  world.description = "a wall with a square window";
  return world;
}

}  // namespace acdplan::envs::testing
