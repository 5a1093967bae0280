#pragma once
// Prisms from polygons for the collision module (2D obstacles and robots as solids), sub-meshes
// and the exact "piece equals its hull" test for the 3D ACD pieces. Internal;
// cleaning, parts and closedness of 3D meshes are acd::PrepareMesh()'s.

#include <Eigen/Core>
#include <vector>

#include "acd/polygon2d.h"
#include "acd/triangle_mesh.h"

namespace acdplan::collision::internal {

/// `polygon` (prepared: outer CCW, holes CW) extruded to the closed prism z in [z0, z1], caps
/// triangulated by a constrained Delaunay triangulation; faces CCW seen from outside.
acd::TriangleMesh ExtrudePolygon(const acd::Polygon2d& polygon, double z0, double z1);

/// The convex prism over the counter-clockwise convex ring `hull`, z in [z0, z1]; caps are
/// fans; faces CCW seen from outside.
acd::TriangleMesh ExtrudeConvexRing(const acd::Ring2d& hull, double z0, double z1);

/// The triangles `triangles` (row indices) of `mesh`, with only the vertices they use.
acd::TriangleMesh SubMesh(const acd::TriangleMesh& mesh, const std::vector<int>& triangles);

/// True if the closed mesh `piece` equals `hull`, its convex hull: every face of `piece` spans a
/// supporting plane of `hull` with `hull` on its inner side (no vertex of `hull` strictly
/// outside, by CGAL's exact orientation predicate on the double coordinates), so the surface of
/// `piece` lies in the boundary of `hull`, and a closed surface inside the boundary of a convex
/// body is all of it. Requires a closed `piece` (every edge on two triangles) with faces
/// counter-clockwise seen from outside. O(faces x hull vertices), stopping at the first face
/// that fails.
bool EqualsItsHull(const acd::TriangleMesh& piece, const acd::TriangleMesh& hull);

}  // namespace acdplan::collision::internal
