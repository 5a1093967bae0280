#pragma once
// Closing the holes of a mesh: the first of PrepareMesh()'s repairs.

#include <Eigen/Core>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

/// Triangles that close the holes of `mesh` (cleaned: no degenerate or repeated triangles).
struct HoleFilling {
  std::vector<Eigen::Vector3i> triangles;  ///< New triangles over `mesh`'s vertices.
  int filled = 0;                          ///< Boundary loops closed.
  int failed = 0;                          ///< Loops left open (no triangulation found, or the
                                           ///< boundary did not close into a loop).
};

/// Finds the boundary loops of `mesh` (edges with one triangle, chained head to tail in the
/// direction opposite their triangle's; a loop through a vertex twice is split there) and
/// triangulates each without new vertices: PMP::triangulate_hole_polyline with the 2D
/// constrained Delaunay triangulation when the loop is nearly planar, else its minimum
/// dihedral-angle/area triangulation over a 3D Delaunay search space. Loops are taken in order
/// of their lowest boundary edge, so the result is reproducible. The new triangles' orientation
/// is not settled: the caller orients the whole mesh again.
HoleFilling FillHoles(const TriangleMesh& mesh);

}  // namespace acdplan::acd::internal
