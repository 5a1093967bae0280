#pragma once
// OMPL.app problem files (`.cfg`): the rigid-body problems OMPL.app ships in resources/2D and
// resources/3D, read directly.

#include <Eigen/Geometry>
#include <string>
#include <utility>
#include <vector>

#include "acd/triangle_mesh.h"
#include "envs/workspace3d.h"

namespace acdplan::envs {

/// One `[planner]` entry of a problem file: an OMPL.app planner name and its parameters.
struct OmplAppPlanner {
  std::string ompl_app_name;  ///< As the file spells it, lower case: "rrtconnect".
  std::string planner;        ///< acdplan's name (planning/registry.h): "RRTConnect".
  /// `name.param=value` lines in file order ("range" -> "10"; "name" renames the copy).
  std::vector<std::pair<std::string, std::string>> parameters;
  /// `problem.key=value` lines that apply to this copy only ("sampler" -> "bridge_test").
  std::vector<std::pair<std::string, std::string>> context;
  int line = 0;  ///< Where the entry starts (its `name=` or first `name.param=` line).
};

/// A rigid-body problem of OMPL.app, ready to plan. Poses are those OMPL.app plans with: the
/// pose moves `robot` (already shifted by `robot_center`, see below), the world is not moved.
struct OmplAppProblem {
  std::string path;  ///< The file read.
  std::string name;  ///< [problem] name; the file's stem when absent.
  /// 2 (SE(2): start/goal x, y, theta; the state's z is 0 and its rotation is about z) or 3
  /// (SE(3): x, y, z and axis-angle theta about axis).
  int dimension = 3;
  std::string robot_path, world_path;  ///< Resolved against the file's folder; world may be "".
  Eigen::Isometry3d start = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d goal = Eigen::Isometry3d::Identity();
  /// The state space's position bounds: `volume.min/max.*`, or the world's bounding box when
  /// they are absent (OMPL.app's inferEnvironmentBounds() with factor 1, add 0). z is [0, 0]
  /// in 2D.
  Eigen::AlignedBox3d bounds;
  bool bounds_from_file = false;  ///< Whether the volume keys gave `bounds`.
  /// The valid-state sampler in acdplan's spelling (planning/registry.h SamplerNames()):
  /// OMPL.app's `bridge_test` is "bridge"; "" when the file names none.
  std::string sampler;
  /// [problem] control: "kinematic_car" or "dynamic_car" (OMPL.app's KinematicCarPlanning and
  /// DynamicCarPlanning; "kinematic car" is read the same), 2D only; "" for a geometric problem.
  /// Its planners are then control planners (`planner` in acdplan's spelling: SyclopRRT, ...).
  std::string control;
  std::string objective;                 ///< [problem] objective ("length"); "" when absent.
  double objective_threshold = -1;       ///< [problem] objective.threshold; < 0 when absent.
  double goal_threshold = -1;            ///< [problem] threshold (goal tolerance); < 0 when absent.
  double time_limit = -1;                ///< [benchmark] time_limit [s]; < 0 when absent.
  double mem_limit = -1;                 ///< [benchmark] mem_limit [MB]; < 0 when absent.
  int run_count = -1;                    ///< [benchmark] run_count; < 0 when absent.
  std::vector<OmplAppPlanner> planners;  ///< [planner] entries in file order.
  /// The robot's reference point in its mesh file's frame: OMPL.app's getRobotCenter(), the
  /// mean of every vertex of the robot scene as assimp imports it (node transforms applied,
  /// vertices split where normals differ and joined where identical); z = 0 in 2D.
  Eigen::Vector3d robot_center = Eigen::Vector3d::Zero();
  acd::TriangleMesh robot;  ///< The robot mesh (envs::ReadMesh) minus `robot_center`.
  acd::TriangleMesh world;  ///< The world mesh (envs::ReadMesh), not moved; empty if no world.
  /// Lines accepted but ignored ("<file>:<line>: <key>: ..."), e.g. OMPL.app state-space
  /// settings such as longest_valid_segment_fraction; the command line prints them.
  std::vector<std::string> warnings;
};

/// Reads an OMPL.app problem file. The syntax is INI: `[section]` headers, `key=value` lines
/// (spaces around both trimmed), comments from `#` or `;` at the start of a line, blank lines.
/// Sections: [problem] (name, robot, world, start.*, goal.*, volume.*, sampler, control,
/// objective, objective.threshold, threshold, solution_length; other keys are OMPL.app
/// state-space settings, kept as warnings), [benchmark] (time_limit, mem_limit, run_count,
/// output, save_paths), [planner] (`name=` starts a copy of a planner, `name.param=value` sets
/// a parameter of the last copy, or starts one, as OMPL.app's BenchmarkOptions does;
/// `problem.key=value` applies to the copy before it).
///
/// The dimension: 2 when start.theta and goal.theta are given and no z or axis key, 3 when
/// start and goal both give x, y, z, theta and axis.x/y/z (OMPL.app's isSE2Problem /
/// isSE3Problem); anything else is an error naming the key that makes the file mixed.
///
/// @throws InputError "<file>:<line>: <key>: <rule>" (line 0 when the file cannot be read;
///         the [problem] header's line for a missing key), e.g.
///         "bugtrap.cfg:31: planner 'spars2' is not available in acdplan (available: prm, ...)",
///         "car.cfg:4: control: 'blimp' is not supported (acdplan plans kinematic_car and
///         dynamic_car)",
///         "x.cfg:7: start.x: expected a number, got 'abc'", for syntax errors, keys given
///         twice, missing or mixed pose keys, bad numbers, empty bounds, unknown samplers or
///         planners, and mesh files that ReadMesh() cannot read.
OmplAppProblem ReadOmplAppProblem(const std::string& path);

/// The 3D world of `problem` (for SE(3) scenarios): `problem.bounds` as the bounds and the
/// world mesh, unmoved, as the one obstacle (none without a world); the description names the
/// problem. OMPL.app's volume bounds limit the robot's reference point, not its body, and its
/// world meshes need not be closed (several shipped ones are not).
Workspace3d OmplAppWorkspace3d(const OmplAppProblem& problem);

/// OMPL.app's planner names (lower case) that acdplan runs, with acdplan's name for each
/// (planning/registry.h PlannerNames()), in OMPL.app's order.
std::vector<std::pair<std::string, std::string>> OmplAppPlannerTable();

}  // namespace acdplan::envs
