#pragma once
// The obstacles of a workspace as exact solids and as convex pieces (ACD component hulls): the
// geometry CollisionWorld and PointLocator are built from.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "acd/polygon2d.h"
#include "acd/triangle_mesh.h"
#include "envs/workspace2d.h"
#include "envs/workspace3d.h"

namespace acdplan::collision {

/// Options for BuildObstacleSet(); `{}` is valid.
struct ObstacleSetOptions {
  /// 2D only: concavity tolerated per ACD component of an obstacle [units]; >= 0. 0 gives an
  /// exact convex decomposition (hull = component); larger values give fewer, looser hulls.
  double tau = 0.02;
  /// 2D only: obstacles become prisms z in [-h/2, h/2] of this height h [units]; > 0. Robots are
  /// extruded to [-h/4, h/4] so that no robot face is coplanar with an obstacle cap.
  double extrusion_height = 1.0;
};

/// One convex piece of an obstacle: an ACD component (2D) or a part of the obstacle's surface
/// (3D, until a 3D ACD exists: a part of acd::PrepareMesh(), a solid with its cavities or a
/// surface patch), with its convex hull.
struct ObstaclePiece {
  int obstacle = 0;         ///< Index of the obstacle this piece belongs to.
  acd::TriangleMesh solid;  ///< The piece's own surface: 2D the extruded component polygon
                            ///< (closed), 3D the part's triangles.
  /// `solid` is closed: every edge has two triangles, so inside/outside is defined by ray
  /// parity (acd::PreparedMesh::closed_parts).
  bool closed = true;
  /// `solid` is convex, so it equals `hull` (2D: every vertex of the component is a strict
  /// vertex of its hull, decided with exact predicates; 3D: never claimed).
  bool convex = false;
  acd::TriangleMesh hull;  ///< Convex hull of `solid`, closed, faces counter-clockwise
                           ///< seen from outside.
  /// #H by 4 half-spaces (n, d) with unit outward n: the hull is { x : n . x <= d for all rows }.
  Eigen::Matrix<double, Eigen::Dynamic, 4> planes;
  Eigen::AlignedBox3d box;  ///< Bounding box of `hull`.
  acd::Polygon2d polygon;   ///< 2D only: the component polygon (exact point location).
};

/// A workspace's obstacles, ready for collision checking and point location.
struct ObstacleSet {
  int dimension = 2;                      ///< 2 or 3.
  Eigen::AlignedBox3d bounds;             ///< Workspace bounds (2D: z in [-h/2, h/2]).
  double extrusion_height = 1.0;          ///< 2D: the prism height used [units].
  std::vector<acd::Polygon2d> polygons;   ///< 2D: the obstacles (prepared).
  std::vector<acd::TriangleMesh> meshes;  ///< Exact obstacle surfaces (2D: extruded prisms).
  std::vector<ObstaclePiece> pieces;      ///< Convex pieces of every obstacle.
  /// Where the hulls come from, for reports: "ACD (Decompose2d, tau = 0.02)" in 2D,
  /// "connected components (no 3D ACD yet)" in 3D.
  std::string hulls_source;
};

/// Builds the pieces of a 2D workspace: each obstacle polygon (the solid) is decomposed with
/// acd::Decompose2d(tau) and every component and its hull are extruded to a prism.
/// O(sum of the decomposition costs).
/// @throws InputError if an option is out of range or an obstacle is invalid.
ObstacleSet BuildObstacleSet(const envs::Workspace2d& workspace,
                             const ObstacleSetOptions& options = {});

/// Builds the pieces of a 3D workspace: one piece per part of each obstacle mesh as
/// acd::PrepareMesh() finds them (without repair: a solid with its cavities, or an edge-connected
/// surface patch of a mesh that is not a solid), with its 3D convex hull (CGAL convex_hull_3).
/// `meshes` holds the cleaned meshes. Meshes that are not solids are accepted here (`closed` is
/// false); exact point location on them is refused later.
/// @throws InputError if a mesh fails acd::CheckTriangleMesh() or has no face of positive
///         area.
ObstacleSet BuildObstacleSet(const envs::Workspace3d& workspace);

/// The number of obstacle triangles (sum over `meshes`).
int TriangleCount(const ObstacleSet& obstacles);

}  // namespace acdplan::collision
