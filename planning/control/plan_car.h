#pragma once
// Plans a car (planning/control/car.h) through a 2D workspace with OMPL's control planners;
// Syclop's decomposition is the ACD (AcdDecomposition) or OMPL's grid.

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "acd/concavity_measure.h"
#include "acd/decomposition2d.h"
#include "collision/collision_mode.h"
#include "envs/robot.h"
#include "envs/workspace2d.h"
#include "planning/control/car.h"
#include "planning/tau_diag.h"

namespace acdplan::planning::control {

/// The control planners.
enum class ControlPlanner { kSyclopRrt, kSyclopEst, kRrt, kKpiece1, kEst, kPdst };
/// "SyclopRRT", "SyclopEST", "RRT", "KPIECE1", "EST", "PDST". @throws InputError if unknown.
ControlPlanner ParseControlPlanner(const std::string& name);
std::string ToString(ControlPlanner planner);
/// Every control planner's name, in the enum's order.
std::vector<std::string> ControlPlannerNames();

/// Syclop's workspace decomposition.
enum class DecompositionKind {
  kAcd,   ///< "acd": AcdDecomposition of the free space's ACD.
  kGrid,  ///< "grid": OMPL's GridDecomposition, `grid_cells` x `grid_cells` over the bounds.
};
/// "acd", "grid". @throws InputError if unknown.
DecompositionKind ParseDecompositionKind(const std::string& name);
std::string ToString(DecompositionKind kind);

/// One car query; `{}` is invalid only in `workspace`, `start`, `goal`.
struct CarQuery {
  envs::Workspace2d workspace;
  envs::Robot robot;  ///< Point, disc or polygon (the car's body).
  CarModel model = CarModel::kKinematic;
  CarOptions car;
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  ///< x, y, theta (speed and steering 0).
  /// x, y, theta: the goal pose must be free, but only its position is sought (goal_radius).
  Eigen::Vector3d goal = Eigen::Vector3d::Zero();
  double goal_radius = 0.5;  ///< Solved when the position is this close to the goal [units].
  ControlPlanner planner = ControlPlanner::kSyclopRrt;
  DecompositionKind decomposition = DecompositionKind::kAcd;  ///< Syclop planners only.
  int grid_cells = 10;                                        ///< kGrid: cells per side; >= 1.
  double tau_diag = kDefaultTauDiag;  ///< ACD tolerance / bounds diagonal (planning/tau_diag.h).
  acd::ConcavityMeasure measure = acd::ConcavityMeasure::kShortestPath;  ///< The ACD's measure.
  collision::CollisionMode collision_mode = collision::CollisionMode::kHullsExact;
  double time_limit = 5.0;  ///< [s], decomposition included.
  /// > 0: stop after this many evaluations of the planner's termination condition
  /// (ompl::base::IterationTerminationCondition) instead of at `time_limit`, so that a run
  /// depends on OMPL's seed only (tests).
  unsigned termination_checks = 0;
};

struct CarResult {
  bool solved = false;            ///< An exact solution (within goal_radius).
  double time_s = 0.0;            ///< Wall time, decomposition (cache look-up) included [s].
  double decomposition_ms = 0.0;  ///< The map's ACD cost (computed once; decomposition_cache.h).
  int regions = 0;                ///< Regions of Syclop's decomposition (0 for other planners).
  double path_duration = 0.0;     ///< Sum of the controls' durations [s].
  std::vector<std::vector<double>> path;  ///< States (copyToReals), start to end.
  /// The solution (exact or, when not solved, OMPL's approximate one if any) at every
  /// propagation step (PathControl::interpolate()), states as copyToReals; for pictures.
  std::vector<std::vector<double>> trajectory;
  /// The regions of Syclop's decomposition `trajectory` passes through, in order (consecutive
  /// repeats merged): the lead the tree followed in the end (Syclop keeps its own lead private).
  /// Empty for the other planners or without a trajectory.
  std::vector<int> visited_regions;
  /// kAcd: the free space's ACD whose components are the regions (empty otherwise).
  acd::Decomposition2d decomposition;
  std::uint64_t tree_states = 0;       ///< States of the planner's tree(s) (PlannerData).
  std::uint64_t collision_checks = 0;  ///< State validity checks.
};

/// Plans `query` (OMPL's global seed as the caller set it). Expected failures are results.
/// @throws InputError if the start or the goal pose is in collision or out of bounds.
CarResult PlanCar(const CarQuery& query);

}  // namespace acdplan::planning::control
