#pragma once
// Moving AI benchmark scenario files (.scen: start and goal cells on a .map grid,
// https://movingai.com/benchmarks/formats.html).

#include <Eigen/Core>
#include <string>
#include <vector>

namespace acdplan::envs {

/// One problem (a line) of a scenario file.
struct MovingAiProblem {
  int bucket = 0;
  std::string map;       ///< The map as the file names it.
  std::string map_path;  ///< Where it was found (ResolveMovingAiMap()).
  int map_width = 0, map_height = 0;
  Eigen::Vector2i start = Eigen::Vector2i::Zero();  ///< Cell (x: column, y: row from the top).
  Eigen::Vector2i goal = Eigen::Vector2i::Zero();
  double optimal_length = 0.0;  ///< On the grid: 8 moves, diagonals sqrt(2), no corner cutting.
  int line = 0;                 ///< In the file.
};

/// Reads a Moving AI `.scen` file:
///   version 1                           (optional; "version 1.0" too)
///   <bucket> <map> <map width> <map height> <start x> <start y> <goal x> <goal y> <optimal>
///   ...                                 (one line per problem; tabs or spaces between fields)
/// Cells are (column, row) with (0, 0) the map's upper-left cell. Each problem's map is
/// resolved by ResolveMovingAiMap(); the map files themselves are not read here.
/// @throws InputError "<file>:<line>: <rule>": a missing or malformed field, a version other
///         than 1, a cell outside the map's declared size, a negative optimal length; "<file>:
///         no problem in file".
std::vector<MovingAiProblem> ReadMovingAiScenario(const std::string& path);

/// Where the map `map` named in the scenario file `scenario_path` is: `map` itself if absolute
/// and a file, else relative to the scenario's folder if that is a file, else the file of the
/// same name in the scenario's folder (benchmark sets name maps by their path in the set, as
/// "maps/dao/arena.map", and are often unpacked flat). The last candidate when none is a file.
std::string ResolveMovingAiMap(const std::string& scenario_path, const std::string& map);

/// The centre of cell (x, y) (x: column, y: row from the top) of a map of `height` rows in
/// the world of LoadMovingAiMap() (unit cells, origin at the lower-left corner, y up).
Eigen::Vector2d MovingAiCellCentre(const Eigen::Vector2i& cell, int height);

}  // namespace acdplan::envs
