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
  /// 3D only: concavity tolerated per ACD component of an obstacle, relative to the
  /// acd::ReferenceRadius of each part of the obstacle (ObstacleComponent; tau = tau_rel_3d x
  /// radius); > 0. The default is the finest of the dissertation's settings (0.2, 0.05, 0.02):
  /// hull point location errs on <= 1% of the points of every closed V-HACD mesh there (15 of 19
  /// at 0.05, up to 2.9% on plaque), hulls+exact checks are as fast or faster, and every V-HACD
  /// mesh builds in about a minute or less (mite, 39k triangles, the slowest;
  /// docs/bench/bench_collision.md, docs/bench/acd3d_bench.md).
  double tau_rel_3d = 0.02;
};

/// 3D: a part of an obstacle's surface as acd::PrepareMesh() finds it (without repair: a solid
/// with its cavities, or an edge-connected surface patch of a mesh that is not a solid), the exact
/// geometry the ACD pieces stand for.
struct ObstacleComponent {
  int obstacle = 0;        ///< Index of the obstacle it belongs to.
  acd::TriangleMesh mesh;  ///< Its triangles, exact input coordinates.
  /// Every edge has two triangles, so the part's own inside is defined by ray parity
  /// (acd::PreparedMesh::closed_parts); an obstacle's inside combines its closed parts by
  /// nonzero winding (PointLocator, LocateMethod::kExact).
  bool closed = true;
};

/// One nearly convex piece of an obstacle, an ACD component, with its convex hull: 2D a component
/// of Decompose2d; 3D a component of Decompose3d (a solid ACD piece of a closed obstacle
/// part, a surface ACD patch of an open one).
struct ObstaclePiece {
  int obstacle = 0;         ///< Index of the obstacle this piece belongs to.
  int component = -1;       ///< 3D: index into ObstacleSet::components; -1 in 2D.
  acd::TriangleMesh solid;  ///< The piece's own surface: 2D the extruded component polygon
                            ///< (closed), 3D the ACD component's mesh (a solid piece with its
                            ///< cut faces, closed; or a surface patch, open).
  bool closed = true;       ///< `solid` is a closed 2-manifold (inside/outside is defined).
  /// `solid` is convex, so it equals `hull` (2D: every vertex of the component is a strict
  /// vertex of its hull; 3D: a closed piece every face of which lies in a facet plane of its
  /// hull, with the same orientation; both decided with exact predicates). A hull hit on a
  /// convex piece is a hit on the obstacle, with no exact confirmation (unless `repaired`, or its
  /// obstacle has cavities).
  bool convex = false;
  /// 3D: the piece is a solid ACD piece of a part that crossed itself and was repaired first
  /// (into the solid it winds around positively, acd::PrepareMesh()), so it may cover points the
  /// exact test (ray parity in each part) calls outside, such as where the part overlaps itself:
  /// a point inside it is not taken as inside the obstacle without confirmation.
  bool repaired = false;
  acd::TriangleMesh hull;  ///< Convex hull of `solid`, closed, faces counter-clockwise
                           ///< seen from outside.
  /// #H by 4 half-spaces (n, d) with unit outward n: the hull is { x : n . x <= d for all rows }.
  Eigen::Matrix<double, Eigen::Dynamic, 4> planes;
  Eigen::AlignedBox3d box;  ///< Bounding box of `hull`.
  acd::Polygon2d polygon;   ///< 2D only: the component polygon (exact point location).
  /// 3D only: the triangles of `components[component].mesh` whose bounding boxes meet `box`:
  /// every point of the component's surface inside the hull lies on one of them, so they are the
  /// exact geometry a hit on this hull is confirmed against (input coordinates, unlike the
  /// piece's own cut faces).
  std::vector<int> triangles;
};

/// A workspace's obstacles, ready for collision checking and point location.
struct ObstacleSet {
  int dimension = 2;                          ///< 2 or 3.
  Eigen::AlignedBox3d bounds;                 ///< Workspace bounds (2D: z in [-h/2, h/2]).
  double extrusion_height = 1.0;              ///< 2D: the prism height used [units].
  std::vector<acd::Polygon2d> polygons;       ///< 2D: the obstacles (prepared).
  std::vector<acd::TriangleMesh> meshes;      ///< Exact obstacle surfaces (2D: extruded prisms).
  std::vector<ObstaclePiece> pieces;          ///< Convex pieces of every obstacle.
  std::vector<ObstacleComponent> components;  ///< 3D: the parts of every obstacle.
  /// Where the hulls come from, for reports: "ACD (Decompose2d, tau = 0.02)" in 2D,
  /// "ACD (Decompose3d, tau_rel = 0.05: 12 solid, 3 surface)" in 3D (per part:
  /// solid ACD, solid ACD after repair, surface ACD, or its plain hull when neither ran).
  std::string hulls_source;
  /// 3D: one line per part whose ACD could not run (then its one piece is its
  /// hull), with the reason.
  std::vector<std::string> notes;
};

/// Builds the pieces of a 2D workspace: each obstacle polygon (the solid) is decomposed with
/// acd::Decompose2d(tau) and every component and its hull are extruded to a prism.
/// O(sum of the decomposition costs).
/// @throws InputError if an option is out of range or an obstacle is invalid.
ObstacleSet BuildObstacleSet(const envs::Workspace2d& workspace,
                             const ObstacleSetOptions& options = {});

/// Builds the pieces of a 3D workspace. Each obstacle mesh is cleaned and split into parts by
/// acd::PrepareMesh() (`meshes` holds the cleaned meshes, `components` the parts); each part is
/// decomposed (acd::Decompose3d, tau = options.tau_rel_3d x its acd::ReferenceRadius): solid ACD
/// when it is a solid, or one after repair (closed but self-intersecting), so that the pieces'
/// hulls cover its volume; surface ACD when it is open (patch hulls cover its surface; flat ones
/// are thickened by 1e-6 of the bounds' diagonal so that they bound a volume). A part whose ACD
/// cannot run (a closed one that is no solid even after repair, or a decomposition that throws)
/// gets its convex hull as its one piece and a line in `notes`. Every hull is CGAL convex_hull_3 of
/// the piece's vertices. Open meshes are accepted here (`closed` is false); exact point location on
/// them is refused later.
/// @throws InputError if a mesh fails acd::CheckTriangleMesh() or has no face of positive area,
///         or tau_rel_3d is not > 0.
ObstacleSet BuildObstacleSet(const envs::Workspace3d& workspace,
                             const ObstacleSetOptions& options = {});

/// The number of obstacle triangles (sum over `meshes`).
int TriangleCount(const ObstacleSet& obstacles);

}  // namespace acdplan::collision
