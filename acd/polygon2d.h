#pragma once
// Planar polygon types shared by every part of acdplan.

#include <Eigen/Core>
#include <vector>

namespace acdplan::acd {

/// A point in the plane [workspace units].
using Point2d = Eigen::Vector2d;

/// A closed ring of vertices; the closing edge from back() to front() is implicit (the first
/// vertex is not repeated).
using Ring2d = std::vector<Point2d>;

/// A polygon with holes. After PreparePolygons() (acd/prepare_polygon.h): `outer` is simple and
/// counter-clockwise, each hole is simple, clockwise and strictly inside `outer`, no two rings
/// cross, and no ring has duplicate or collinear consecutive vertices.
struct Polygon2d {
  Ring2d outer;               ///< Outer boundary, counter-clockwise.
  std::vector<Ring2d> holes;  ///< Hole boundaries, clockwise.
};

/// Signed area of `ring`: positive when counter-clockwise (shoelace formula). Relative error
/// below 2e-11 and an exact sign (0 only for zero area) for coordinates of magnitude 1e-145 ..
/// 1e153: a double-precision sum with an error bound, and an exact expansion sum where the
/// terms cancel beyond that bound (huge, thin spikes). O(n).
double SignedArea(const Ring2d& ring);

/// Area of `polygon`: outer area minus the holes' areas.
double Area(const Polygon2d& polygon);

/// Area centroid of `polygon` (holes subtracted); where the outer ring's area underflows to 0 (a
/// sliver of subnormal width), the mean of its vertices.
Point2d Centroid(const Polygon2d& polygon);

/// Total number of vertices over all rings.
int VertexCount(const Polygon2d& polygon);

/// The radius the dissertation relates tau to (Ch. IV.D, Table 2): the largest distance from
/// the mean of the outer ring's vertices to any of them (81.70 for nazca_monkey.poly).
double ReferenceRadius(const Polygon2d& polygon);

/// Returns a copy of `ring` with the vertex order reversed (orientation flipped).
Ring2d Reversed(const Ring2d& ring);

}  // namespace acdplan::acd
