#pragma once
// The ACD decomposition as a lead for geometric planning (issue 12): samples concentrated on
// the shortest chain of ACD components from the start to the goal, widened as Syclop
// re-weights its lead (Plaku, Kavraki and Vardi, "Motion planning with dynamics by a
// synergistic combination of layers of planning", IEEE T-RO 2010) when the chain alone has
// not been enough.

#include <ompl/base/StateSampler.h>

#include <Eigen/Core>
#include <cstdint>
#include <memory>

#include "acd/decomposition2d.h"
#include "base/random.h"
#include "envs/robot.h"
#include "planning/acd_sampler_options.h"
#include "planning/rejection_valid_state_sampler.h"

namespace acdplan::planning {

namespace internal {
class LeadDistribution;
enum class SpaceKind;
}  // namespace internal

/// The query the lead is computed for.
struct AcdLeadQuery {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();  ///< Reference point at the start [units].
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();   ///< Reference point at the goal [units].
  double robot_width = 0.0;  ///< RobotWidth(): openings shorter than this are penalised.
};

/// Options of the lead; `{}` is valid.
///
/// Widening schedule (a budget schedule, so a run depends on its seed only): each sampler
/// instance counts its draws (candidates, valid or not). The first `stage` draws follow the
/// lead (level 0), the next 2 x `stage` also the lead's neighbours (level 1), and every later
/// draw the whole decomposition (level 2), where stage = max(min_stage_draws,
/// stage_draws_per_part x (components + openings of the lead)). A lead of 20 parts keeps its
/// first 1000 draws; in the sample-budget protocol (100 samples) a correct lead is never
/// widened, while a time-budget run that stays unsolved reaches level 2 within milliseconds
/// to tenths of a second.
struct AcdLeadOptions {
  double narrow_penalty = 100.0;  ///< Cost factor of an opening shorter than the robot; >= 1.
  int stage_draws_per_part = 50;  ///< Draws per lead part before widening; >= 1.
  int min_stage_draws = 200;      ///< Lower bound of the first stage [draws]; >= 1.
  double opening_share = 0.5;     ///< Share of the targeted draws at openings; in [0, 1].
  double opening_jitter = 0.1;    ///< Across-opening Gaussian sigma / opening length; >= 0.
  /// Share of uniform draws while the lead (or its neighbourhood) is followed, in [0, 1];
  /// level 2 uses AcdSamplerOptions::uniform_share (probabilistic completeness).
  double lead_uniform_share = 0.02;
};

/// The robot's smallest width [units]: 0 for a point, the diameter of a disc, the minimum
/// over the convex hull's edges of the largest distance of a vertex to the edge's line for a
/// polygon (rotating calipers; the narrowest slot it can slide through). A mesh: 0.
double RobotWidth(const envs::Robot& robot);

/// Draws states from the lead distribution (internal::LeadDistribution: the lead's components
/// uniformly, its openings Gaussian, widened by the schedule of AcdLeadOptions, plus
/// AcdSamplerOptions::uniform_share of uniform states). Spaces and orientation as
/// AcdStateSampler: R^2, R^3, SE(2), SE(3); `aligned` turns the robot across an opening.
class AcdLeadStateSampler : public ompl::base::StateSampler {
 public:
  AcdLeadStateSampler(const ompl::base::StateSpace* space,
                      std::shared_ptr<const internal::LeadDistribution> lead, std::uint64_t seed);
  ~AcdLeadStateSampler() override;

  void sampleUniform(ompl::base::State* state) override;
  /// Uniform in the box of half-side `distance` around `near` (the lead plays no part).
  void sampleUniformNear(ompl::base::State* state, const ompl::base::State* near,
                         double distance) override;
  void sampleGaussian(ompl::base::State* state, const ompl::base::State* mean,
                      double stdDev) override;

  /// Draws so far and the level they are at now (0 lead, 1 neighbours, 2 everything).
  std::uint64_t draws() const { return draws_; }
  int level() const;
  /// The part of the last sampleUniform(): a component index, -1 - an opening index, or
  /// kUniformPart for a uniform draw.
  static constexpr int kUniformPart = 1 << 30;
  int last_part() const { return last_part_; }

 private:
  std::shared_ptr<const internal::LeadDistribution> lead_;
  internal::SpaceKind kind_;
  RandomEngine rng_engine_;
  double phase_ = 0.0;  ///< Start of the stratified pick sequence.
  std::uint64_t draws_ = 0;
  int last_part_ = kUniformPart;
};

/// AcdLeadStateSampler's draws, the first valid one of at most `max_attempts` per sample().
class AcdLeadValidStateSampler : public RejectionValidStateSampler<AcdLeadStateSampler> {
 public:
  AcdLeadValidStateSampler(const ompl::base::SpaceInformation* si,
                           std::shared_ptr<const internal::LeadDistribution> lead,
                           std::uint64_t seed, int max_attempts);
};

/// Installs the lead samplers on `si` (valid-state sampler for PRM and co., state sampler for
/// RRT and co.), as InstallAcdSamplers() does for the plain ACD distribution: every allocated
/// sampler gets its own seed derived from `options.seed`.
/// @throws InputError if an option is out of range; std::invalid_argument if the space is not
///         supported or the decomposition is empty.
void InstallAcdLeadSamplers(const std::shared_ptr<ompl::base::SpaceInformation>& si,
                            const acd::Decomposition2d& decomposition, const AcdLeadQuery& query,
                            const AcdSamplerOptions& options,
                            const AcdLeadOptions& lead_options = {});

}  // namespace acdplan::planning
