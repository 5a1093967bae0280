#pragma once
// A cheap, conservative separation test between two convex polytopes by their face planes: the
// first filter of a hull test before GJK. Internal.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace acdplan::collision::internal {

/// A convex polytope as its vertices and its outward face planes (n, d), |n| = 1, with every
/// vertex v satisfying n . v <= d (acd::HullPlanes() gives such planes).
struct ConvexPolytope {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector4d, Eigen::aligned_allocator<Eigen::Vector4d>> planes;

  /// This polytope moved by `pose`; `out`'s storage is reused.
  void Transformed(const Eigen::Isometry3d& pose, ConvexPolytope* out) const;
};

/// True if a face plane of `a` has every vertex of `b` beyond it by more than `margin`, or a face
/// plane of `b` has every vertex of `a` beyond it by more than `margin` [units] (the separating
/// axis theorem restricted to face normals). Then the polytopes are disjoint: this never says
/// "separated" for polytopes that touch, as long as `margin` exceeds the rounding of the dot
/// products. It may say "not separated" for disjoint polytopes (an edge-edge axis separates
/// them); an exact test must follow. O(|planes a| |vertices b| + |planes b| |vertices a|),
/// stopping at the first separating plane.
bool SeparatedByAFacePlane(const ConvexPolytope& a, const ConvexPolytope& b, double margin);

/// True if `p` is inside `polytope` by more than `margin` (n . p < d - margin for every plane);
/// false for a polytope without planes.
bool InsideBy(const ConvexPolytope& polytope, const Eigen::Vector3d& p, double margin);

/// True if some vertex of `a` lies inside `b` by more than `margin` (InsideBy()): the two then
/// overlap.
bool AVertexInside(const ConvexPolytope& a, const ConvexPolytope& b, double margin);

}  // namespace acdplan::collision::internal
