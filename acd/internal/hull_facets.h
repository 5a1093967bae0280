#pragma once
// A 3D convex hull as its facets, each a convex polygon, found from the point set alone.

#include <Eigen/Core>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

/// The convex hull of a point set as polygons over its extreme points.
struct HullFacets {
  /// The hull's extreme points (#V), sorted lexicographically by (x, y, z): a point inside a
  /// facet or on an edge is none. A point set is one point, two for a segment.
  std::vector<Eigen::Vector3d> vertices;
  /// One polygon per facet: indices into `vertices`, strictly convex (no three corners
  /// collinear), counter-clockwise seen from outside, starting at its smallest index; sorted.
  /// A flat hull has one facet, counter-clockwise about the first of +z, +x, +y its plane is not
  /// parallel to; a segment or a point has none.
  std::vector<std::vector<int>> facets;
};

/// The facets of the convex hull of `points` (>= 1), thickened first as ConvexHull3() says.
/// They depend on the set of points alone, not on their order or on memory addresses: CGAL's
/// convex_hull_3 cuts a facet with >= 4 coplanar corners into triangles along diagonals that
/// follow its heap addresses, and keeps some points inside facets or on edges as vertices,
/// depending on the input order. Its triangles are joined across edges whose four points are
/// exactly coplanar (exact predicates), and each facet's polygon is the 2D convex hull of its
/// points (exact orientations, collinear points dropped) in a coordinate plane it projects onto
/// one to one. O(n log n) for n points.
HullFacets ConvexHullFacets(const std::vector<Eigen::Vector3d>& points, double thickness);

/// Indices of the corners of the 2D convex hull of `points` seen along coordinate axis
/// `drop_axis` (the other two coordinates; exact orientations, points on an edge or repeated
/// dropped), counter-clockwise in (u, v) = the next two axes in cyclic order. Collinear points
/// give their two ends, one point itself. O(n log n).
std::vector<int> ConvexCornersAlongAxis(const std::vector<Eigen::Vector3d>& points, int drop_axis);

/// `hull` as a triangle mesh: each facet fanned from its first (smallest) corner, triangles
/// listed from their smallest corner and sorted. Closed and manifold when `hull` bounds a
/// volume; no triangle has three collinear corners.
TriangleMesh FanTriangulation(const HullFacets& hull);

}  // namespace acdplan::acd::internal
