#include "planning/acd_lead_sampler3d.h"

#include <ompl/base/SpaceInformation.h>

#include <atomic>
#include <cmath>
#include <stdexcept>

#include "base/input_error.h"
#include "planning/internal/lead3d.h"
#include "planning/internal/space_access.h"
#include "planning/internal/space_access3d.h"

namespace acdplan::planning {

AcdLeadStateSampler3d::AcdLeadStateSampler3d(
    const ompl::base::StateSpace* space, std::shared_ptr<const internal::LeadDistribution3d> lead,
    std::uint64_t seed)
    : ompl::base::StateSampler(space),
      lead_(std::move(lead)),
      kind_(internal::Classify3d(space, "3D acd_lead")),
      rng_engine_(seed),
      phase_(UniformReal(rng_engine_, 0.0, 1.0)) {}

AcdLeadStateSampler3d::~AcdLeadStateSampler3d() = default;

int AcdLeadStateSampler3d::level() const { return lead_->LevelAfter(draws_); }

void AcdLeadStateSampler3d::sampleUniform(ompl::base::State* state) {
  const int level = lead_->LevelAfter(draws_);
  const double pick = internal::StratifiedPick(phase_, draws_++);
  for (int attempt = 0; attempt < 16; ++attempt) {
    int part = AcdLeadStateSampler::kUniformPart;
    const internal::AcdDraw3d draw = lead_->Draw(rng_engine_, level, pick, &part);
    if (draw.uniform) break;
    if (internal::SetFromDraw3d(kind_, space_, draw, state, rng_engine_)) {
      last_part_ = part;
      return;
    }
  }
  last_part_ = AcdLeadStateSampler::kUniformPart;
  internal::SampleUniform(kind_, space_, state, rng_engine_);
}

void AcdLeadStateSampler3d::sampleUniformNear(ompl::base::State* state,
                                              const ompl::base::State* near, double distance) {
  internal::SampleUniformNear(kind_, space_, state, near, distance, rng_engine_);
}

void AcdLeadStateSampler3d::sampleGaussian(ompl::base::State* state, const ompl::base::State* mean,
                                           double stdDev) {
  internal::SampleGaussian(kind_, space_, state, mean, stdDev, rng_engine_);
}

AcdLeadValidStateSampler3d::AcdLeadValidStateSampler3d(
    const ompl::base::SpaceInformation* si,
    std::shared_ptr<const internal::LeadDistribution3d> lead, std::uint64_t seed, int max_attempts)
    : RejectionValidStateSampler(si, "acd_lead", max_attempts, std::move(lead), seed) {}

void InstallAcdLeadSamplers3d(const std::shared_ptr<ompl::base::SpaceInformation>& si,
                              const envs::FreeSpaceDecomposition3d& decomposition,
                              const AcdLeadQuery3d& query, const AcdSamplerOptions& options,
                              const AcdLeadOptions& lead_options, const acd::TriangleMesh* robot) {
  if (!(lead_options.narrow_penalty >= 1)) {
    throw InputError("acd_lead: narrow_penalty: expected a number >= 1");
  }
  CheckAcdSamplerOptions(options);
  internal::Classify3d(si->getStateSpace().get(),
                       "3D acd_lead");  // Fail now, not inside the planner.
  internal::LeadQuery3d lead_query;
  lead_query.start = query.start;
  lead_query.goal = query.goal;
  internal::LongAxis3d axis;
  if (robot) {
    axis = internal::PrincipalAxis(robot->vertices);
    lead_query.robot_width = internal::RobotWidth3d(robot->vertices);
  }
  auto lead = std::make_shared<const internal::LeadDistribution3d>(decomposition, lead_query,
                                                                   options, lead_options, axis);
  const std::uint64_t seed = options.seed;
  const int attempts = options.max_attempts;
  auto counter = std::make_shared<std::atomic<std::uint64_t>>(0);
  si->getStateSpace()->setStateSamplerAllocator(
      [lead, seed, counter](const ompl::base::StateSpace* space) {
        return std::make_shared<AcdLeadStateSampler3d>(space, lead, DeriveSeed(seed, (*counter)++));
      });
  si->setValidStateSamplerAllocator(
      [lead, seed, counter, attempts](const ompl::base::SpaceInformation* info) {
        return std::make_shared<AcdLeadValidStateSampler3d>(
            info, lead, DeriveSeed(seed, (*counter)++), attempts);
      });
}

}  // namespace acdplan::planning
