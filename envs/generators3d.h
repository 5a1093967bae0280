#pragma once
// Procedural 3D narrow-passage worlds. Every generator takes an explicit seed (base/random.h):
// the same seed and options give the same world. Obstacles are built from axis-aligned boxes
// on a grid: each is a closed, outward-oriented triangle mesh (acd::PrepareMesh() finds it
// solid); distinct obstacles are disjoint. The world is [0, width] x [0, depth] x [0, height]
// (x, y, z) and its free space is connected.

#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "envs/workspace3d.h"

namespace acdplan::envs {

/// A free box a generator made narrow (a window, a mouth, a hatch, a tube leg), for tests,
/// query placement and pictures.
struct Passage3d {
  Eigen::AlignedBox3d box;  ///< The passage's free box.
  int axis = 0;             ///< The axis (0 x, 1 y, 2 z) along which it leads through.
};
using Passages3d = std::vector<Passage3d>;

/// A wall across x (at x = width / 2) filling the world's y-z section, with one square window
/// at a random place (its lower corner uniform in the middle 60% of each free range).
struct WindowWallOptions {
  double width = 10.0;          ///< World size along x [units]; > wall_thickness.
  double depth = 10.0;          ///< Along y [units]; > window_side.
  double height = 10.0;         ///< Along z [units]; > window_side.
  double wall_thickness = 0.5;  ///< [units]; > 0.
  double window_side = 1.0;     ///< [units]; > 0.
};
Workspace3d MakeWindowWall(std::uint64_t seed, const WindowWallOptions& options = {},
                           Passages3d* passages = nullptr);

/// A bug trap: a hollow cubic cage in the middle of a cubic world, closed but for a square
/// mouth in its +x wall at a random place, from which a funnel (a square tube of the mouth's
/// inner size) leads `funnel_length` into the cage, so the way in and out is long and narrow.
struct BugTrap3dOptions {
  double size = 10.0;           ///< World side [units]; > trap_size.
  double trap_size = 5.0;       ///< Outer side of the cage [units].
  double wall_thickness = 0.4;  ///< [units]; > 0.
  double mouth_side = 0.8;      ///< [units]; > 0; trap_size > mouth_side + 4 wall_thickness.
  double funnel_length = 1.5;   ///< Into the cage [units]; in (0, trap_size - 3 wall_thickness).
};
Workspace3d MakeBugTrap3d(std::uint64_t seed, const BugTrap3dOptions& options = {},
                          Passages3d* passages = nullptr);

/// Rooms stacked on `floors` floors: horizontal slabs between the floors fill the world's x-y
/// section, each with one square hatch at a random place (lower corner uniform in the middle
/// 80% of each free range). One obstacle per slab.
struct CubiclesOptions {
  double width = 10.0;           ///< Along x [units]; > hatch_side.
  double depth = 10.0;           ///< Along y [units]; > hatch_side.
  int floors = 3;                ///< Rooms in the stack; >= 2.
  double floor_height = 3.0;     ///< Floor to floor [units]; > floor_thickness.
  double floor_thickness = 0.3;  ///< Slab thickness [units]; > 0.
  double hatch_side = 1.0;       ///< [units]; > 0.
};
Workspace3d MakeCubicles(std::uint64_t seed, const CubiclesOptions& options = {},
                         Passages3d* passages = nullptr);

/// A square tube carved through a solid cube that fills the world: it enters at x = 0, runs
/// along x, turns at a right angle along y, and either leaves at y = size (1 bend) or turns back
/// along x and leaves at x = size (2 bends); the bend positions are random. The free space is
/// the tube.
struct BentTubeOptions {
  double size = 10.0;      ///< World side [units]; > 6 tube_side.
  double tube_side = 1.0;  ///< Inner side of the tube [units]; > 0.
  int bends = 1;           ///< 1 or 2.
};
Workspace3d MakeBentTube(std::uint64_t seed, const BentTubeOptions& options = {},
                         Passages3d* passages = nullptr);

/// Names GenerateWorkspace3d() accepts: "window_wall", "bug_trap3d", "cubicles", "bent_tube".
std::vector<std::string> Generator3dNames();

/// The parameters the 3D generators share; 0 keeps the generator's default.
struct Generator3dParameters {
  /// The passage's side [units]; >= 0: window_side, mouth_side, hatch_side or tube_side.
  double passage_width = 0.0;
  /// [units]; >= 0: wall_thickness, or floor_thickness for "cubicles"; not for "bent_tube".
  double wall_thickness = 0.0;
};

/// The generator `name` with its default options, except the parameters that are set.
/// @throws InputError "GenerateWorkspace3d(): <rule>" for an unknown name (listing the known
///         ones), a negative or non-finite parameter, wall_thickness for "bent_tube", or a
///         parameter the generator's own checks reject.
Workspace3d GenerateWorkspace3d(const std::string& name, std::uint64_t seed,
                                const Generator3dParameters& parameters = {},
                                Passages3d* passages = nullptr);

}  // namespace acdplan::envs
