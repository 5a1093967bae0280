#include "planning/acd_valid_state_sampler.h"

#include <ompl/base/SpaceInformation.h>

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
    : ompl::base::ValidStateSampler(si),
      sampler_(si->getStateSpace().get(), std::move(targets), seed) {
  name_ = "acd";
  setNrAttempts(static_cast<unsigned int>(max_attempts));
}

bool AcdValidStateSampler::sample(ompl::base::State* state) {
  for (unsigned int attempt = 0; attempt < attempts_; ++attempt) {
    sampler_.sampleUniform(state);
    ++candidates_;
    if (si_->isValid(state)) return true;
  }
  return false;
}

bool AcdValidStateSampler::sampleNear(ompl::base::State* state, const ompl::base::State* near,
                                      double distance) {
  for (unsigned int attempt = 0; attempt < attempts_; ++attempt) {
    sampler_.sampleUniformNear(state, near, distance);
    ++candidates_;
    if (si_->isValid(state)) return true;
  }
  return false;
}

}  // namespace acdplan::planning
