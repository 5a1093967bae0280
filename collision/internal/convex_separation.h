#pragma once
// Separation tests on convex polytopes: a cheap, conservative one between two polytopes by their
// face planes (the first filter of a hull test before GJK), and a complete one between a
// polytope and a triangle. Internal.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <vector>

namespace acdplan::collision::internal {

/// A triangle as its three corners.
using Triangle3 = std::array<Eigen::Vector3d, 3>;

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

/// The directions of the edges of the closed convex mesh `hull` (each edge once; the diagonals of
/// coplanar triangles included, which only adds axes to try): the edge-edge axes of
/// TouchesTriangle().
std::vector<Eigen::Vector3d> EdgeDirections(const Eigen::MatrixX3d& vertices,
                                            const Eigen::MatrixX3i& triangles);

/// True if the convex polytope `a` (its planes and vertices) and the triangle `t` share a point
/// (touching counts), by the separating axis theorem: they are disjoint iff the projections on
/// one of a's face normals, t's normal, or a cross product of one of `a_edges` (the directions
/// of a's edges) with an edge of t are disjoint. Decided in doubles: may differ from an exact
/// answer only where the two touch up to rounding. A degenerate t (no normal) is tested on the
/// other axes only, which never misses a contact. O(|planes| + |a_edges| x 3) axes, each
/// O(|vertices|), stopping at the first that separates.
bool TouchesTriangle(const ConvexPolytope& a, const std::vector<Eigen::Vector3d>& a_edges,
                     const Triangle3& t);

}  // namespace acdplan::collision::internal
