#pragma once
// Volume, area and centroids of triangle meshes.

#include <Eigen/Core>

#include "acd/triangle_mesh.h"

namespace acdplan::acd {

/// Signed volume enclosed by `mesh` [units^3]: positive for a closed mesh whose faces are CCW
/// seen from outside. Tetrahedra are summed about the first vertex, not the origin, so that far
/// meshes keep their precision. Meaningless for an open mesh.
double MeshVolume(const TriangleMesh& mesh);

/// Total triangle area [units^2].
double MeshArea(const TriangleMesh& mesh);

/// Centroid of the enclosed volume of a closed mesh; of the surface (area-weighted) when the
/// volume is zero or the mesh is open (`solid` false).
Eigen::Vector3d MeshCentroid(const TriangleMesh& mesh, bool solid);

}  // namespace acdplan::acd
