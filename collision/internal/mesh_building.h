#pragma once
// Prisms from polygons for the collision module (2D obstacles and robots as solids). Internal;
// cleaning, parts and closedness of 3D meshes are acd::PrepareMesh()'s.

#include <Eigen/Core>

#include "acd/polygon2d.h"
#include "acd/triangle_mesh.h"

namespace acdplan::collision::internal {

/// `polygon` (prepared: outer CCW, holes CW) extruded to the closed prism z in [z0, z1], caps
/// triangulated by a constrained Delaunay triangulation; faces CCW seen from outside.
acd::TriangleMesh ExtrudePolygon(const acd::Polygon2d& polygon, double z0, double z1);

/// The convex prism over the counter-clockwise convex ring `hull`, z in [z0, z1]; caps are
/// fans; faces CCW seen from outside.
acd::TriangleMesh ExtrudeConvexRing(const acd::Ring2d& hull, double z0, double z1);

<<<<<<< HEAD
/// `mesh` with vertices at identical positions merged (exact comparison) and triangles that
/// collapse to fewer than three distinct vertices dropped. Mesh files split a vertex wherever
/// its normal or texture coordinate changes; for geometry those copies are one vertex.
acd::TriangleMesh WeldVertices(const acd::TriangleMesh& mesh);

/// The connected components of `mesh` (triangles sharing a vertex), each with its own
/// compacted vertex list, in order of their first triangle.
std::vector<acd::TriangleMesh> ConnectedComponents(const acd::TriangleMesh& mesh);

/// True if every edge of `mesh` is shared by exactly two triangles (a closed surface, so
/// inside and outside are defined by ray parity). `bad_edges` receives the number of edges
/// with one or more than two triangles.
bool IsClosedMesh(const acd::TriangleMesh& mesh, int* bad_edges = nullptr);

/// The triangles `triangles` (row indices) of `mesh`, with only the vertices they use.
acd::TriangleMesh SubMesh(const acd::TriangleMesh& mesh, const std::vector<int>& triangles);

/// True if the closed mesh `piece` equals `hull`, its convex hull: every face of `piece` spans a
/// supporting plane of `hull` with `hull` on its inner side (no vertex of `hull` strictly
/// outside, by CGAL's exact orientation predicate on the double coordinates), so the surface of
/// `piece` lies in the boundary of `hull`, and a closed surface inside the boundary of a convex
/// body is all of it. Requires IsClosedMesh(piece) and faces counter-clockwise seen from
/// outside. O(faces x hull vertices), stopping at the first face that fails.
bool EqualsItsHull(const acd::TriangleMesh& piece, const acd::TriangleMesh& hull);

=======
>>>>>>> main
}  // namespace acdplan::collision::internal
