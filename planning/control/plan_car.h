#pragma once
// Plans a car (planning/control/car.h) through a 2D workspace with OMPL's control planners;
// Syclop's decomposition is the ACD (AcdDecomposition) or OMPL's grid.

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "envs/robot.h"
#include "envs/workspace2d.h"
#include "planning/control/car.h"

namespace acdplan::planning::control {

/// The control planners.
enum class ControlPlanner { kSyclopRrt, kSyclopEst, kRrt, kKpiece1, kEst, kPdst };
/// "SyclopRRT", "SyclopEST", "RRT", "KPIECE1", "EST", "PDST". @throws InputError if unknown.
ControlPlanner ParseControlPlanner(const std::string& name);
std::string ToString(ControlPlanner planner);

/// Syclop's workspace decomposition.
enum class DecompositionKind {
  kAcd,   ///< "acd": AcdDecomposition of the free space's ACD.
  kGrid,  ///< "grid": OMPL's GridDecomposition, `grid_cells` x `grid_cells` over the bounds.
};

/// One car query; `{}` is invalid only in `workspace`, `start`, `goal`.
struct CarQuery {
  envs::Workspace2d workspace;
  envs::Robot robot;  ///< Point, disc or polygon (the car's body).
  CarModel model = CarModel::kKinematic;
  CarOptions car;
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  ///< x, y, theta (speed and steering 0).
  Eigen::Vector3d goal = Eigen::Vector3d::Zero();   ///< x, y (theta ignored).
  double goal_radius = 0.5;  ///< Solved when the position is this close to the goal [units].
  ControlPlanner planner = ControlPlanner::kSyclopRrt;
  DecompositionKind decomposition = DecompositionKind::kAcd;  ///< Syclop planners only.
  int grid_cells = 10;                                        ///< kGrid: cells per side; >= 1.
  double tau_diag = 0.02;   ///< ACD tolerance / bounds diagonal (as scenarios).
  double time_limit = 5.0;  ///< [s], decomposition included.
};

struct CarResult {
  bool solved = false;            ///< An exact solution (within goal_radius).
  double time_s = 0.0;            ///< Wall time, decomposition (cache look-up) included [s].
  double decomposition_ms = 0.0;  ///< The map's ACD cost (computed once; decomposition_cache.h).
  int regions = 0;                ///< Regions of Syclop's decomposition (0 for other planners).
  double path_duration = 0.0;     ///< Sum of the controls' durations [s].
  std::vector<std::vector<double>> path;  ///< States (copyToReals), start to end.
};

/// Plans `query` (OMPL's global seed as the caller set it). Expected failures are results.
/// @throws InputError if the start is in collision.
CarResult PlanCar(const CarQuery& query);

}  // namespace acdplan::planning::control
