#pragma once
// A convex hull whose faces and planes do not depend on memory addresses.

#include <Eigen/Core>
#include <vector>

#include "acd/internal/in_plane_tolerance.h"
#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

/// A convex hull as a mesh and as outward half-spaces (n, d), |n| = 1, { x : n . x <= d }.
struct CanonicalHull {
  TriangleMesh mesh;  ///< ConvexHull3's mesh: closed, its triangles from the points alone.
  Eigen::Matrix<double, Eigen::Dynamic, 4> planes;
};

/// The convex hull of `points` (>= 1) with planes that are the same bytes in every run. The
/// facets are ConvexHullFacets' (exactly coplanar triangles joined); each facet is regrouped as
/// the hull vertices within kInPlaneTolerance of the hull's size of the plane through three of
/// its own vertices (chosen by lexicographic order), its plane refitted the same way from the
/// group and oriented by the facet's outward normal; a plane some hull vertex lies clearly
/// outside of (10 x kInPlaneTolerance of the hull's size) is dropped, any other moved out to
/// the farthest hull vertex, so every plane supports the hull. Planes are sorted by their
/// vertex sets. A hull of fewer than 4 vertices keeps no planes; a flat one keeps its one plane.
CanonicalHull MakeCanonicalHull(const std::vector<Eigen::Vector3d>& points);

}  // namespace acdplan::acd::internal
