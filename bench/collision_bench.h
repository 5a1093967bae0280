#pragma once
// The collision benchmark behind `acdplan bench-collision`: bvh vs hulls vs hulls+exact and
// exact vs hull point location, in one process, on the same random poses and points. Every rate
// is over the median time of up to 7 passes.

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "bench/targets.h"
#include "collision/obstacle_set.h"

namespace acdplan::bench {

/// Options for BenchCollision(); `{}` is valid (skips 3D when `mesh_dir` is empty).
struct BenchCollisionOptions {
  int poses = 20000;       ///< Random poses per world and robot; > 0.
  int points = 200000;     ///< Random points per world for point location; > 0.
  std::uint64_t seed = 1;  ///< Seeds the worlds (envs generators) and the poses.
  double tau = 0.02;       ///< 2D obstacle ACD tau [units] (ObstacleSetOptions::tau); >= 0.
  /// 3D obstacle ACD tau relative to each obstacle part's reference radius
  /// (ObstacleSetOptions::tau_rel_3d); > 0.
  double tau_rel_3d = collision::ObstacleSetOptions{}.tau_rel_3d;
  std::string mesh_dir;             ///< Folder of .obj meshes used one by one as 3D obstacles.
  std::vector<std::string> meshes;  ///< File names in `mesh_dir`; empty = every .obj there.
};

/// One world (and robot) of the benchmark; the JSON keys are the field names. Rates are
/// fractions in [0, 1]; a figure that could not be measured is NaN (null in JSON) and `note`
/// says why.
struct BenchCollisionRow {
  std::string world;         ///< "zigzag/disc", "zigzag/polygon", "bunny/mesh", ...
  std::string hulls_source;  ///< ObstacleSet::hulls_source.
  int triangles = 0;         ///< Obstacle triangles in the exact BVH.
  int hulls = 0;             ///< Convex pieces.
  int poses = 0;
  double bvh_checks_per_s = 0;
  double hulls_checks_per_s = 0;
  double hulls_exact_checks_per_s = 0;
  double collision_rate = 0;             ///< Poses in collision (bvh).
  double hulls_false_positive_rate = 0;  ///< Of the poses bvh calls free, those hulls rejects.
  int hulls_misses = 0;                  ///< Poses hulls calls free and bvh in collision (0).
  int hulls_exact_mismatches = 0;        ///< Poses where hulls+exact and bvh disagree.
  double locate_exact_points_per_s = 0;
  double locate_hulls_points_per_s = 0;
  double locate_hulls_error_rate = 0;  ///< Of all points, those the two locators disagree on.
  std::string note;
};

/// Runs the benchmark: every built-in 2D world (envs::GeneratorNames(), seed `options.seed`)
/// with a disc (radius 0.2) and an L-shaped polygon robot (0.6 x 0.4), then every mesh of
/// `options.mesh_dir` as the one obstacle of a 3D world (its box grown 10% per side) with a cube
/// robot of side 5% of the mesh's box diagonal. Each mode is timed on one thread over the same
/// poses (after 100 ms of untimed warm-up passes, bench/time_runs.h); point location over the same
/// random points in the bounds, all of them in one call per pass (PointLocator's batch Inside()).
/// Progress lines go to `progress` when not null.
/// @throws InputError for out-of-range options or an unreadable mesh folder.
std::vector<BenchCollisionRow> BenchCollision(const BenchCollisionOptions& options,
                                              std::ostream* progress = nullptr);

/// The rows as a Markdown table with the speed-ups, then `targets` checked on them (no such
/// section without targets).
std::string BenchCollisionMarkdown(const std::vector<BenchCollisionRow>& rows,
                                   const std::vector<Target>& targets = {});

/// What collision targets can use: the label "world" (as in the table, e.g. "zigzag/disc") and
/// "kind" ("2d" or "mesh"), and as metrics the rows' numeric JSON fields (bvh_checks_per_s,
/// hulls_checks_per_s, ..., locate_hulls_error_rate). A figure that could not be measured
/// (exact point location in an open mesh) is absent: its targets do not apply to the row.
const TargetVocabulary& CollisionTargetVocabulary();

/// The rows as target rows (labels and metrics above).
std::vector<TargetRow> CollisionTargetRows(const std::vector<BenchCollisionRow>& rows);

/// {"format": "acdplan.bench_collision/1", "options": {...}, "worlds": [row, ...]}.
std::string BenchCollisionJson(const std::vector<BenchCollisionRow>& rows,
                               const BenchCollisionOptions& options);

}  // namespace acdplan::bench
