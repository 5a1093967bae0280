#pragma once
// 3D convex hulls as triangle meshes, and their half-space form.

#include <Eigen/Core>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::acd {

/// Convex hull of `points` (CGAL convex_hull_3) as a closed triangle mesh, faces CCW seen from
/// outside. A flat or degenerate point set is thickened by `thickness` [units] along its missing
/// principal directions first, so that the hull bounds a volume when thickness > 0; with
/// thickness 0 the hull of a flat set stays flat (one side, volume 0) and that of a segment or a
/// point has no triangle. Requires >= 1 point. The mesh depends on the set of points alone (not
/// their order, not memory addresses), byte for byte: its vertices are the hull's extreme points
/// sorted by (x, y, z), and each facet (all its exactly coplanar triangles) is fanned from its
/// smallest vertex, so no triangle has collinear corners (internal::ConvexHullFacets).
/// O(n log n) for n points.
TriangleMesh ConvexHull3(const std::vector<Eigen::Vector3d>& points, double thickness);

/// Whether `hull`, a mesh of ConvexHull3() at thickness 0, bounds no volume: it has no triangle,
/// or is one-sided (fanned, a flat hull of V vertices has V - 2 triangles; a closed one, 2V - 4).
/// Exact, from the mesh's counts: its computed volume is rounding noise, and not even that for
/// a flat hull off the origin (its one side's signed volume is the plane's offset x area / 3).
bool IsFlatHull(const TriangleMesh& hull);

/// Outward half-spaces (n, d), |n| = 1, of the closed convex mesh `hull`: one row per face
/// (coplanar faces merged); the hull is { x : n . x <= d for every row }. Every d is at least
/// max over the hull's vertices of n . v, so no vertex of `hull` is ever outside a row, even for
/// a sliver face whose computed normal is off. O(faces x vertices).
Eigen::Matrix<double, Eigen::Dynamic, 4> HullPlanes(const TriangleMesh& hull);

}  // namespace acdplan::acd
