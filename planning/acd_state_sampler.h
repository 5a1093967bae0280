#pragma once
// AcdStateSampler: the ACD sampling distribution (dissertation Ch. VI.C, Algorithm 10) as an
// OMPL state sampler, without validity checks -- for the planners that draw from the state
// space's sampler rather than a valid-state sampler (RRT, RRTConnect, RRT*, LazyPRM, ...).

#include <ompl/base/StateSampler.h>

#include <cstdint>
#include <memory>

#include "acd/decomposition2d.h"
#include "base/random.h"
#include "planning/acd_sampler_options.h"

namespace acdplan::planning {

namespace internal {
class AcdTargets;
enum class SpaceKind;
}  // namespace internal

/// Draws states around the centroids of an ACD's components and the midpoints of its
/// openings, plus a share of uniform states (see AcdSamplerOptions for the distribution).
///
/// Spaces: RealVectorStateSpace of dimension 2 (x, y) or 3 (x, y, z), SE2StateSpace,
/// SE3StateSpace. The decomposition is of a 2D workspace, so targets give x and y only; z
/// (3D spaces) is uniform over the space's bounds and SE(3) rotations are uniform (or a turn
/// about z by the aligned yaw). Draws whose x, y fall outside the bounds are redrawn (up to 16
/// times, then a uniform state is used), so the distribution is not piled on the boundary.
///
/// Thread safety: each instance owns its random engine (RandomEngine, seeded at
/// construction); the targets are immutable and shared. No global random state is used, so
/// the same seed gives the same samples. Instances are not themselves shared between threads
/// (OMPL allocates one per planner thread).
class AcdStateSampler : public ompl::base::StateSampler {
 public:
  /// @throws InputError if `options` are out of range; std::invalid_argument if `space`
  ///         is not supported.
  AcdStateSampler(const ompl::base::StateSpace* space, const acd::Decomposition2d& decomposition,
                  const AcdSamplerOptions& options = {});
  /// Shares precomputed targets (used by InstallAcdSamplers()); `seed` seeds this instance.
  AcdStateSampler(const ompl::base::StateSpace* space,
                  std::shared_ptr<const internal::AcdTargets> targets, std::uint64_t seed);
  ~AcdStateSampler() override;

  /// A state from the ACD distribution (OMPL calls the main draw "uniform").
  void sampleUniform(ompl::base::State* state) override;
  /// A state within `distance` of `near` (per coordinate; angles too), drawn around the
  /// targets within `distance` of `near` when there are any, else uniformly in that box.
  void sampleUniformNear(ompl::base::State* state, const ompl::base::State* near,
                         double distance) override;
  /// Gaussian around `mean` with `stdDev` per coordinate (no targets involved).
  void sampleGaussian(ompl::base::State* state, const ompl::base::State* mean,
                      double stdDev) override;

  /// True if the last sampleUniform() used a target (false: a uniform draw).
  bool last_was_targeted() const { return last_targeted_; }

 private:
  std::shared_ptr<const internal::AcdTargets> targets_;
  internal::SpaceKind kind_;
  RandomEngine rng_engine_;
  bool last_targeted_ = false;
};

}  // namespace acdplan::planning
