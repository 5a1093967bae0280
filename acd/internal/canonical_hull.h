#pragma once
// A convex hull whose faces and planes do not depend on memory addresses.

#include <Eigen/Core>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

/// A convex hull as a mesh and as outward half-spaces (n, d), |n| = 1, { x : n . x <= d }.
struct CanonicalHull {
  TriangleMesh mesh;
  Eigen::Matrix<double, Eigen::Dynamic, 4> planes;
};

/// The convex hull of `points` (>= 1), rebuilt so the same points give the same bytes in every
/// run: CGAL's convex_hull_3 (through ConvexHull3) triangulates coplanar facets in an order
/// that depends on memory addresses (measured: the same input gave different planes in
/// consecutive runs of one process). Each facet is regrouped as the hull vertices within
/// 1e-9 of the hull's size of its plane, its plane refitted through three of them chosen by
/// lexicographic order, and its polygon fanned from its smallest vertex. Vertices are sorted
/// lexicographically; planes by their vertex sets. A flat hull keeps no planes.
CanonicalHull MakeCanonicalHull(const std::vector<Eigen::Vector3d>& points);

}  // namespace acdplan::acd::internal
