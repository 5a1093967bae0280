#pragma once
// Planning scenarios: a YAML file naming the world, the robot, the query and how to plan.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "acd/concavity_measure.h"
#include "collision/collision_mode.h"
#include "envs/robot.h"
#include "envs/workspace2d.h"
#include "envs/workspace3d.h"
#include "planning/acd_sampler_options.h"
#include "planning/control/plan_car.h"
#include "planning/registry.h"
#include "planning/tau_diag.h"

namespace acdplan::planning {

/// A control-space robot of a scenario (`robot: {type: kinematic_car | dynamic_car}`) and how
/// it is planned (planning/control/plan_car.h).
struct CarScenario {
  control::CarModel model = control::CarModel::kKinematic;
  control::CarOptions options;  ///< Wheelbase, bounds, propagation step (OMPL.app's defaults).
  control::ControlPlanner planner = control::ControlPlanner::kSyclopRrt;
  control::DecompositionKind decomposition = control::DecompositionKind::kAcd;  ///< Syclop's.
  int grid_cells = 10;       ///< kGrid: cells per side; >= 1.
  double goal_radius = 0.5;  ///< Solved within this distance of the goal position [units]; > 0.
  /// Not in the YAML: > 0 ends the planner after this many termination-condition checks
  /// instead of the time limit (CarQuery::termination_checks; runs that depend on the seed
  /// only, for tests).
  unsigned termination_checks = 0;
};

/// A loaded, validated scenario. The file format (every key optional unless marked):
///
///   description: "one line"
///   workspace: world.yaml            # required: any file envs::LoadWorld() reads (relative
///                                    # to this file): a 2D world, or a 3D one (a 3D
///                                    # workspace YAML or a mesh: the scenario is then 3D,
///                                    # planned in R^3 or SE(3)), or a generator:
///   workspace: {generator: wall_gap, seed: 1, passage_width: 0.05, wall_thickness: 1.0}
///                                    # generators: envs::GeneratorNames(); wall_thickness
///                                    # for wall_gap, bug_trap, two_rooms, spiral and maze;
///                                    # 3D: envs::Generator3dNames() (window_wall, ...;
///                                    # passage_width = the window/mouth/hatch/tube side)
///   repair: true                     # with a workspace file: make invalid obstacle polygons
///                                    # valid (acd::RepairPolygon), each change a warning
///   unknown: free                    # with an occupancy map: its unknown cells are free
///                                    # (default blocked; envs::OccupancyMapOptions)
///   robot: {shape: point}            # point (default) | disc (radius) | polygon (polygon:
///                                    # [[x, y], ...] in the body frame; plans in SE(2)) |
///                                    # mesh (mesh: robots/rod.obj, relative to this file;
///                                    # 3D worlds only; plans in SE(3))
///   start: [x, y]                    # required; [x, y, yaw] for a polygon robot [rad];
///                                    # 3D: [x, y, z] for a point, [x, y, z, roll, pitch,
///                                    # yaw] for a mesh (rotation Rz(yaw) Ry(pitch) Rx(roll)
///                                    # [rad], as URDF's rpy)
///   goal: [x, y]                     # required; as start
///   acd: {tau_diag: 0.02, measure: sp}  # tau = tau_diag x the bounds' diagonal; measure
///                                    # sl | sp | h1 | h2. The old spelling tau_rel is read
///                                    # as tau_diag with a warning (`acdplan decompose
///                                    # --tau-rel` is relative to the reference radius)
///   planner: {name: PRM, samples: 200}   # name: registry.h PlannerNames(); exactly one of
///                                    # time_limit [s] > 0 or samples (integer >= 1, the
///                                    # Figure-4 protocol: PRM, PRM_ACD, PRMstar); default
///                                    # time_limit 5
///   sampler: {name: acd, uniform_share: 0.1, orientation: random, opening_weight: 4,
///             centroid_spread: 0.3, opening_spread: 0.5}   # name: registry.h SamplerNames()
///                                    # lead: true (name acd): acd_lead, samples along the
///                                    # shortest chain of components (acd_lead_sampler.h)
///                                    # aligned_jitter [rad]: the spread of aligned poses
///                                    # 3D with a mesh robot: orientation defaults to aligned
///                                    # (the mesh's principal axis along the openings'
///                                    # normals, spread aligned_jitter [rad])
///   collision: {mode: hulls+exact}   # bvh | hulls | hulls+exact
///   seed: 1                          # integer >= 0: samplers (and the CLI's OMPL seed)
///
/// Control-space robots (2D worlds): a car as OMPL.app defines it, planned with OMPL's control
/// planners (planning/control/plan_car.h); bounds in [units], [s] and [rad]:
///
///   robot: {type: kinematic_car,     # kinematic_car | dynamic_car (second order)
///           length: 1, width: 0.5,   # wheelbase L, and the body: a length x width
///                                    # rectangle centred on (x, y), unless shape (point,
///                                    # disc, polygon) gives another body; width default L/2
///           max_speed: 1, max_steer: 0.5236,        # |v|, |phi| (30 deg)
///           max_accel: 0.5, max_steer_rate: 0.0349, # dynamic_car: |a|, |phi'| (2 deg/s)
///           step: 0.05, min_control_steps: 1, max_control_steps: 20}  # propagation
///   start: [x, y, yaw]               # required; at rest, wheels straight
///   goal: [x, y, yaw]                # required; this pose must be free; solved when the
///                                    # position is within goal_radius (heading free)
///   goal_radius: 0.5                 # cars only
///   planner: {name: SyclopRRT, time_limit: 5}  # SyclopRRT | SyclopEST | RRT | KPIECE1 |
///                                    # EST | PDST; a time limit only; default SyclopRRT
///   decomposition: {name: acd}       # Syclop's regions: acd (the free space's ACD, its
///                                    # `acd:` options) | grid (OMPL's GridDecomposition,
///                                    # `cells` per side, default 10); cars only
/// A car takes no `sampler` (the decomposition guides Syclop); a car's planner with a rigid
/// robot, or a geometric planner with a car, is an error.
struct Scenario {
  std::string path;  ///< The file it was read from ("" if built in code).
  std::string description;
  std::string workspace_label;  ///< The workspace file, or "generator <name> (seed s)".
  int dimension = 2;            ///< 2: `workspace` holds the world; 3: `workspace3d`.
  envs::Workspace2d workspace;
  envs::Workspace3d workspace3d;  ///< The 3D world (dimension 3).
  envs::Robot robot;
  /// 2 numbers (point, disc) or 3 (polygon: x, y, yaw); 3D: 3 (point: x, y, z) or 6 (mesh:
  /// x, y, z, roll, pitch, yaw).
  std::vector<double> start, goal;
  double tau_diag = kDefaultTauDiag;  ///< ACD tolerance / the bounds' diagonal; >= 0.
  acd::ConcavityMeasure measure = acd::ConcavityMeasure::kShortestPath;
  PlannerType planner = PlannerType::kPrm;
  double time_limit = 5.0;  ///< [s]; used when samples == 0.
  int samples = 0;          ///< > 0: Figure-4 protocol with this many collision-free samples.
  SamplerType sampler = SamplerType::kAcd;
  AcdSamplerOptions sampler_options;  ///< Its seed is overwritten by `seed` when planning.
  collision::CollisionMode collision_mode = collision::CollisionMode::kHullsExact;
  std::uint64_t seed = 1;
  /// Set for a car (robot.type): then `robot` is its body, start and goal are [x, y, yaw],
  /// and `planner`, `sampler`, `samples` are unused.
  std::optional<CarScenario> car;
  /// Things the file says that were accepted but deserve a word ("<file>: acd.tau_rel: ...");
  /// the command line prints them on stderr.
  std::vector<std::string> warnings;
};

/// Reads and validates a scenario file; loads its workspace.
/// @throws InputError "<file>: <key path>: <rule>", e.g. "demo.yaml: planner.time_limit:
///         expected a positive number, got 'fast'", for syntax errors (with the line), unknown
///         keys, wrong types, out-of-range values, unknown names, and errors of the workspace.
Scenario LoadScenario(const std::string& path);

/// Checks the cross-field rules (planner/sampler names, budget, start/goal dimensions for the
/// robot, a car's options); called by LoadScenario() and again after command-line overrides.
/// @throws InputError naming the key ("<file>: planner.samples: ...").
void CheckScenario(const Scenario& scenario);

}  // namespace acdplan::planning
