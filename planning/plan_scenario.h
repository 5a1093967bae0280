#pragma once
// Runs a Scenario: free space, ACD, collision world, OMPL planner and sampler; reports.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "acd/decompose2d.h"
#include "acd/decomposition2d.h"
#include "envs/free_space_decomposition3d.h"
#include "planning/scenario.h"

namespace acdplan::planning {

/// What a car scenario's control planner did (Scenario::car; planning/control/plan_car.h).
struct CarPlan {
  control::ControlPlanner planner = control::ControlPlanner::kSyclopRrt;
  /// Syclop's regions: the ACD's components (kAcd) or grid cells (kGrid); nullopt for the
  /// planners without a decomposition.
  std::optional<control::DecompositionKind> decomposition;
  int grid_cells = 0;  ///< kGrid: cells per side.
  int regions = 0;     ///< Regions of Syclop's decomposition (0 without one).
  /// The regions the final trajectory passes through (consecutive repeats merged): the lead
  /// the tree followed; ACD region i = decomposition.components[i], a grid's as OMPL numbers
  /// its cells.
  std::vector<int> visited_regions;
  /// The solution at every propagation step (x, y, yaw[, v, phi]); OMPL's approximate
  /// solution when not solved (pictures only).
  std::vector<std::vector<double>> trajectory;
  double duration_s = 0.0;  ///< The solution's duration (the sum of its controls') [s].
};

/// What PlanScenario() did and found.
struct PlanResult {
  bool solved = false;  ///< Exact solution (time budget) / start and goal connected
                        ///< (sample budget).
  SamplerType sampler = SamplerType::kAcd;
  PlannerType planner = PlannerType::kPrm;
  std::string budget;             ///< "200 samples" or "5 s".
  double time_s = 0.0;            ///< Wall time of the whole run, decomposition included [s].
  double decomposition_ms = 0.0;  ///< Free space + ACD as this run paid it [ms]: the whole
                                  ///< computation, or only the cache look-up on a map seen
                                  ///< before (DecomposeFreeSpaceCached()).
  double decomposition_compute_ms = 0.0;  ///< What computing the map's ACD cost [ms].
  bool decomposition_cached = false;      ///< True if the ACD came from the cache.
  std::uint64_t samples = 0;  ///< Sample budget: collision-free samples placed; time budget:
                              ///< vertices of the planner's roadmap or tree(s).
  std::uint64_t collision_checks = 0;  ///< State validity checks (samples and motions).
  double path_length = 0.0;  ///< In the state space's metric (SE(2): OMPL's weighted sum); 0
                             ///< without a solution.
  int components = 0, openings = 0;
  std::vector<std::vector<double>> path;      ///< States from start to goal (x, y[, yaw]).
  std::vector<std::vector<double>> vertices;  ///< Roadmap / tree vertices (for pictures).
  std::vector<std::pair<int, int>> edges;     ///< Roadmap / tree edges.
  acd::Decomposition2d decomposition;         ///< The ACD of the free space (2D).
  /// 3D scenarios: the 3D ACD of the free space (components and openings); path states are
  /// then x, y, z (point) or x, y, z, qx, qy, qz, qw (mesh robot, OMPL's SE3 reals).
  std::shared_ptr<const envs::FreeSpaceDecomposition3d> decomposition3d;
  std::vector<std::string> notes;  ///< What the planner should tell the user (3D free space).
  /// Car scenarios: the control planner's part. Then `samples` are the tree's states,
  /// `path_length` the solution's duration [s], `path` the states at the controls' ends,
  /// `components` Syclop's regions and `decomposition` the ACD only with `decomposition: acd`.
  std::optional<CarPlan> car;
};

/// The ACD options of `scenario`: tau = tau_diag x the bounds' diagonal, its measure.
acd::Decompose2dOptions ScenarioAcdOptions(const Scenario& scenario);

/// Plans `scenario`: free space (envs::FreeSpace2d), its ACD (tau = tau_diag x bounds diagonal;
/// from the process's cache when the map was decomposed before, planning/decomposition_cache.h),
/// a collision::CollisionWorld (robot kept inside the bounds too), the state space (R^2 for a
/// point or disc robot, SE(2) for a polygon robot), the sampler installed with the scenario's
/// seed, then either the Figure-4 protocol (scenario.samples > 0:
/// BuildSampleBudgetRoadmap()) or the planner on the time limit. The path is reported raw,
/// not simplified, so lengths compare planners rather than the simplifier.
/// A 3D scenario (dimension 3) runs PlanScenario3d() (planning/plan_scenario3d.h) instead, a
/// car scenario PlanCarScenario() (planning/control/plan_car_scenario.h).
/// Expected failures (no solution) are results; only bad input throws.
/// @throws InputError if the start or the goal is in collision or out of bounds.
PlanResult PlanScenario(const Scenario& scenario);

/// Seeds OMPL's global random generator (used by the planners themselves, e.g. PRM's
/// expansion step, RRT's goal bias) and sets OMPL's log level to warnings (`quiet`) -- for a
/// command-line process; call once, before any planner exists. The samplers never use it.
void ConfigureOmpl(std::uint64_t seed, bool quiet);

/// The result as JSON: solved, sampler, planner, budget, time_s, decomposition_ms, samples,
/// collision_checks, path_length, components, openings, path, and the scenario's file.
std::string PlanResultToJson(const Scenario& scenario, const PlanResult& result);

/// An SVG picture (2D): obstacles, ACD components and openings, roadmap vertices and edges,
/// the path, start and goal (a car: CarPlanToSvg()). 3D: PlanScene3d() (plan_picture3d.h) in an
/// oblique orthographic view, +z up.
std::string PlanResultToSvg(const Scenario& scenario, const PlanResult& result);

}  // namespace acdplan::planning
