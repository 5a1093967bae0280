#pragma once
// Centroid() and Area() of a polygon in one pass over its rings. Internal: the 2D ACD records
// each component's area for its statistics while it computes the centroid.

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// Centroid(polygon), and Area(polygon) into `*area`: the same values, each ring's signed area
/// computed once. Where the outer ring's area underflows to 0 (a sliver of subnormal width), the
/// mean of its vertices.
Point2d CentroidAndArea(const Polygon2d& polygon, double* area);

}  // namespace acdplan::acd::internal
