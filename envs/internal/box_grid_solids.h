#pragma once
// Closed box-built solids: the union of the cells of a rectilinear grid that a predicate marks
// solid, as one closed, outward-oriented triangle mesh per face-connected part.

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::envs::internal {

/// The solid cells of the grid with cell walls at `x`, `y`, `z` (each sorted, duplicates
/// allowed and dropped), cell (i, j, k) = [x_i, x_i+1] x [y_j, y_j+1] x [z_k, z_k+1] solid when
/// `solid(its centre)`. Returns one mesh per face-connected set of solid cells: every boundary
/// face of the set split along the grid (so no vertex lies inside another face's edge: no
/// T-junctions), two triangles per face, counter-clockwise seen from outside. A part is a
/// closed 2-manifold unless two of its cells meet only along an edge or at a corner (the
/// callers' layouts avoid that). Parts are ordered by their first cell (x fastest).
/// O(cells) time.
std::vector<acd::TriangleMesh> BoxGridSolids(
    std::vector<double> x, std::vector<double> y, std::vector<double> z,
    const std::function<bool(const Eigen::Vector3d&)>& solid);

}  // namespace acdplan::envs::internal
