#pragma once
// The ACD sampling distribution in 3D (R^3 and SE(3)), independent of OMPL (private to
// planning): the 3D counterpart of acd_targets.h.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "base/random.h"
#include "envs/free_space_decomposition3d.h"
#include "planning/acd_sampler_options.h"

namespace acdplan::planning::internal {

/// A rigid robot's long axis, for the aligned orientations near openings.
struct LongAxis3d {
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();  ///< Body frame, unit; zero = none.
  double length = 0.0;     ///< The robot's extent along `axis` [units]; >= 0.
  double thickness = 0.0;  ///< Its largest extent across `axis` (principal axes) [units].
};

/// A place 3D samples are drawn around.
struct AcdTarget3d {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< Centroid or opening centroid.
  double sigma = 0.0;         ///< Gaussian spread in every direction (in the opening's plane).
  double sigma_normal = 0.0;  ///< Openings: spread along the normal; centroids: = sigma.
  double weight = 0.0;        ///< Relative probability of being picked.
  bool opening = false;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< Openings: unit normal.
};

/// One draw of a 3D sample.
struct AcdDraw3d {
  bool uniform = true;  ///< True: the caller samples uniformly instead.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  bool has_rotation = false;  ///< True: use `rotation` (aligned near an opening).
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
};

/// The targets of a 3D free-space decomposition (immutable; shared between samplers).
///
/// Centroid of a component of volume V: weight 1, sigma = centroid_spread x cbrt(V). Opening
/// of narrowest width w: weight opening_weight x min(mean width / w, max_narrowness) (a narrow
/// passage draws more samples, as in 2D), sigma = opening_spread x max(w - robot thickness,
/// w / 10) in its plane (the play the robot has in the passage; a point has w) and
/// opening_spread x max(w, robot length) along its normal, so that an aligned robot is drawn
/// inside the passage and just out of it on either side. With orientation kAligned and a long
/// axis, a sample drawn at an opening gets the long axis along the normal (either way round)
/// tilted by a Gaussian: axis direction = normalize(n + aligned_jitter (g1 u + g2 v)) for
/// standard normal g1, g2 and (u, v) spanning the opening's plane (so tan(tilt) /
/// aligned_jitter is Rayleigh distributed), with a uniform roll about the axis; every other
/// rotation is uniform on SO(3).
class AcdTargets3d {
 public:
  AcdTargets3d(const envs::FreeSpaceDecomposition3d& decomposition,
               const AcdSamplerOptions& options, const LongAxis3d& long_axis = {});

  const std::vector<AcdTarget3d>& targets() const { return targets_; }
  const AcdSamplerOptions& options() const { return options_; }
  const LongAxis3d& long_axis() const { return long_axis_; }

  /// Draws a target-based sample (or says "uniform") with `rng`.
  AcdDraw3d Draw(RandomEngine& rng) const;

  /// The aligned rotation for an opening of unit normal `normal` (documented above).
  Eigen::Quaterniond AlignedRotation(RandomEngine& rng, const Eigen::Vector3d& normal) const;

 private:
  AcdSamplerOptions options_;
  LongAxis3d long_axis_;
  std::vector<AcdTarget3d> targets_;
  std::vector<double> cumulative_;  ///< Prefix sums of the weights.
};

/// A uniformly random rotation (Shoemake 1992).
Eigen::Quaterniond UniformRotation(RandomEngine& rng);

/// The principal axis of `vertices` (#V by 3; the eigenvector of the largest eigenvalue of
/// their covariance) and the extent along it, when that eigenvalue is at least
/// `min_elongation`^2 times the second: a robot with a long axis. Otherwise a zero axis.
LongAxis3d PrincipalAxis(const Eigen::Matrix<double, Eigen::Dynamic, 3>& vertices,
                         double min_elongation = 1.5);

}  // namespace acdplan::planning::internal
