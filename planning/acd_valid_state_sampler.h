#pragma once
// AcdValidStateSampler: PRM_ACD's sampling (dissertation Ch. VI.C, Algorithm 10) as an OMPL
// valid-state sampler -- the robot placed around ACD component centroids and openings, kept
// if collision free.

#include <cstdint>
#include <memory>

#include "acd/decomposition2d.h"
#include "planning/acd_sampler_options.h"
#include "planning/acd_state_sampler.h"
#include "planning/rejection_valid_state_sampler.h"

namespace acdplan::planning {

/// Draws candidates from AcdStateSampler's distribution and returns the first valid one
/// (at most `options.max_attempts` candidates per call; OMPL's setNrAttempts() changes it).
///
/// Algorithm 10 generates k samples around every centroid and opening in turn; this sampler
/// draws the target at random with the weights of AcdSamplerOptions instead, so any sample
/// budget works, the distribution does not depend on how many samples were taken before, and
/// the uniform share keeps it probabilistically complete.
///
/// Thread safety and spaces: as AcdStateSampler (own seeded engine, no global random state).
class AcdValidStateSampler : public RejectionValidStateSampler<AcdStateSampler> {
 public:
  /// @throws InputError if `options` are out of range; std::invalid_argument if the
  ///         space of `si` is not supported.
  AcdValidStateSampler(const ompl::base::SpaceInformation* si,
                       const acd::Decomposition2d& decomposition,
                       const AcdSamplerOptions& options = {});
  /// Shares precomputed targets (used by InstallAcdSamplers()); `seed` seeds this instance.
  AcdValidStateSampler(const ompl::base::SpaceInformation* si,
                       std::shared_ptr<const internal::AcdTargets> targets, std::uint64_t seed,
                       int max_attempts);
};

}  // namespace acdplan::planning
