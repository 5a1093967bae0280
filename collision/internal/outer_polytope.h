#pragma once
// A convex polytope with few faces around a convex hull with many: what a hull test of a concave
// ACD piece takes instead of its hull, whose hits are confirmed on the piece's triangles anyway.
// Internal.

#include "acd/triangle_mesh.h"

namespace acdplan::collision::internal {

/// A closed convex mesh that contains the closed convex mesh `hull` and has at most about
/// `max_planes` + 6 face planes: the intersection of the half-spaces n . x <= max over hull's
/// vertices of n . x (+ a rounding slack of 1e-9 of hull's box diagonal) for the six axis
/// directions and up to `max_planes` of hull's face normals, chosen farthest apart (each the
/// normal least aligned with those chosen before it, the axes first). `planes`: hull's face
/// planes (acd::HullPlanes()). `hull` itself when it has no more than `max_planes` + 6 of them.
/// Deterministic. O(max_planes x faces).
acd::TriangleMesh OuterPolytope(const acd::TriangleMesh& hull,
                                const Eigen::Matrix<double, Eigen::Dynamic, 4>& planes,
                                int max_planes);

}  // namespace acdplan::collision::internal
