#pragma once
// Moving AI benchmark grid maps (https://movingai.com/benchmarks/formats.html).

#include <string>

#include "envs/occupancy_grid.h"
#include "envs/workspace2d.h"

namespace acdplan::envs {

/// Reads a Moving AI `.map` file:
///   type octile
///   height H
///   width W
///   map
///   H lines of W characters
/// '.', 'G' (ground) and 'S' (swamp) are free; '@', 'O' (out of bounds), 'T' (trees) and 'W'
/// (water) are blocked. The header lines may come in any order before `map`. Cells are one
/// unit wide with the origin at (0, 0); the first map line is the top row (largest y), so the
/// world looks like the text.
/// @throws InputError "<file>:<line>: <rule>", e.g. "maze.map:7: row 3 has 9 cells,
///         expected 10" or "maze.map:5: unknown terrain 'x' in column 4".
OccupancyGrid ReadMovingAiMap(const std::string& path);

/// GridWorkspace(ReadMovingAiMap(path)).
Workspace2d LoadMovingAiMap(const std::string& path);

}  // namespace acdplan::envs
