#pragma once
// Samplers and planners by name, for scenarios, the command line and benchmarks.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "acd/decomposition2d.h"
#include "planning/acd_sampler_options.h"

namespace ompl::base {
class Planner;
class SpaceInformation;
}  // namespace ompl::base

namespace acdplan::planning {

/// "uniform", "gaussian", "bridge", "obstacle_based", "max_clearance", "acd".
std::vector<std::string> SamplerNames();

/// "PRM", "PRM_ACD" (planning/acd_prm.h), "PRMstar", "LazyPRM", "RRT", "RRTConnect",
/// "RRTstar", "EST", "KPIECE1", "BKPIECE1", "SBL".
std::vector<std::string> PlannerNames();

/// Planners that accept a sample budget (the Figure-4 protocol): "PRM", "PRM_ACD", "PRMstar".
bool SupportsSampleBudget(const std::string& planner);

/// Installs the sampler `name` on `si`. "acd": InstallAcdSamplers(si, decomposition, options).
/// Any other: seeded uniform state sampling (InstallSeededUniformSampler(si, options.seed))
/// and OMPL's valid-state sampler of that name (UniformValidStateSampler,
/// GaussianValidStateSampler, BridgeTestValidStateSampler, ObstacleBasedValidStateSampler,
/// MaximizeClearanceValidStateSampler), so every sampler is reproducible from the seed.
/// @throws acd::InputError for an unknown name (listing the known ones).
void InstallSampler(const std::string& name,
                    const std::shared_ptr<ompl::base::SpaceInformation>& si,
                    const acd::Decomposition2d& decomposition, const AcdSamplerOptions& options);

/// A new geometric planner `name` on `si` with OMPL's default parameters. "PRM_ACD" connects
/// along `decomposition` (of the workspace the robot moves in) with random picks seeded by
/// `seed`; the other planners ignore both.
/// @throws acd::InputError for an unknown name (listing the known ones);
///         std::invalid_argument for "PRM_ACD" without a decomposition.
std::shared_ptr<ompl::base::Planner> MakePlanner(
    const std::string& name, const std::shared_ptr<ompl::base::SpaceInformation>& si,
    const acd::Decomposition2d* decomposition = nullptr, std::uint64_t seed = 1);

}  // namespace acdplan::planning
