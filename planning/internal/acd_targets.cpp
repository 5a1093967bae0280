#include "planning/internal/acd_targets.h"

#include <algorithm>
#include <cmath>

#include "base/input_error.h"

namespace acdplan::planning::internal {

double AcrossAngle(const Eigen::Vector2d& d) { return std::atan2(d.y(), d.x()) + M_PI / 2; }

double AlignedYaw(RandomEngine& rng, double across, const AcdSamplerOptions& options) {
  const double flip = UniformIndex(rng, 2) ? M_PI : 0.0;
  const double yaw =
      across - options.long_axis + flip + options.aligned_jitter * StandardNormal(rng);
  return std::remainder(yaw, 2 * M_PI);
}

AcdTargets::AcdTargets(const acd::Decomposition2d& decomposition, const AcdSamplerOptions& options)
    : options_(options) {
  CheckAcdSamplerOptions(options);
  for (const acd::Component2d& component : decomposition.components) {
    const double area = std::abs(acd::Area(component.polygon));
    if (!(area > 0)) continue;
    AcdTarget target;
    target.position = component.centroid;
    target.sigma = options.centroid_spread * std::sqrt(area);
    target.weight = 1.0;
    targets_.push_back(target);
  }
  double total_length = 0;
  int count = 0;
  for (const acd::Opening2d& opening : decomposition.openings) {
    const double length = (opening.b - opening.a).norm();
    if (length > 0) {
      total_length += length;
      ++count;
    }
  }
  const double mean_length = count > 0 ? total_length / count : 0.0;
  for (const acd::Opening2d& opening : decomposition.openings) {
    const Eigen::Vector2d d = opening.b - opening.a;
    const double length = d.norm();
    if (!(length > 0) || options.opening_weight == 0) continue;
    AcdTarget target;
    target.position = 0.5 * (opening.a + opening.b);
    target.sigma = options.opening_spread * length;
    // Narrowness: a short opening (relative to the others) is a narrow passage, where uniform
    // sampling is weakest (Ch. VI.C); capped so a sliver cut cannot take every sample.
    target.weight = options.opening_weight * std::min(mean_length / length, options.max_narrowness);
    target.opening = true;
    target.across = AcrossAngle(d);
    targets_.push_back(target);
  }
  double sum = 0;
  for (const AcdTarget& target : targets_) {
    sum += target.weight;
    cumulative_.push_back(sum);
  }
}

AcdDraw AcdTargets::DrawAround(RandomEngine& rng, const AcdTarget& target) const {
  AcdDraw draw;
  draw.uniform = false;
  const double dx = StandardNormal(rng), dy = StandardNormal(rng);
  draw.position = target.position + target.sigma * Eigen::Vector2d(dx, dy);
  if (target.opening && options_.orientation == AcdOrientation::kAligned) {
    draw.has_yaw = true;
    draw.yaw = AlignedYaw(rng, target.across, options_);
  }
  return draw;
}

AcdDraw AcdTargets::Draw(RandomEngine& rng) const {
  if (targets_.empty() || UniformReal(rng, 0.0, 1.0) < options_.uniform_share) return AcdDraw{};
  const double u = UniformReal(rng, 0.0, 1.0) * cumulative_.back();
  const size_t index = std::min<size_t>(
      std::upper_bound(cumulative_.begin(), cumulative_.end(), u) - cumulative_.begin(),
      targets_.size() - 1);
  return DrawAround(rng, targets_[index]);
}

AcdDraw AcdTargets::DrawNear(RandomEngine& rng, const Eigen::Vector2d& near, double radius) const {
  if (targets_.empty() || UniformReal(rng, 0.0, 1.0) < options_.uniform_share) return AcdDraw{};
  double sum = 0;
  std::vector<std::pair<double, size_t>> candidates;
  for (size_t i = 0; i < targets_.size(); ++i) {
    if ((targets_[i].position - near).norm() <= radius) {
      sum += targets_[i].weight;
      candidates.emplace_back(sum, i);
    }
  }
  if (candidates.empty() || !(sum > 0)) return AcdDraw{};
  const double u = UniformReal(rng, 0.0, 1.0) * sum;
  for (const auto& [prefix, i] : candidates) {
    if (u < prefix) return DrawAround(rng, targets_[i]);
  }
  return DrawAround(rng, targets_[candidates.back().second]);
}

}  // namespace acdplan::planning::internal
