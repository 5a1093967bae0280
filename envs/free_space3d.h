#pragma once
// The free space of a 3D workspace: the bounds box minus the union of the obstacles.

#include <string>
#include <vector>

#include "acd/triangle_mesh.h"
#include "envs/workspace3d.h"

namespace acdplan::envs {

/// What FreeSpace3d() returns.
struct FreeSpace3dResult {
  /// The free space's boundary: closed, faces counter-clockwise seen from the free side (outer
  /// shells outward, the shells around obstacles that float inside the bounds -- cavities --
  /// inward), so acd::PrepareMesh() calls it a solid, possibly of several parts. Empty when
  /// the obstacles cover the bounds.
  acd::TriangleMesh mesh;
  double volume = 0.0;  ///< Enclosed volume of `mesh` [units^3].
  /// One line per obstacle that was not subtracted, with the reason ("obstacle 2: open surface
  /// (...): left to the collision checker").
  std::vector<std::string> notes;
};

/// The free space `workspace.bounds` minus the union of `workspace.obstacles`, computed with
/// exact Boolean operations (CGAL Polygon_mesh_processing corefinement on an exact kernel,
/// one obstacle after the other) and rounded to doubles once at the end.
///
/// Obstacles may overlap, touch each other or the bounds, cross the bounds or lie outside.
/// Open obstacle meshes: each obstacle goes through acd::PrepareMesh() with repair, which
/// closes its holes (boundary loops triangulated, e.g. a box missing a face becomes the box);
/// an obstacle that is still not a solid (a lone sheet, a non-manifold or self-crossing
/// surface) has no inside to subtract, so it is left out of the free space -- the free space
/// then over-estimates, which only costs the sampler some wasted samples -- and named in
/// `notes`; the collision checker still sees its surface. So is an obstacle whose exact
/// difference CGAL cannot form as a 2-manifold (e.g. two obstacles meeting along an edge).
/// Complexity: one corefinement per obstacle, O((n + k) log n) each for n triangles and k
/// intersections.
/// @throws InputError if the bounds are empty or an obstacle fails acd::CheckTriangleMesh().
FreeSpace3dResult FreeSpace3d(const Workspace3d& workspace);

}  // namespace acdplan::envs
