#include "envs/occupancy_grid.h"

#include <cmath>

#include "base/input_error.h"
#include "envs/internal/trace_cells.h"

namespace acdplan::envs {

std::vector<acd::Polygon2d> TraceObstacles(const OccupancyGrid& grid) {
  const int w = grid.width, h = grid.height;
  if (w < 0 || h < 0 || grid.blocked.size() != static_cast<size_t>(w) * h) {
    throw InputError(
        "TraceObstacles(): blocked has " + std::to_string(grid.blocked.size()) +
        " cells, expected width * height = " + std::to_string(static_cast<long long>(w) * h));
  }
  if (!std::isfinite(grid.resolution) || !(grid.resolution > 0.0) || !grid.origin.allFinite()) {
    throw InputError("TraceObstacles(): resolution must be finite and > 0, origin finite");
  }
  // Flip to y up: grid row r is cell row h - 1 - r.
  std::vector<std::uint8_t> blocked(grid.blocked.size());
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) blocked[(h - 1 - r) * w + c] = grid.Blocked(r, c) ? 1 : 0;
  }
  std::vector<double> xs(w + 1), ys(h + 1);
  for (int i = 0; i <= w; ++i) xs[i] = grid.origin.x() + grid.resolution * i;
  for (int i = 0; i <= h; ++i) ys[i] = grid.origin.y() + grid.resolution * i;
  return internal::TraceCells(w, h, blocked, xs, ys);
}

Workspace2d GridWorkspace(const OccupancyGrid& grid) {
  Workspace2d workspace;
  workspace.obstacles = TraceObstacles(grid);
  workspace.bounds = Eigen::AlignedBox2d(
      grid.origin, grid.origin + grid.resolution * Eigen::Vector2d(grid.width, grid.height));
  return workspace;
}

}  // namespace acdplan::envs
