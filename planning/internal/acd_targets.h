#pragma once
// The ACD sampling distribution in the plane, independent of OMPL (private to planning).

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "acd/decomposition2d.h"
#include "base/random.h"
#include "planning/acd_sampler_options.h"

namespace acdplan::planning::internal {

/// A place samples are drawn around.
struct AcdTarget {
  Eigen::Vector2d position;  ///< Centroid or opening midpoint [units].
  double sigma = 0.0;        ///< Gaussian spread [units].
  double weight = 0.0;       ///< Relative probability of being picked.
  bool opening = false;      ///< True for an opening midpoint.
  double across = 0.0;       ///< Openings: angle of the opening's normal [rad].
};

/// One draw of the 2D part of a sample.
struct AcdDraw {
  bool uniform = true;             ///< True: the caller samples uniformly instead.
  Eigen::Vector2d position{0, 0};  ///< Reference point (when !uniform).
  bool has_yaw = false;            ///< True: use `yaw` (aligned orientation near an opening).
  double yaw = 0.0;
};

/// The angle of the normal of an opening running along `d` [rad]: AcdTarget::across.
double AcrossAngle(const Eigen::Vector2d& d);

/// A yaw that turns the robot's long axis across an opening whose normal is at `across`, either
/// way round, jittered by options.aligned_jitter (AcdOrientation::kAligned); in [-pi, pi].
double AlignedYaw(RandomEngine& rng, double across, const AcdSamplerOptions& options);

/// The targets of `decomposition` under `options` (immutable; shared between samplers).
class AcdTargets {
 public:
  AcdTargets(const acd::Decomposition2d& decomposition, const AcdSamplerOptions& options);

  const std::vector<AcdTarget>& targets() const { return targets_; }
  const AcdSamplerOptions& options() const { return options_; }

  /// Draws a target-based sample (or says "uniform") with `rng`.
  AcdDraw Draw(RandomEngine& rng) const;

  /// As Draw(), restricted to targets within `radius` of `near` (uniform if there are none).
  AcdDraw DrawNear(RandomEngine& rng, const Eigen::Vector2d& near, double radius) const;

 private:
  AcdDraw DrawAround(RandomEngine& rng, const AcdTarget& target) const;

  AcdSamplerOptions options_;
  std::vector<AcdTarget> targets_;
  std::vector<double> cumulative_;  ///< Prefix sums of the weights.
};

}  // namespace acdplan::planning::internal
