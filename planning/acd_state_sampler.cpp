#include "planning/acd_state_sampler.h"

#include "base/random.h"
#include "planning/internal/acd_targets.h"
#include "planning/internal/space_access.h"

namespace acdplan::planning {

AcdStateSampler::AcdStateSampler(const ompl::base::StateSpace* space,
                                 const acd::Decomposition2d& decomposition,
                                 const AcdSamplerOptions& options)
    : AcdStateSampler(space, std::make_shared<internal::AcdTargets>(decomposition, options),
                      DeriveSeed(options.seed, 0)) {}

AcdStateSampler::AcdStateSampler(const ompl::base::StateSpace* space,
                                 std::shared_ptr<const internal::AcdTargets> targets,
                                 std::uint64_t seed)
    : ompl::base::StateSampler(space),
      targets_(std::move(targets)),
      kind_(internal::Classify(space)),
      rng_engine_(seed) {}

AcdStateSampler::~AcdStateSampler() = default;

void AcdStateSampler::sampleUniform(ompl::base::State* state) {
  for (int attempt = 0; attempt < 16; ++attempt) {
    const internal::AcdDraw draw = targets_->Draw(rng_engine_);
    if (draw.uniform) break;
    if (internal::SetFromDraw(kind_, space_, draw, state, rng_engine_)) {
      last_targeted_ = true;
      return;
    }
  }
  last_targeted_ = false;
  internal::SampleUniform(kind_, space_, state, rng_engine_);
}

void AcdStateSampler::sampleUniformNear(ompl::base::State* state, const ompl::base::State* near,
                                        double distance) {
  // Angles (and z) uniformly near `near`; x, y around a nearby target when one is drawn.
  internal::SampleUniformNear(kind_, space_, state, near, distance, rng_engine_);
  const Eigen::Vector2d centre = internal::Xy(kind_, near);
  for (int attempt = 0; attempt < 16; ++attempt) {
    const internal::AcdDraw draw = targets_->DrawNear(rng_engine_, centre, distance);
    if (draw.uniform) return;
    if ((draw.position - centre).cwiseAbs().maxCoeff() <= distance &&
        internal::SetXy(kind_, space_, state, draw.position)) {
      return;
    }
  }
}

void AcdStateSampler::sampleGaussian(ompl::base::State* state, const ompl::base::State* mean,
                                     double stdDev) {
  internal::SampleGaussian(kind_, space_, state, mean, stdDev, rng_engine_);
}

}  // namespace acdplan::planning
