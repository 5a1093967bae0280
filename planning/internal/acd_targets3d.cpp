#include "planning/internal/acd_targets3d.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace acdplan::planning::internal {

namespace {

// A unit vector perpendicular to unit `n`.
Eigen::Vector3d Perpendicular(const Eigen::Vector3d& n) {
  const Eigen::Vector3d helper =
      std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return n.cross(helper).normalized();
}

}  // namespace

Eigen::Quaterniond UniformRotation(RandomEngine& rng) {
  const double u1 = UniformReal(rng, 0, 1), u2 = UniformReal(rng, 0, 2 * M_PI),
               u3 = UniformReal(rng, 0, 2 * M_PI);
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  return Eigen::Quaterniond(b * std::cos(u3), a * std::sin(u2), a * std::cos(u2), b * std::sin(u3));
}

LongAxis3d PrincipalAxis(const Eigen::Matrix<double, Eigen::Dynamic, 3>& vertices,
                         double min_elongation) {
  LongAxis3d result;
  if (vertices.rows() < 2) return result;
  const Eigen::RowVector3d mean = vertices.colwise().mean();
  const Eigen::Matrix<double, Eigen::Dynamic, 3> centred = vertices.rowwise() - mean;
  const Eigen::Matrix3d covariance = centred.transpose() * centred;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const Eigen::Vector3d values = solver.eigenvalues();  // Ascending.
  if (!(values[2] > 0) || values[2] < min_elongation * min_elongation * values[1]) return result;
  result.axis = solver.eigenvectors().col(2).normalized();
  const Eigen::VectorXd along = vertices * result.axis;
  result.length = along.maxCoeff() - along.minCoeff();
  for (int k = 0; k < 2; ++k) {
    const Eigen::VectorXd across = vertices * solver.eigenvectors().col(k).normalized();
    result.thickness = std::max(result.thickness, across.maxCoeff() - across.minCoeff());
  }
  return result;
}

AcdTargets3d::AcdTargets3d(const envs::FreeSpaceDecomposition3d& decomposition,
                           const AcdSamplerOptions& options, const LongAxis3d& long_axis)
    : options_(options), long_axis_(long_axis) {
  CheckAcdSamplerOptions(options);
  for (const envs::FreeComponent3d& component : decomposition.components) {
    if (!(component.volume > 0)) continue;
    AcdTarget3d target;
    target.position = component.centroid;
    target.sigma = target.sigma_normal = options.centroid_spread * std::cbrt(component.volume);
    target.weight = 1.0;
    targets_.push_back(target);
  }
  double total_width = 0;
  int count = 0;
  for (const envs::FreeOpening3d& opening : decomposition.openings) {
    if (opening.width > 0) {
      total_width += opening.width;
      ++count;
    }
  }
  const double mean_width = count > 0 ? total_width / count : 0.0;
  for (const envs::FreeOpening3d& opening : decomposition.openings) {
    if (!(opening.width > 0) || options.opening_weight == 0) continue;
    AcdTarget3d target;
    target.position = opening.centroid;
    // In the plane: the play the robot has in the passage (its width less the robot's
    // thickness across its long axis; a tenth of the width at least). Along the normal: the
    // robot's length, to reach the poses just out of the passage.
    const double play = std::max(opening.width - long_axis.thickness, 0.1 * opening.width);
    target.sigma = options.opening_spread * play;
    target.sigma_normal = options.opening_spread * std::max(opening.width, long_axis.length);
    // Narrowness by the bottleneck width (Ch. VI.C: where uniform sampling is weakest),
    // capped so a sliver cut cannot take every sample.
    target.weight =
        options.opening_weight * std::min(mean_width / opening.width, options.max_narrowness);
    target.opening = true;
    target.normal = opening.normal.normalized();
    targets_.push_back(target);
  }
  double sum = 0;
  for (const AcdTarget3d& target : targets_) {
    sum += target.weight;
    cumulative_.push_back(sum);
  }
}

Eigen::Quaterniond AcdTargets3d::AlignedRotation(RandomEngine& rng,
                                                 const Eigen::Vector3d& normal) const {
  const Eigen::Vector3d u = Perpendicular(normal), v = normal.cross(u);
  const double g1 = StandardNormal(rng), g2 = StandardNormal(rng);
  Eigen::Vector3d direction = (normal + options_.aligned_jitter * (g1 * u + g2 * v)).normalized();
  if (UniformIndex(rng, 2)) direction = -direction;
  const double roll = UniformReal(rng, -M_PI, M_PI);
  // Roll about the body axis first, then turn the body axis onto `direction`.
  return Eigen::Quaterniond::FromTwoVectors(long_axis_.axis, direction) *
         Eigen::Quaterniond(Eigen::AngleAxisd(roll, long_axis_.axis));
}

AcdDraw3d AcdTargets3d::Draw(RandomEngine& rng) const {
  if (targets_.empty() || UniformReal(rng, 0.0, 1.0) < options_.uniform_share) return AcdDraw3d{};
  const double pick = UniformReal(rng, 0.0, 1.0) * cumulative_.back();
  const size_t index = std::min<size_t>(
      std::upper_bound(cumulative_.begin(), cumulative_.end(), pick) - cumulative_.begin(),
      targets_.size() - 1);
  const AcdTarget3d& target = targets_[index];
  AcdDraw3d draw;
  draw.uniform = false;
  const Eigen::Vector3d n = target.normal, u = Perpendicular(n), v = n.cross(u);
  const double a = StandardNormal(rng), b = StandardNormal(rng), c = StandardNormal(rng);
  draw.position = target.position + target.sigma * (a * u + b * v) + target.sigma_normal * c * n;
  if (target.opening && options_.orientation == AcdOrientation::kAligned &&
      long_axis_.axis.squaredNorm() > 0) {
    draw.has_rotation = true;
    draw.rotation = AlignedRotation(rng, n);
  }
  return draw;
}

}  // namespace acdplan::planning::internal
