#pragma once
// The 3D ACD of a 3D workspace's free space: nearly convex components joined by planar
// openings, the map the 3D ACD samplers and PRM_ACD plan with (dissertation Ch. V and VI.C).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "acd/triangle_mesh.h"
#include "envs/workspace3d.h"

namespace acdplan::envs {

/// A nearly convex piece of the free space.
struct FreeComponent3d {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< Volume centroid [units].
  double volume = 0.0;                                 ///< [units^3]; > 0.
  acd::TriangleMesh hull;  ///< Convex hull of the piece, closed, faces CCW seen from outside.
  /// #H by 4 half-spaces (n, d), unit outward n: the hull is { x : n . x <= d for all rows }.
  Eigen::Matrix<double, Eigen::Dynamic, 4> planes;
};

/// The planar region two adjacent components share: a passage between them.
struct FreeOpening3d {
  /// The convex hull of the region, vertices in order, CCW seen from `normal`'s tip.
  std::vector<Eigen::Vector3d> polygon;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< Area centroid of the region [units].
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   ///< Unit, from component_a into _b.
  double area = 0.0;                                   ///< Of the region [units^2].
  /// The passage's bottleneck: the minimum width of the polygon in its plane (rotating
  /// calipers on its convex hull) [units]. A square window of side s has width s.
  double width = 0.0;
  int component_a = -1, component_b = -1;  ///< Indices into components, a < b.
};

/// Options for DecomposeFreeSpace3d(); `{}` is valid but tau 0 gives many components.
struct FreeSpaceDecomposition3dOptions {
  double tau = 0.0;  ///< Concavity tolerated per component (acd::Decompose3d) [units]; >= 0.
  /// Read and write the disk cache (FreeSpaceCacheDir()).
  bool use_cache = true;
  std::string cache_dir;  ///< Overrides FreeSpaceCacheDir() when not empty.
};

/// What DecomposeFreeSpace3d() returns.
struct FreeSpaceDecomposition3d {
  Eigen::AlignedBox3d bounds;  ///< The workspace bounds.
  double tau = 0.0;            ///< The tolerance used [units].
  double free_volume = 0.0;    ///< Volume of the free space [units^3].
  std::vector<FreeComponent3d> components;
  std::vector<FreeOpening3d> openings;
  /// FreeSpace3d()'s notes (obstacles left out) and the decomposition's (a free space that is
  /// not a solid after rounding: then each part's hull is its one component).
  std::vector<std::string> notes;
  std::string key;          ///< The content hash of the inputs (32 hex digits).
  bool from_cache = false;  ///< Read from the disk cache rather than computed.
  double time_ms = 0.0;     ///< Free space + ACD (or the cache read) [ms].
  double compute_ms = 0.0;  ///< What computing the free space and its ACD cost [ms] (kept in
                            ///< the cache: a cache hit reports the original cost).

  /// The index of the component whose hull holds `point` most deeply (largest distance to
  /// the hull's nearest face), or -1 if none holds it. O(total hull faces).
  int Locate(const Eigen::Vector3d& point) const;
};

/// The component adjacency graph: per component, the sorted components it shares an
/// opening with.
std::vector<std::vector<int>> ComponentGraph(const FreeSpaceDecomposition3d& decomposition);

/// The minimum width of the planar polygon `polygon` (at least 3 points, in a plane of unit
/// normal `normal`): the smallest distance between two parallel lines in that plane enclosing
/// it, by rotating calipers over the edges of its 2D convex hull (Toussaint 1983). O(n log n).
/// 0 for fewer than 3 points or collinear points.
double NarrowestWidth(const std::vector<Eigen::Vector3d>& polygon, const Eigen::Vector3d& normal);

/// The free space of `workspace` (FreeSpace3d()), decomposed by acd::Decompose3d (solid ACD,
/// tau = options.tau), its components and openings summarised as above.
///
/// Cache: the result is stored in FreeSpaceCacheDir() (or options.cache_dir) under the
/// content hash of (format version, bounds, every obstacle's vertices and triangles, tau),
/// written atomically (temporary file + rename). A later call with the same inputs reads it
/// instead of decomposing (from_cache true): the same components and openings, bit for bit.
/// An entry that cannot be parsed or whose stored key differs is recomputed, with a line on
/// stderr saying why; it is never trusted. A cache that cannot be written is a warning too.
/// @throws InputError as FreeSpace3d(), or if tau < 0.
FreeSpaceDecomposition3d DecomposeFreeSpace3d(const Workspace3d& workspace,
                                              const FreeSpaceDecomposition3dOptions& options);

/// The cache folder: $ACDPLAN_CACHE_DIR, else $XDG_CACHE_HOME/acdplan, else
/// $HOME/.cache/acdplan, else "" (no cache).
std::string FreeSpaceCacheDir();

}  // namespace acdplan::envs
