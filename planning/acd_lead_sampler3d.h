#pragma once
// The ACD decomposition as a lead in 3D worlds (R^3, SE(3)): acd_lead on the 3D ACD's
// adjacency graph (issue 12 on top of issue 11). Same law and widening schedule as the 2D
// lead (acd_lead_sampler.h), with 3D components and planar openings.

#include <ompl/base/StateSampler.h>

#include <Eigen/Core>
#include <cstdint>
#include <memory>

#include "acd/triangle_mesh.h"
#include "base/random.h"
#include "envs/free_space_decomposition3d.h"
#include "planning/acd_lead_sampler.h"
#include "planning/acd_sampler_options.h"
#include "planning/rejection_valid_state_sampler.h"

namespace acdplan::planning {

namespace internal {
class LeadDistribution3d;
enum class SpaceKind;
}  // namespace internal

/// The query a 3D lead is computed for: the reference points of the start and goal poses.
struct AcdLeadQuery3d {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  ///< [units].
  Eigen::Vector3d goal = Eigen::Vector3d::Zero();   ///< [units].
};

/// The lead's share of draws at openings in 3D scenarios (AcdLeadOptions::opening_share; 0.5
/// in 2D): a 3D passage is a small part of its rooms, a rigid body's pose through it narrow.
constexpr double kLeadOpeningShare3d = 0.8;

/// Draws states from the 3D lead distribution (internal::LeadDistribution3d), widened by the
/// schedule of AcdLeadOptions, the part picked by a stratified golden-ratio sequence as in 2D.
/// Spaces: RealVector(3), SE3.
class AcdLeadStateSampler3d : public ompl::base::StateSampler {
 public:
  AcdLeadStateSampler3d(const ompl::base::StateSpace* space,
                        std::shared_ptr<const internal::LeadDistribution3d> lead,
                        std::uint64_t seed);
  ~AcdLeadStateSampler3d() override;

  void sampleUniform(ompl::base::State* state) override;
  /// Uniform within `distance` of `near` (the lead plays no part).
  void sampleUniformNear(ompl::base::State* state, const ompl::base::State* near,
                         double distance) override;
  void sampleGaussian(ompl::base::State* state, const ompl::base::State* mean,
                      double stdDev) override;

  std::uint64_t draws() const { return draws_; }
  /// The level in force now (0 lead, 1 neighbours, 2 everything).
  int level() const;
  /// The part of the last sampleUniform(): a component index, -1 - an opening index, or
  /// AcdLeadStateSampler::kUniformPart.
  int last_part() const { return last_part_; }

 private:
  std::shared_ptr<const internal::LeadDistribution3d> lead_;
  internal::SpaceKind kind_;
  RandomEngine rng_engine_;
  double phase_ = 0.0;
  std::uint64_t draws_ = 0;
  int last_part_ = AcdLeadStateSampler::kUniformPart;
};

/// AcdLeadStateSampler3d's draws, the first valid one of at most `max_attempts` per sample().
class AcdLeadValidStateSampler3d : public RejectionValidStateSampler<AcdLeadStateSampler3d> {
 public:
  AcdLeadValidStateSampler3d(const ompl::base::SpaceInformation* si,
                             std::shared_ptr<const internal::LeadDistribution3d> lead,
                             std::uint64_t seed, int max_attempts);
};

/// Installs the 3D lead samplers on `si` as InstallAcdSamplers3d() installs the 3D ACD
/// samplers. `robot` (a mesh robot's body-frame surface; null for a point) gives the long axis
/// for the aligned orientations and the width below which an opening is penalised
/// (internal::RobotWidth3d: its smallest extent across its principal axes).
/// @throws InputError if an option is out of range; std::invalid_argument if the space is not
///         RealVector(3) or SE3 or the decomposition is empty.
void InstallAcdLeadSamplers3d(const std::shared_ptr<ompl::base::SpaceInformation>& si,
                              const envs::FreeSpaceDecomposition3d& decomposition,
                              const AcdLeadQuery3d& query, const AcdSamplerOptions& options,
                              const AcdLeadOptions& lead_options = {},
                              const acd::TriangleMesh* robot = nullptr);

}  // namespace acdplan::planning
