#pragma once
// Rings without structure grouped into polygons with holes, as a shapefile stores them.
// Internal: include only from .cpp files of the acd library.

#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// Groups `rings` (each without its closing point, in any orientation) into polygons by how they
/// nest: a ring that an even number of the others contain (0, or an island in a lake) is an outer
/// ring, one that an odd number contain is a hole of the innermost of them. This is the even-odd
/// rule applied to whole rings, which GIS readers use where a format gives no structure (an
/// ESRI shapefile record); for valid input it also agrees with the format's orientation rule
/// (outer rings clockwise, holes counter-clockwise), and it does not depend on it. Containment
/// is decided exactly, at the first vertex of the inner ring that is not on the outer one's
/// boundary (rings may touch at points); a ring whose every vertex lies on another's boundary is
/// not inside it. Polygons come in the order of their outer rings, holes in their order in
/// `rings`; orientation and validity are left to PreparePolygons(). A sweep over bounding boxes
/// finds the pairs to test; O(n m) for a ring of n vertices tested in one of m.
std::vector<Polygon2d> PolygonsByNesting(const std::vector<Ring2d>& rings);

}  // namespace acdplan::acd::internal
