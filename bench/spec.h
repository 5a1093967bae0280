#pragma once
// Benchmark definitions: the BENCH.yaml file of `acdplan bench` and its expansion into cases
// and runs (a fixed global order, so shards and seeds are reproducible).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bench/targets.h"
#include "planning/scenario.h"
#include "planning/scenario_yaml.h"

namespace acdplan::bench {

struct BenchSpec;

/// One world of a benchmark: a workspace with a start and a goal (for every robot).
struct BenchWorld {
  std::string name;              ///< Unique; used in file names (letters, digits, '_', '-', '.').
  std::string family;            ///< Worlds of one sweep share it (plots: success vs width).
  double passage_width = 0.0;    ///< [units]; 0 if unknown. Taken from the generator.
  double workspace_width = 0.0;  ///< Bounds' extent along x [units].
  /// Workspace, start and goal ([x, y] or [x, y, yaw]; point and disc robots use x, y, a
  /// polygon robot yaw 0 when absent), ACD tolerance and measure, collision mode.
  planning::Scenario scenario;
};

/// One robot of a benchmark.
struct BenchRobot {
  std::string name;
  envs::Robot robot;  ///< Unused when `from_scenario`.
  /// `shape: scenario`: each world's own robot (its scenario file's, e.g. an OMPL.app
  /// problem's robot mesh footprint).
  bool from_scenario = false;
  planning::AcdSamplerOptions
      acd_options;  ///< The bench's acd_sampler options, orientation per robot.
  /// A car (`type: kinematic_car | dynamic_car`, planning::ReadCarRobot()): planned by control
  /// planners; `robot` is then its body.
  std::optional<planning::CarRobot> car;
};

/// A budget: exactly one of `time_limit` (> 0) and `samples` (>= 1, the Figure-4 protocol).
struct BenchBudget {
  double time_limit = 0.0;  ///< [s]
  int samples = 0;
  /// "200 samples" or "2 s" (as PlanResult::budget).
  std::string Label() const;
};

/// Syclop's decomposition in a car's case: the ACD's regions, or OMPL's grid of `cells` per
/// side.
struct BenchDecomposition {
  planning::control::DecompositionKind kind = planning::control::DecompositionKind::kAcd;
  int cells = 0;  ///< kGrid: cells per side (>= 1).
  /// "acd" or "grid<cells>" (as `decompositions:` names it).
  std::string Label() const;
};

/// One cell of the benchmark: world x robot x sampler x planner x budget. A car's case:
/// world x robot x decomposition x control planner x budget, the decomposition in the sampler's
/// column ("acd", "grid20", or "none" for the planners without one).
struct BenchCase {
  int index = 0;             ///< Position in BenchSpec::cases.
  int world = 0, robot = 0;  ///< Indices into BenchSpec::worlds / robots.
  planning::SamplerType sampler = planning::SamplerType::kAcd;
  planning::PlannerType planner = planning::PlannerType::kPrm;
  BenchBudget budget;
  bool control = false;  ///< A car's case: the two fields below instead of sampler, planner.
  planning::control::ControlPlanner control_planner = planning::control::ControlPlanner::kSyclopRrt;
  std::optional<BenchDecomposition> decomposition;  ///< Syclop planners only.
  /// The sampler's name, or a car's decomposition label ("none" without one).
  std::string SamplerLabel() const;
  /// The planner's name (geometric or control).
  std::string PlannerLabel() const;
  /// "world/robot/sampler/planner/budget": stable, seeds are derived from it.
  std::string Key(const BenchSpec& spec) const;
};

/// A loaded, validated benchmark. The file format (see configs/bench/*.yaml):
///
///   name: narrow_passages           # required: letters, digits, '_', '-'
///   description: "one line"
///   seed: 1                         # base seed, integer >= 0 (default 1)
///   runs: 20                        # runs per case, integer >= 1 (default 10)
///   acd: {tau_diag: 0.02, measure: sp}  # defaults for worlds without their own (tau_rel:
///                                   # the older spelling, read with a warning)
///   acd_sampler: {uniform_share: 0.1, opening_weight: 4, centroid_spread: 0.3,
///                 opening_spread: 0.5}
///   worlds:                         # required, non-empty
///     - name: demo                  # required unless `scenario` gives one (its file stem)
///       scenario: ../demo.yaml      # a scenario file: workspace, start, goal, acd, collision
///                                   # (or an OMPL.app problem .cfg, planning/scenario_cfg.h)
///     - scenario: maps/arena.map.scen # a Moving AI scenario file, with
///       problem: 12                 # its problem (from 0); named "<file stem>_<problem>"
///                                   # (or problems: [0, 12, 24]: one world each, of the
///                                   # family "<file stem>", or <name> when given)
///     - name: gap                   # or inline:
///       workspace: {generator: wall_gap, seed: 1, wall_thickness: 1.0}   # or a file name
///       start: [2.5, 5.0]
///       goal: [7.5, 5.0]
///       passage_widths: [0.5, 0.2, 0.05]  # optional sweep: one world per width, named
///                                   # "<name>_w<width>", family <name>
///   robots:                         # default [{name: point, shape: point}]
///     - {name: disc, shape: disc, radius: 0.05}
///     - {name: bar, shape: polygon, polygon: [[x, y], ...], orientation: aligned}
///     - {name: own, shape: scenario}  # each world's scenario's robot (an OMPL.app .cfg's)
///     - {name: car, type: kinematic_car, length: 0.3, width: 0.15}   # a car: the keys of a
///                                   # scenario's car robot (planning/scenario.h)
///   cases:                          # required, non-empty; each a cross product
///     - worlds: [demo]              # optional subsets by name (default: all)
///       robots: [disc]
///       samplers: [uniform, acd]    # registry.h SamplerNames()
///       planners: [PRM]             # registry.h PlannerNames()
///       budgets: [{samples: 200}, {time_limit: 2}]   # samples: PRM, PRM_ACD, PRMstar
///     - robots: [car]               # cars only (not mixed with rigid robots in one case):
///       planners: [SyclopRRT, RRT]  # control planners (plan_car.h ControlPlannerNames())
///       decompositions: [acd, grid10, grid20]  # Syclop's (default [acd]); no `samplers`;
///       budgets: [{time_limit: 5}]  # time limits only. A world's scenario that is a car's
///                                   # gives its goal_radius (else 0.5).
///   targets:                        # optional acceptance targets (bench/targets.h), on rows
///     - where: {planner: PRM}       # world x robot x planner x budget (bench/summary.h
///       metric: acd.success_rate    # PlanningTargetVocabulary())
///       compare: ">="
///       value: 0.95
struct BenchSpec {
  std::string path;  ///< The file it was read from.
  std::string name, description;
  std::uint64_t seed = 1;
  int runs = 10;
  std::vector<BenchWorld> worlds;
  std::vector<BenchRobot> robots;
  std::vector<BenchCase> cases;  ///< In file order: groups, then worlds, robots, samplers,
                                 ///< planners, budgets.
  std::vector<Target> targets;   ///< Checked in summary.md.
  /// Accepted but worth a word ("b.yaml: acd.tau_rel: read as tau_diag ..."), for stderr;
  /// a scenario file's own warnings are in its world's scenario.
  std::vector<std::string> warnings;
};

/// Reads and validates a benchmark file; loads (generates) its worlds.
/// @throws InputError "<file>: <key path>: <rule>", e.g. "b.yaml: cases[0].planners[1]:
///         unknown planner 'PRN' (expected one of: ...)", for syntax errors (with the line),
///         unknown keys, wrong types, out-of-range values, unknown or duplicate names, a sample
///         budget with a planner other than PRM / PRMstar, and errors of a world or scenario file.
BenchSpec LoadBenchSpec(const std::string& path);

/// Which part of the runs to do: runs k (global index) with k % count == index - 1.
struct BenchShard {
  int index = 1;  ///< 1-based; in [1, count].
  int count = 1;  ///< >= 1.
};

/// Parses "I/N" (1 <= I <= N). @throws InputError "expected I/N ..., got '<text>'" otherwise.
BenchShard ParseBenchShard(const std::string& text);

/// One run to do: its place in the global order and its seed.
struct BenchRunId {
  int case_index = 0;
  int run = 0;               ///< 0-based within the case.
  std::uint64_t global = 0;  ///< case_index * runs + run.
  std::uint64_t seed = 0;
};

/// The seed of run `run` of the case with key `case_key`: a 64-bit mix (splitmix64 over an
/// FNV-1a hash of the key) of the base seed, the key and the run index. The same inputs give
/// the same seed on every machine, whatever the shard.
std::uint64_t BenchRunSeed(std::uint64_t base_seed, const std::string& case_key, int run);

/// The runs of `shard` in the global order (case-major, then run index), with `runs` runs per
/// case.
std::vector<BenchRunId> BenchRunsOfShard(const BenchSpec& spec, int runs, const BenchShard& shard);

}  // namespace acdplan::bench
