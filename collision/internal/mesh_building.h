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

}  // namespace acdplan::collision::internal
