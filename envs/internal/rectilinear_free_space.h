#pragma once
// The free space of a workspace whose edges are all axis-parallel (grid maps, box worlds),
// traced on the grid of its coordinates instead of built with Boolean operations.

#include <optional>
#include <vector>

#include "acd/polygon2d.h"
#include "envs/workspace2d.h"

namespace acdplan::envs::internal {

/// FreeSpace2d() of `workspace` (prepared: obstacles as acd::PreparePolygon() leaves them), before
/// its final sort, when every obstacle edge is axis-parallel: the distinct
/// obstacle coordinates inside the bounds cut the bounds into a grid of cells; a cell is blocked
/// when an obstacle covers it (winding numbers, row by row); the free cells' 4-connected
/// components are traced (TraceChamfered()), one polygon each, valid and clean as traced. These
/// are the Boolean construction's regions: cells meeting at a corner are connected only through
/// a free side cell, so two components touching at a corner are two polygons, and where one
/// component meets itself at a corner (a hole touching another of its rings there) the corner
/// is cut off by the diamond |dx| + |dy| < `gap` on both sides.
///
/// O(cells + obstacle edges * rows they span). Returns std::nullopt, leaving the work to the
/// Boolean construction, when an obstacle edge is not axis-parallel, when the grid would have
/// more than max(2^22, 64 * obstacle vertices) cells (scattered boxes), or when `gap` is not
/// below a quarter of the grid spacing or too small to move a coordinate.
std::optional<std::vector<acd::Polygon2d>> RectilinearFreeSpace(const Workspace2d& workspace,
                                                                double gap);

}  // namespace acdplan::envs::internal
