#pragma once
// The two repairs PrepareMesh() offers: closing holes and uniting closed shells that cross.

#include <Eigen/Core>
#include <optional>
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

/// The union of the closed shells `shells` (triangle lists of `mesh`), each outward-oriented and
/// free of self-intersections, which may cross each other: PMP::corefine_and_compute_union on
/// exact (Epeck) copies, taken in the given order, rounded to doubles at the end. The result
/// depends on the input alone: its vertices in exact lexicographic (x, y, z) order, its
/// triangles (lowest vertex first) sorted. Empty when CGAL cannot form the union (it would not
/// be manifold).
std::optional<TriangleMesh> UniteClosedShells(const TriangleMesh& mesh,
                                              const std::vector<std::vector<int>>& shells);

}  // namespace acdplan::acd::internal
