#include "planning/acd_valid_state_sampler.h"

#include "base/random.h"
#include "planning/internal/acd_targets.h"

namespace acdplan::planning {

AcdValidStateSampler::AcdValidStateSampler(const ompl::base::SpaceInformation* si,
                                           const acd::Decomposition2d& decomposition,
                                           const AcdSamplerOptions& options)
    : AcdValidStateSampler(si, std::make_shared<internal::AcdTargets>(decomposition, options),
                           DeriveSeed(options.seed, 0), options.max_attempts) {}

AcdValidStateSampler::AcdValidStateSampler(const ompl::base::SpaceInformation* si,
                                           std::shared_ptr<const internal::AcdTargets> targets,
                                           std::uint64_t seed, int max_attempts)
    : RejectionValidStateSampler(si, "acd", max_attempts, std::move(targets), seed) {}

}  // namespace acdplan::planning
