#include "planning/acd_samplers3d.h"

#include <ompl/base/SpaceInformation.h>

#include <atomic>
#include <stdexcept>

#include "planning/internal/acd_targets3d.h"
#include "planning/internal/space_access.h"
#include "planning/internal/space_access3d.h"

namespace acdplan::planning {

AcdStateSampler3d::AcdStateSampler3d(const ompl::base::StateSpace* space,
                                     std::shared_ptr<const internal::AcdTargets3d> targets,
                                     std::uint64_t seed)
    : ompl::base::StateSampler(space),
      targets_(std::move(targets)),
      kind_(internal::Classify3d(space, "3D ACD samplers")),
      rng_engine_(seed) {}

AcdStateSampler3d::~AcdStateSampler3d() = default;

void AcdStateSampler3d::sampleUniform(ompl::base::State* state) {
  for (int attempt = 0; attempt < 16; ++attempt) {
    const internal::AcdDraw3d draw = targets_->Draw(rng_engine_);
    if (draw.uniform) break;
    if (internal::SetFromDraw3d(kind_, space_, draw, state, rng_engine_)) return;
  }
  internal::SampleUniform(kind_, space_, state, rng_engine_);
}

void AcdStateSampler3d::sampleUniformNear(ompl::base::State* state, const ompl::base::State* near,
                                          double distance) {
  internal::SampleUniformNear(kind_, space_, state, near, distance, rng_engine_);
}

void AcdStateSampler3d::sampleGaussian(ompl::base::State* state, const ompl::base::State* mean,
                                       double stdDev) {
  internal::SampleGaussian(kind_, space_, state, mean, stdDev, rng_engine_);
}

AcdValidStateSampler3d::AcdValidStateSampler3d(
    const ompl::base::SpaceInformation* si, std::shared_ptr<const internal::AcdTargets3d> targets,
    std::uint64_t seed, int max_attempts)
    : RejectionValidStateSampler(si, "acd", max_attempts, std::move(targets), seed) {}

void InstallAcdSamplers3d(const std::shared_ptr<ompl::base::SpaceInformation>& si,
                          const envs::FreeSpaceDecomposition3d& decomposition,
                          const AcdSamplerOptions& options, const acd::TriangleMesh* robot) {
  internal::Classify3d(si->getStateSpace().get(),
                       "3D ACD samplers");  // Fail now, not inside the planner.
  internal::LongAxis3d axis;
  if (robot) axis = internal::PrincipalAxis(robot->vertices);
  auto targets = std::make_shared<const internal::AcdTargets3d>(decomposition, options, axis);
  const std::uint64_t seed = options.seed;
  const int attempts = options.max_attempts;
  auto counter = std::make_shared<std::atomic<std::uint64_t>>(0);
  si->getStateSpace()->setStateSamplerAllocator(
      [targets, seed, counter](const ompl::base::StateSpace* space) {
        return std::make_shared<AcdStateSampler3d>(space, targets, DeriveSeed(seed, (*counter)++));
      });
  si->setValidStateSamplerAllocator(
      [targets, seed, counter, attempts](const ompl::base::SpaceInformation* info) {
        return std::make_shared<AcdValidStateSampler3d>(info, targets,
                                                        DeriveSeed(seed, (*counter)++), attempts);
      });
}

}  // namespace acdplan::planning
