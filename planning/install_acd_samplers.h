#pragma once
// The one call that puts the ACD samplers into any OMPL SpaceInformation.

#include <memory>

#include "acd/decomposition2d.h"
#include "planning/acd_sampler_options.h"

namespace ompl::base {
class SpaceInformation;
}

namespace acdplan::planning {

/// Installs the ACD samplers on `si`:
///  - si->setValidStateSamplerAllocator(): an AcdValidStateSampler (PRM, PRM*, EST, ...);
///  - si->getStateSpace()->setStateSamplerAllocator(): an AcdStateSampler (RRT, RRTConnect,
///    RRT*, LazyPRM, KPIECE1, ... and every valid-state sampler that draws from the space).
/// Call it before the planner's setup(). The targets are computed once and shared; the k-th
/// sampler allocated gets the seed DeriveSeed(options.seed, k), so one seed reproduces a
/// single-threaded run exactly. `decomposition` is of the 2D workspace the robot moves in
/// (acd::Decompose2d(envs::FreeSpace2d(workspace))); it is copied where needed.
///
///   auto si = setup.getSpaceInformation();                    // any OMPL SimpleSetup
///   acd::Decomposition2d acd = acd::Decompose2d(envs::FreeSpace2d(world), {/*tau=*/0.1});
///   planning::AcdSamplerOptions options;  options.seed = 42;
///   planning::InstallAcdSamplers(si, acd, options);
///   setup.setPlanner(std::make_shared<ompl::geometric::PRM>(si));
///   setup.solve(1.0);
///
/// @throws InputError if `options` are out of range; std::invalid_argument if the state
///         space is not RealVector(2|3), SE2 or SE3.
void InstallAcdSamplers(const std::shared_ptr<ompl::base::SpaceInformation>& si,
                        const acd::Decomposition2d& decomposition,
                        const AcdSamplerOptions& options = {});

/// Installs seeded plain uniform sampling on `si`'s state space (AcdStateSampler without
/// targets), so OMPL's own valid-state samplers (uniform, gaussian, bridge, ...), which draw
/// from the space's sampler, are reproducible from `seed` without OMPL's global seed.
void InstallSeededUniformSampler(const std::shared_ptr<ompl::base::SpaceInformation>& si,
                                 std::uint64_t seed);

}  // namespace acdplan::planning
