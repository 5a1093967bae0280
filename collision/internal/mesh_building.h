#pragma once
// Triangle meshes for the collision module: prisms from polygons, 3D convex hulls, connected
// components, closedness. Internal.

#include <Eigen/Core>
#include <vector>

#include "acd/polygon2d.h"
#include "envs/triangle_mesh.h"

namespace acdplan::collision::internal {

/// `polygon` (prepared: outer CCW, holes CW) extruded to the closed prism z in [z0, z1], caps
/// triangulated by a constrained Delaunay triangulation; faces CCW seen from outside.
envs::TriangleMesh ExtrudePolygon(const acd::Polygon2d& polygon, double z0, double z1);

/// The convex prism over the counter-clockwise convex ring `hull`, z in [z0, z1]; caps are
/// fans; faces CCW seen from outside.
envs::TriangleMesh ExtrudeConvexRing(const acd::Ring2d& hull, double z0, double z1);

/// Convex hull of `points` (CGAL convex_hull_3) as a closed triangle mesh, faces CCW seen from
/// outside. Flat or degenerate point sets are thickened by `thickness` along their missing
/// directions first, so the result always bounds a volume. Requires >= 1 point.
envs::TriangleMesh ConvexHull3(const std::vector<Eigen::Vector3d>& points, double thickness);

/// Outward half-spaces (n, d), |n| = 1, of the closed convex mesh `hull`: one row per face
/// (coplanar faces merged).
Eigen::Matrix<double, Eigen::Dynamic, 4> HullPlanes(const envs::TriangleMesh& hull);

/// `mesh` with vertices at identical positions merged (exact comparison) and triangles that
/// collapse to fewer than three distinct vertices dropped. Mesh files split a vertex wherever
/// its normal or texture coordinate changes; for geometry those copies are one vertex.
envs::TriangleMesh WeldVertices(const envs::TriangleMesh& mesh);

/// The connected components of `mesh` (triangles sharing a vertex), each with its own
/// compacted vertex list, in order of their first triangle.
std::vector<envs::TriangleMesh> ConnectedComponents(const envs::TriangleMesh& mesh);

/// True if every edge of `mesh` is shared by exactly two triangles (a closed surface, so
/// inside and outside are defined by ray parity). `bad_edges` receives the number of edges
/// with one or more than two triangles.
bool IsClosedMesh(const envs::TriangleMesh& mesh, int* bad_edges = nullptr);

}  // namespace acdplan::collision::internal
