#pragma once
// Contour tracing of cells on a rectilinear grid (possibly non-uniform spacing).

#include <cstdint>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::envs::internal {

/// Traces the blocked cells of a `w` x `h` grid with y pointing UP: cell (cx, cy) is
/// `blocked[cy * w + cx]` and covers [xs[cx], xs[cx + 1]] x [ys[cy], ys[cy + 1]]; `xs` has
/// w + 1 and `ys` h + 1 strictly increasing coordinates. Returns one polygon per obstacle
/// piece as documented for envs::TraceObstacles() (4-connected pieces, pinches cut along
/// horizontal grid lines, vertices only where the boundary turns).
std::vector<acd::Polygon2d> TraceCells(int w, int h, const std::vector<std::uint8_t>& blocked,
                                       const std::vector<double>& xs,
                                       const std::vector<double>& ys);

/// The boundaries of the 4-connected components of the cells set in `cells` (same grid as
/// TraceCells()), one polygon each: the outer ring counter-clockwise, holes clockwise, vertices
/// only where the boundary turns. Pinches are not cut: where a component's two diagonal cells
/// meet at a corner (the other two are not in it), each of the two passes of its boundary cuts
/// the corner off, running through the points `chamfer` before and after it along its edges.
/// The component loses the square |dx| + |dy| < `chamfer` around the corner, and its rings are
/// simple and disjoint provided 2 * `chamfer` is below the grid spacing. Components touching
/// only at a corner stay separate and keep the corner. O(cells).
std::vector<acd::Polygon2d> TraceChamfered(int w, int h, const std::vector<std::uint8_t>& cells,
                                           const std::vector<double>& xs,
                                           const std::vector<double>& ys, double chamfer);

}  // namespace acdplan::envs::internal
