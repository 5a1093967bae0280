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
/// the triangles, exact predicates), so the faces' orientation does not matter. Boundary points
/// count as inside. Thread-safe after construction (the tree is built eagerly).
class MeshLocator3d {
 public:
  /// Requires a closed mesh (every edge on two triangles): a part of acd::PrepareMesh() that
  /// PreparedMesh::closed_parts marks.
  explicit MeshLocator3d(const acd::TriangleMesh& mesh);
  ~MeshLocator3d();
  MeshLocator3d(MeshLocator3d&&) noexcept;
  MeshLocator3d& operator=(MeshLocator3d&&) noexcept;
  bool Contains(const Eigen::Vector3d& p) const;
  /// Inside and not on the surface.
  bool ContainsInInterior(const Eigen::Vector3d& p) const;
  const Eigen::AlignedBox3d& box() const { return box_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  Eigen::AlignedBox3d box_;
};

/// Exact point location over a whole ObstacleSet. 2D: one PolygonLocator2d per obstacle polygon.
/// 3D: one MeshLocator3d per closed part (ObstacleSet::components: the parts of
/// acd::PrepareMesh(), the input surface, not the ACD pieces) and the nonzero winding rule over
/// an obstacle's parts: each part P has a weight w(P) = +1 or -1, and p is inside obstacle k when
///   sum of w(P) over the closed parts P of k that contain p  >  0,
/// where a part of weight +1 contains its surface and one of weight -1 does not, so that every
/// point of the solid's boundary (a cavity's surface too) is inside. The weight is P's nesting:
/// w(P) = (-1)^d(P), d(P) the number of other closed parts of k that enclose P without meeting it
/// (a vertex of P strictly inside Q, no triangle of P touching or crossing one of Q; exact
/// predicates). This is CGAL orient_to_bound_a_volume's rule (outermost shells outward, nested ones
/// alternating) and acd::PrepareMesh()'s cavity rule, extended to shells that cross: those never
/// nest, each counts +1, so overlapping shells (a mesh modelled as several closed pieces) mean
/// their union. The file's face orientation is not used: PrepareMesh() turns every closed patch
/// outward, so a shell that is inside out in the file is read as outward, and a shell inside
/// another that it does not meet is a cavity whichever way it faces (as in the solid ACD). Hence:
///  - a solid (PrepareMesh() found no defect): its parts are disjoint solids, each of weight +1:
///    inside = inside a part, as ray parity on the whole mesh says;
///  - disjoint nested shells: even-odd, whatever their orientations;
///  - crossing or touching shells: their union.
/// Limit: a shell that lies inside the overlap of n >= 2 crossing shells and meets none is
/// weighted (-1)^n, so it cuts no cavity out of that overlap (the winding there is >= n - 1 > 0).
class ExactObstacleLocator {
 public:
  /// `skip_open`: 3D parts that are not closed are left out (the collision world's containment
  /// test); otherwise such a part throws InputError naming it and its first defect (point
  /// location). O(S^2) bounding-box tests over the S closed parts of an obstacle, plus one ray
  /// query and, where the vertex is inside, one face intersection pass (acd's
  /// IntersectingFacePairs) per pair whose boxes nest.
  ExactObstacleLocator(const ObstacleSet& obstacles, bool skip_open);
  bool Inside(const Eigen::Vector3d& p) const;
  /// 3D: Inside(p) over the closed parts listed in `components` (indices into
  /// ObstacleSet::components; repeats count once) instead of all of them: the same
  /// answer whenever the list holds every part that contains p.
  bool InsideAmong(const std::vector<int>& components, const Eigen::Vector3d& p) const;
  /// 3D: obstacle `obstacle` has a part of weight -1, so being inside one of its parts is not
  /// enough to be inside it.
  bool has_cavities(int obstacle) const {
    return has_cavities_[static_cast<size_t>(obstacle)] != 0;
  }
  int skipped_open_pieces() const { return skipped_open_; }

 private:
  // Winding > 0 for some obstacle, over `pieces` (ascending indices into pieces_).
  bool WindingPositive(const std::vector<int>& pieces, const Eigen::Vector3d& p) const;

  int dimension_ = 2;
  std::vector<PolygonLocator2d> polygons_;
  std::vector<MeshLocator3d> pieces_;  // closed parts, in ObstacleSet::components order
  std::vector<int> piece_obstacle_;
  std::vector<int> piece_weight_;
  std::vector<int> all_pieces_;          // 0, 1, ..., pieces_.size() - 1
  std::vector<int> piece_of_component_;  // -1 for a skipped part
  std::vector<char> has_cavities_;       // per obstacle
  int obstacle_count_ = 0;
  int skipped_open_ = 0;
};

}  // namespace acdplan::collision::internal
