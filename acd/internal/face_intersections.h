#pragma once
// Self-intersections of a triangle soup: the faces of a mesh that meet other than in the edge or
// vertex they share (the rule of CGAL's Polygon_mesh_processing::self_intersections, on a soup
// so that non-manifold and non-orientable meshes are diagnosed too).

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

/// Pairs (f, g), f < g, of triangles of `mesh` that intersect other than in what they share:
/// - no shared vertex: any common point;
/// - one shared vertex: the edge opposite the shared vertex in one triangle meets the other;
/// - a shared edge: the two opposite corners are coplanar with it and on the same side (the
///   triangles overlap).
/// Requires every triangle non-degenerate (three distinct, non-collinear corners) and no two
/// with the same three vertices. Exact predicates (CGAL Epick); candidate pairs from a box
/// intersection (CGAL box_self_intersection_d), so O(n log^3 n + k) for k candidate pairs.
/// Sorted.
std::vector<std::pair<int, int>> IntersectingFacePairs(const TriangleMesh& mesh);

/// Whether a face of `faces` (indices into `mesh`) and another face of `mesh` intersect, by the
/// rule and under the requirements of IntersectingFacePairs(). Only pairs with a face of `faces`
/// are tested: a check of the faces new to a mesh whose other faces are known not to cross.
/// Candidate pairs from a box intersection of those faces with all (CGAL box_intersection_d).
bool AnyFaceIntersects(const TriangleMesh& mesh, const std::vector<int>& faces);

/// A point common to triangles `f` and `g` of `mesh` (which intersect): computed exactly
/// (CGAL Epeck), then rounded.
Eigen::Vector3d FaceIntersectionPoint(const TriangleMesh& mesh, int f, int g);

}  // namespace acdplan::acd::internal
