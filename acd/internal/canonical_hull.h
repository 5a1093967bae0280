#pragma once
// A convex hull whose faces and planes do not depend on memory addresses.

#include <Eigen/Core>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

/// A convex hull as a mesh and as outward half-spaces (n, d), |n| = 1, { x : n . x <= d }.
struct CanonicalHull {
  TriangleMesh mesh;    ///< Deterministic, but facets regrouped to a tolerance may T-join.
  TriangleMesh closed;  ///< ConvexHull3's own mesh: closed (its coplanar facets' diagonals
                        ///< may differ between runs; the geometry does not).
  Eigen::Matrix<double, Eigen::Dynamic, 4> planes;
};

/// The convex hull of `points` (>= 1), rebuilt so the same points give the same bytes in every
/// run: CGAL's convex_hull_3 (through ConvexHull3) triangulates coplanar facets in an order
/// that depends on memory addresses (measured: the same input gave different planes in
/// consecutive runs of one process). The true facets are found by joining CGAL's triangles
/// across edges where they are exactly coplanar; each facet is regrouped as the hull vertices
/// within 1e-9 of the hull's size of the plane through three of its own vertices (chosen by
/// lexicographic order), its plane refitted the same way from the group and oriented by the
/// facet's outward normal, and its polygon fanned from its smallest vertex; a plane some hull
/// vertex lies clearly outside of (1e-6 of the hull's size) is dropped. Vertices are sorted
/// lexicographically; planes by their vertex sets. A flat hull keeps no planes.
CanonicalHull MakeCanonicalHull(const std::vector<Eigen::Vector3d>& points);

}  // namespace acdplan::acd::internal
