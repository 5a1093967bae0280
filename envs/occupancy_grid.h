#pragma once
// A grid of blocked / free cells and its conversion to obstacle polygons by contour tracing.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "acd/polygon2d.h"
#include "envs/workspace2d.h"

namespace acdplan::envs {

/// A rectangular cell grid in image order: row 0 is the TOP row (largest y), as in a PGM/PNG
/// image or a Moving AI map. Cell (row r, column c) covers, in world coordinates,
///   x in origin.x + resolution * [c, c + 1],  y in origin.y + resolution * [h - 1 - r, h - r]
/// so `origin` is the lower-left corner of the lower-left cell (the ROS map_server convention).
struct OccupancyGrid {
  int width = 0;                                     ///< Columns; >= 0.
  int height = 0;                                    ///< Rows; >= 0.
  double resolution = 1.0;                           ///< Cell side [units / cell]; > 0.
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< Lower-left corner [units].
  std::vector<std::uint8_t> blocked;  ///< width * height flags, row-major; 1 = blocked.

  bool Blocked(int row, int column) const { return blocked[row * width + column] != 0; }
};

/// The blocked cells as obstacle polygons (with holes), in world coordinates.
///
/// Contour tracing walks the boundary between blocked and free cells and emits a vertex only
/// where the boundary turns, so a straight wall of any length has one edge per side (a 100-cell
/// wall is a 4-vertex rectangle) and no vertex is collinear.
///
/// Connectivity: an obstacle is a 4-connected set of blocked cells; cells that touch only at a
/// corner are separate obstacles (they share that corner point). A 4-connected set whose
/// boundary would pass twice through one corner (a pinch: its two diagonal cells at that
/// corner are both in the set) is not a valid polygon, so it is cut along the horizontal grid
/// line through that corner into pieces that share edges; repeated until no piece pinches.
/// Every returned polygon therefore passes acd::PreparePolygon() and their union is exactly
/// the union of the blocked cells. O(cells) plus O(component size) per pinch cut.
std::vector<acd::Polygon2d> TraceObstacles(const OccupancyGrid& grid);

/// A workspace whose bounds are the grid's extent and whose obstacles are TraceObstacles().
Workspace2d GridWorkspace(const OccupancyGrid& grid);

}  // namespace acdplan::envs
