#pragma once
// The ACD samplers in 3D worlds (R^3, SE(3)): state and valid-state samplers drawing around the
// components and openings of the free space's 3D ACD (dissertation Ch. V and VI.C), and the
// call that installs them.

#include <ompl/base/StateSampler.h>

#include <Eigen/Core>
#include <cstdint>
#include <memory>

#include "acd/triangle_mesh.h"
#include "base/random.h"
#include "envs/free_space_decomposition3d.h"
#include "planning/acd_sampler_options.h"
#include "planning/rejection_valid_state_sampler.h"

namespace acdplan::planning {

namespace internal {
class AcdTargets3d;
enum class SpaceKind;
}  // namespace internal

/// Draws states around the centroids of the 3D components and of the openings of a
/// envs::FreeSpaceDecomposition3d, plus a share of uniform states (the distribution is
/// internal::AcdTargets3d's, planning/internal/acd_targets3d.h). Spaces: RealVector(3), SE3.
/// Draws outside the bounds are redrawn (up to 16 times, then uniform). Each instance owns its
/// seeded engine; the targets are immutable and shared.
class AcdStateSampler3d : public ompl::base::StateSampler {
 public:
  /// @throws std::invalid_argument if `space` is not RealVector(3) or SE3.
  AcdStateSampler3d(const ompl::base::StateSpace* space,
                    std::shared_ptr<const internal::AcdTargets3d> targets, std::uint64_t seed);
  ~AcdStateSampler3d() override;

  /// A state from the ACD distribution (OMPL calls the main draw "uniform").
  void sampleUniform(ompl::base::State* state) override;
  /// Uniform within `distance` of `near` (no targets: the tree planners' local step).
  void sampleUniformNear(ompl::base::State* state, const ompl::base::State* near,
                         double distance) override;
  /// Gaussian around `mean` with `stdDev` per coordinate.
  void sampleGaussian(ompl::base::State* state, const ompl::base::State* mean,
                      double stdDev) override;

 private:
  std::shared_ptr<const internal::AcdTargets3d> targets_;
  internal::SpaceKind kind_;
  RandomEngine rng_engine_;
};

/// AcdStateSampler3d's draws kept when valid (up to `max_attempts` per call).
class AcdValidStateSampler3d : public RejectionValidStateSampler<AcdStateSampler3d> {
 public:
  AcdValidStateSampler3d(const ompl::base::SpaceInformation* si,
                         std::shared_ptr<const internal::AcdTargets3d> targets, std::uint64_t seed,
                         int max_attempts);
};

/// Installs the 3D ACD samplers on `si` as InstallAcdSamplers() does in 2D (valid-state sampler
/// allocator and state sampler allocator; the k-th sampler gets DeriveSeed(options.seed, k)).
/// `robot` (a mesh robot's body-frame surface; null for a point) gives the long axis (the
/// principal axis of its vertices, when it is at least 1.5 times the next: then
/// options.orientation kAligned turns that axis along the openings' normals) and the length
/// and thickness that scale the spread at openings (internal::AcdTargets3d).
/// @throws InputError if `options` are out of range; std::invalid_argument if the space is
///         not RealVector(3) or SE3.
void InstallAcdSamplers3d(const std::shared_ptr<ompl::base::SpaceInformation>& si,
                          const envs::FreeSpaceDecomposition3d& decomposition,
                          const AcdSamplerOptions& options,
                          const acd::TriangleMesh* robot = nullptr);

}  // namespace acdplan::planning
