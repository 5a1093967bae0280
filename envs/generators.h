#pragma once
// Procedural narrow-passage worlds. Every generator takes an explicit seed (base/random.h):
// the same seed and options give the same world.

#include <cstdint>
#include <string>
#include <vector>

#include "envs/workspace2d.h"

namespace acdplan::envs {

/// A vertical wall across the world with one gap at a random height.
struct WallGapOptions {
  double width = 10.0;          ///< World size along x [units]; > 0.
  double height = 10.0;         ///< World size along y [units]; > 0.
  double wall_thickness = 0.5;  ///< [units]; > 0.
  double passage_width = 0.5;   ///< Gap size [units]; in (0, height / 2].
};
Workspace2d MakeWallWithGap(std::uint64_t seed, const WallGapOptions& options = {});

/// A corridor of constant width zig-zagging from the left to the right side between two
/// obstacles; the turn positions and amplitudes are random.
struct ZigZagOptions {
  double width = 10.0;         ///< [units]; > 0.
  double height = 10.0;        ///< [units]; > 0.
  int turns = 5;               ///< Zig-zag corners; >= 1.
  double passage_width = 0.5;  ///< Corridor width, perpendicular to its walls [units]; > 0.
};
Workspace2d MakeZigZagCorridor(std::uint64_t seed, const ZigZagOptions& options = {});

/// A bug trap: a square cage with a funnel-shaped mouth (two lips pointing inwards) at a random
/// height of its right side. The cage's inside is reachable only through the mouth.
struct BugTrapOptions {
  double width = 10.0;          ///< [units]; > 0.
  double height = 10.0;         ///< [units]; > 0.
  double trap_size = 5.0;       ///< Outer side of the cage [units]; < min(width, height).
  double wall_thickness = 0.4;  ///< [units]; > 0.
  double passage_width = 0.4;   ///< Mouth width [units]; > 0.
};
Workspace2d MakeBugTrap(std::uint64_t seed, const BugTrapOptions& options = {});

/// Two rooms inside thick outer walls (which cross the bounds), joined by one door at a random
/// height of the dividing wall, each with random furniture boxes (which may overlap each other
/// or a wall, never the door's approach).
struct TwoRoomsOptions {
  double width = 12.0;          ///< [units]; > 0.
  double height = 8.0;          ///< [units]; > 0.
  double wall_thickness = 0.3;  ///< [units]; > 0.
  double passage_width = 0.6;   ///< Door width [units]; > 0.
  int furniture = 2;            ///< Boxes per room; >= 0.
};
Workspace2d MakeTwoRooms(std::uint64_t seed, const TwoRoomsOptions& options = {});

/// A rectilinear spiral wall around the centre; the corridor between its turns leads from the
/// outside to the centre. The seed picks the start direction and the turning sense.
struct SpiralOptions {
  int turns = 3;                ///< Full turns; >= 1.
  double wall_thickness = 0.3;  ///< [units]; > 0.
  double passage_width = 0.6;   ///< Corridor width [units]; > 0.
  double margin = 1.0;          ///< Free space around the spiral inside the bounds [units]; >= 0.
};
Workspace2d MakeSpiral(std::uint64_t seed, const SpiralOptions& options = {});

/// A perfect maze (randomized depth-first search) of `columns` x `rows` passage cells; the
/// walls are one obstacle traced from the cell grid (envs/occupancy_grid.h).
struct MazeOptions {
  int columns = 8;               ///< Passage cells along x; >= 1.
  int rows = 8;                  ///< Passage cells along y; >= 1.
  double wall_thickness = 0.25;  ///< [units]; > 0.
  double passage_width = 1.0;    ///< [units]; > 0.
};
Workspace2d MakeMaze(std::uint64_t seed, const MazeOptions& options = {});

/// Names GenerateWorkspace2d() accepts: "wall_gap", "zigzag", "bug_trap", "two_rooms",
/// "spiral", "maze".
std::vector<std::string> GeneratorNames();

/// The parameters every generator shares; 0 keeps the generator's default.
struct GeneratorParameters {
  double passage_width = 0.0;   ///< [units]; >= 0.
  double wall_thickness = 0.0;  ///< [units]; >= 0; not an option of "zigzag".
};

/// The generator `name` with its default options, except the parameters that are set.
/// @throws InputError "GenerateWorkspace2d(): <rule>" for an unknown name (listing the known
///         ones), a negative or non-finite parameter, wall_thickness for "zigzag", or a
///         parameter the generator's own checks reject.
Workspace2d GenerateWorkspace2d(const std::string& name, std::uint64_t seed,
                                const GeneratorParameters& parameters = {});

}  // namespace acdplan::envs
