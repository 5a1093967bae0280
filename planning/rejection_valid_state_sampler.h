#pragma once
// A valid-state sampler made of a state sampler: its draws, kept when valid.

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/ValidStateSampler.h>

#include <cstdint>
#include <string>
#include <utility>

namespace acdplan::planning {

/// OMPL's ValidStateSampler over `StateSampler` (one of our state samplers: each instance owns
/// its seeded engine): sample() draws sampleUniform() and keeps the first valid state of at
/// most `max_attempts`, sampleNear() likewise with sampleUniformNear(). The ACD samplers
/// (2D and 3D, with or without a lead) differ only in their state sampler.
template <typename StateSampler>
class RejectionValidStateSampler : public ompl::base::ValidStateSampler {
 public:
  /// `name`: OMPL's sampler name; `sampler_args` follow the space in StateSampler's constructor.
  template <typename... SamplerArgs>
  RejectionValidStateSampler(const ompl::base::SpaceInformation* si, const std::string& name,
                             int max_attempts, SamplerArgs&&... sampler_args)
      : ompl::base::ValidStateSampler(si),
        sampler_(si->getStateSpace().get(), std::forward<SamplerArgs>(sampler_args)...) {
    name_ = name;
    setNrAttempts(static_cast<unsigned int>(max_attempts));
  }

  /// A valid state from the state sampler's distribution; false if none was found in the
  /// attempts.
  bool sample(ompl::base::State* state) override {
    for (unsigned int attempt = 0; attempt < attempts_; ++attempt) {
      sampler_.sampleUniform(state);
      ++candidates_;
      if (si_->isValid(state)) return true;
    }
    return false;
  }
  /// A valid state within `distance` of `near` (the state sampler's sampleUniformNear()).
  bool sampleNear(ompl::base::State* state, const ompl::base::State* near,
                  double distance) override {
    for (unsigned int attempt = 0; attempt < attempts_; ++attempt) {
      sampler_.sampleUniformNear(state, near, distance);
      ++candidates_;
      if (si_->isValid(state)) return true;
    }
    return false;
  }

  const StateSampler& state_sampler() const { return sampler_; }
  /// Candidates drawn so far (valid or not).
  std::uint64_t candidates() const { return candidates_; }

 private:
  StateSampler sampler_;
  std::uint64_t candidates_ = 0;
};

}  // namespace acdplan::planning
