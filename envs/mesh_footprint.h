#pragma once
// The footprint of a planar mesh in the xy plane: how a 2D problem given as meshes (OMPL.app's
// resources/2D) becomes a Workspace2d and a polygon robot.

#include <string>
#include <vector>

#include "acd/polygon2d.h"
#include "acd/triangle_mesh.h"

namespace acdplan::envs {

/// Options for Footprint(); `{}` is valid.
struct FootprintOptions {
  /// Triangles whose z-range misses [z_min, z_max] are skipped (they cannot touch a planar
  /// robot that lives in that slab); the default keeps every triangle.
  double z_min = -1e300;
  double z_max = 1e300;
};

/// The footprint of a planar (2D-problem) mesh: the exact union of its triangles projected to
/// the xy plane (CGAL Boolean_set_operations_2 on exact constructions), triangles seen edge-on
/// skipped, converted to doubles and cleaned by acd::PreparePolygons(): valid polygons with
/// holes, one per connected part. Empty when every triangle is edge-on or skipped.
/// @throws InputError "<where>: ..." if a footprint polygon is invalid after rounding.
std::vector<acd::Polygon2d> Footprint(const acd::TriangleMesh& mesh, const std::string& where,
                                      const FootprintOptions& options = {});

/// Footprint() for a robot: exactly one polygon is required.
/// @throws InputError "<where>: the robot's footprint has N separate parts (a rigid robot
///         needs one outline)" or "<where>: the robot's footprint is empty (...)".
acd::Polygon2d FootprintOutline(const acd::TriangleMesh& mesh, const std::string& where);

}  // namespace acdplan::envs
