#pragma once
// The even-odd region of sets of rings, exactly: the region a make-valid repair keeps, and the
// region two triangulated faces share; and the region a segment graph bounds. Internal.

#include <utility>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// The points inside an odd number of the rings of every layer: for one layer, the even-odd
/// rule (GEOS's "linework" make-valid: a bow tie gives its two triangles, a hole crossing the
/// outer ring the symmetric difference); for several, the intersection of each layer's
/// even-odd region (e.g. two triangulations of faces in one plane: the area both cover, however
/// their edges cross or meet in T-junctions).
///
/// All ring edges go into one exact arrangement (CGAL Arrangement_with_history_2, Epeck); a
/// face's parity per layer flips across an edge that an odd number of that layer's ring edges
/// cover. Edges with the region on both sides vanish. Returned as polygons with holes, interior
/// on the left of every ring (outer counter-clockwise, holes clockwise), rounded to doubles once
/// at the end:
///  - faces joined across an edge form one polygon; polygons that touch at a point stay apart,
///    and a ring passes each vertex once: where the boundary touches itself (a hole touching
///    the outer ring, or a ring touching itself, at a point) it is split into an outer ring and
///    holes;
///  - a vertex between two collinear edges is dropped (e.g. where another ring's edge ends on
///    the boundary);
///  - each ring starts at its lowest vertex (exact lexicographic order), and holes, and
///    polygons by their outer ring, are in lexicographic order of their vertices, so the result
///    depends on the geometry alone.
/// Rounding can make rings of the result touch or cross where they pass closer than rounding:
/// callers that need valid polygons check them (PreparePolygons()). Edges of zero length are
/// skipped; an edge that a layer lists an even number of times (either way round) flips no
/// parity and never reaches the arrangement (the edges a triangulation's triangles share cost
/// nothing), and an edge of several layers is one segment there. At most 32 layers.
/// O((n + k) log n) for n edges left crossing k times.
std::vector<Polygon2d> EvenOddRegions(const std::vector<std::vector<Ring2d>>& layers);

/// What RegionsOfSegmentGraph() returns.
struct BoundedRegions {
  std::vector<Polygon2d> polygons;  ///< As EvenOddRegions() returns its regions.
  int hole_on_segment = -1;  ///< The first hole point that lies on a segment (no face), or -1.
};

/// The region that a planar straight-line graph bounds, as Triangle (J. R. Shewchuk's mesh
/// generator) meshes a .poly file without -c: the bounded faces of the arrangement of
/// `segments` (which may cross, overlap or dangle), less each face that holds one of
/// `hole_points`; the unbounded face is out. Returned as EvenOddRegions() returns its regions:
/// segments with the region on both sides (internal ones) vanish. A hole point on a segment
/// empties no face and is reported in `hole_on_segment`. Zero-length segments are skipped.
/// O((n + k + h) log n) for n segments crossing k times and h hole points.
BoundedRegions RegionsOfSegmentGraph(const std::vector<std::pair<Point2d, Point2d>>& segments,
                                     const std::vector<Point2d>& hole_points);

}  // namespace acdplan::acd::internal
