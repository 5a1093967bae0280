#include "planning/install_acd_samplers.h"

#include <ompl/base/SpaceInformation.h>

#include <atomic>

#include "base/random.h"
#include "planning/acd_state_sampler.h"
#include "planning/acd_valid_state_sampler.h"
#include "planning/internal/acd_targets.h"
#include "planning/internal/space_access.h"

namespace acdplan::planning {

namespace {

void InstallTargets(const std::shared_ptr<ompl::base::SpaceInformation>& si,
                    std::shared_ptr<const internal::AcdTargets> targets, bool valid_sampler) {
  internal::Classify(si->getStateSpace().get());  // Fail now, not inside the planner.
  const std::uint64_t seed = targets->options().seed;
  const int attempts = targets->options().max_attempts;
  // One counter for both allocators: every sampler gets its own derived seed.
  auto counter = std::make_shared<std::atomic<std::uint64_t>>(0);
  si->getStateSpace()->setStateSamplerAllocator(
      [targets, seed, counter](const ompl::base::StateSpace* space) {
        return std::make_shared<AcdStateSampler>(space, targets, DeriveSeed(seed, (*counter)++));
      });
  if (valid_sampler) {
    si->setValidStateSamplerAllocator(
        [targets, seed, counter, attempts](const ompl::base::SpaceInformation* info) {
          return std::make_shared<AcdValidStateSampler>(info, targets,
                                                        DeriveSeed(seed, (*counter)++), attempts);
        });
  }
}

}  // namespace

void InstallAcdSamplers(const std::shared_ptr<ompl::base::SpaceInformation>& si,
                        const acd::Decomposition2d& decomposition,
                        const AcdSamplerOptions& options) {
  InstallTargets(si, std::make_shared<internal::AcdTargets>(decomposition, options), true);
}

void InstallSeededUniformSampler(const std::shared_ptr<ompl::base::SpaceInformation>& si,
                                 std::uint64_t seed) {
  AcdSamplerOptions options;
  options.seed = seed;
  options.uniform_share = 1.0;
  InstallTargets(si, std::make_shared<internal::AcdTargets>(acd::Decomposition2d{}, options),
                 false);
}

}  // namespace acdplan::planning
