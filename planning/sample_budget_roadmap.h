#pragma once
// The Figure-4 protocol (dissertation Ch. I, Fig. 4 and Ch. VI.C): a roadmap of exactly N
// collision-free samples, then a connectivity check.

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "acd/decomposition2d.h"
#include "envs/free_space_decomposition3d.h"

namespace ompl::base {
class SpaceInformation;
class State;
}  // namespace ompl::base

namespace acdplan::planning {

/// Options for BuildSampleBudgetRoadmap(); `{}` is invalid only in `samples`.
struct SampleBudgetOptions {
  int samples = 200;  ///< Collision-free samples to place; >= 1.
  bool star = false;  ///< Connect with PRM*'s k = e(1 + 1/d) log n rule, else k = 10.
  /// If set, connect as PRM_ACD (planning/acd_prm.h) with this decomposition of the workspace.
  const acd::Decomposition2d* acd_connections = nullptr;
  /// If set (and acd_connections is not), connect as PRM_ACD along this 3D decomposition.
  std::shared_ptr<const envs::FreeSpaceDecomposition3d> acd_connections_3d;
  std::uint64_t seed = 1;    ///< Seed of PRM_ACD's random picks.
  int max_failed_calls = 0;  ///< Give up after this many failed sample() calls in a row;
                             ///< 0 = 10 * samples + 100.
};

/// What BuildSampleBudgetRoadmap() found.
struct SampleBudgetRoadmap {
  bool solved = false;  ///< Start and goal are in one connected component.
  int samples = 0;      ///< Collision-free samples placed (== options.samples unless
                        ///< the sampler gave up).
  std::vector<std::vector<double>> vertices;  ///< Roadmap states (space->copyToReals);
                                              ///< start, goal and the samples.
  std::vector<std::pair<int, int>> edges;     ///< Roadmap edges (indices into `vertices`).
  std::vector<std::vector<double>> path;      ///< Start to goal through the roadmap when solved.
  double path_length = 0.0;                   ///< Length of `path` in the space's metric.
};

/// Draws exactly `options.samples` collision-free states from si->allocValidStateSampler(),
/// adds them and `start`, `goal` to an OMPL PRM roadmap (each new milestone is connected to
/// its nearest neighbours by the space's motion validator, as PRM does), and reports whether
/// start and goal ended up in one connected component, with the shortest roadmap path then.
/// No time limit: the budget is the number of samples, so the result depends on the seeds
/// only. `si` must be set up (validity checker installed); start and goal must be valid.
/// @throws std::invalid_argument if `options.samples` < 1 or start / goal is invalid.
SampleBudgetRoadmap BuildSampleBudgetRoadmap(
    const std::shared_ptr<ompl::base::SpaceInformation>& si, const ompl::base::State* start,
    const ompl::base::State* goal, const SampleBudgetOptions& options = {});

}  // namespace acdplan::planning
