#pragma once
// Contour tracing of blocked cells on a rectilinear grid (possibly non-uniform spacing).

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

}  // namespace acdplan::envs::internal
