#pragma once
// Exact inside/outside tests for one solid: a polygon with holes (2D) or a closed triangle
// mesh (3D). Internal to the collision module.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "acd/polygon2d.h"
#include "acd/triangle_mesh.h"
#include "collision/obstacle_set.h"

namespace acdplan::collision::internal {

/// Point in a polygon with holes by ray crossing (Ch. VI.A's "exact" test) with CGAL's exact
/// orientation predicate for every edge that straddles the ray, so the answer is exact for the
/// double input. Edges are bucketed into horizontal slabs so a query only visits the edges of
/// its slab: O(edges per slab) instead of O(n). Boundary points count as inside.
class PolygonLocator2d {
 public:
  explicit PolygonLocator2d(const acd::Polygon2d& polygon);
  bool Contains(const Eigen::Vector2d& p) const;
  const Eigen::AlignedBox2d& box() const { return box_; }

 private:
  struct Edge {
    Eigen::Vector2d a, b;  // a.y() <= b.y()
  };
  Eigen::AlignedBox2d box_;
  double slab_height_ = 1.0;
  std::vector<Edge> edges_;
  std::vector<int> slab_begin_;  // edges of slab s: slab_edges_[slab_begin_[s] .. [s + 1])
  std::vector<int> slab_edges_;
};

/// Point in a closed triangle mesh: CGAL Side_of_triangle_mesh (ray parity on an AABB tree of
/// the triangles, exact predicates). Boundary points count as inside. Thread-safe after
/// construction (the tree is built eagerly).
class MeshLocator3d {
 public:
  /// Requires a closed mesh (every edge on two triangles): a part of acd::PrepareMesh() that
  /// PreparedMesh::closed_parts marks.
  explicit MeshLocator3d(const acd::TriangleMesh& mesh);
  ~MeshLocator3d();
  MeshLocator3d(MeshLocator3d&&) noexcept;
  MeshLocator3d& operator=(MeshLocator3d&&) noexcept;
  bool Contains(const Eigen::Vector3d& p) const;
  const Eigen::AlignedBox3d& box() const { return box_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  Eigen::AlignedBox3d box_;
};

/// Exact point location over a whole ObstacleSet: 2D one PolygonLocator2d per obstacle polygon;
/// 3D one MeshLocator3d per closed part (ObstacleSet::components: the parts of acd::PrepareMesh(),
/// the input surface, not the ACD pieces), a point being inside obstacle k when an odd number of
/// k's parts contain it (as ray parity on the whole mesh would say).
class ExactObstacleLocator {
 public:
  /// `skip_open`: 3D parts that are not closed are left out (the collision world's containment
  /// test); otherwise such a part throws InputError naming it and its first defect (point
  /// location).
  ExactObstacleLocator(const ObstacleSet& obstacles, bool skip_open);
  bool Inside(const Eigen::Vector3d& p) const;
  int skipped_open_pieces() const { return skipped_open_; }

 private:
  int dimension_ = 2;
  std::vector<PolygonLocator2d> polygons_;
  std::vector<MeshLocator3d> pieces_;
  std::vector<int> piece_obstacle_;
  int obstacle_count_ = 0;
  int skipped_open_ = 0;
};

}  // namespace acdplan::collision::internal
