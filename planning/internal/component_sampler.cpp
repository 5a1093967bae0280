#include "planning/internal/component_sampler.h"

#include <algorithm>
#include <cmath>

namespace acdplan::planning::internal {

namespace {

/// Even-odd crossing count of the horizontal ray from `p` to +x against `ring`.
bool Crosses(const acd::Ring2d& ring, const Eigen::Vector2d& p) {
  bool inside = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const acd::Point2d& a = ring[i];
    const acd::Point2d& b = ring[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

}  // namespace

ComponentSampler::ComponentSampler(const acd::Component2d& component)
    : polygon_(component.polygon), area_(std::abs(acd::Area(component.polygon))) {
  const acd::Ring2d& ring = component.hull.size() >= 3 ? component.hull : component.polygon.outer;
  hull_.assign(ring.begin(), ring.end());
  double sum = 0;
  for (size_t i = 1; i + 1 < hull_.size(); ++i) {
    const Eigen::Vector2d u = hull_[i] - hull_[0], v = hull_[i + 1] - hull_[0];
    sum += 0.5 * std::abs(u.x() * v.y() - u.y() * v.x());
    cumulative_.push_back(sum);
  }
}

bool ComponentSampler::Contains(const Eigen::Vector2d& p) const {
  if (polygon_.outer.size() < 3) return false;
  bool inside = Crosses(polygon_.outer, p);
  for (const acd::Ring2d& hole : polygon_.holes) {
    if (hole.size() >= 3 && Crosses(hole, p)) inside = !inside;
  }
  return inside;
}

Eigen::Vector2d ComponentSampler::SampleHull(const std::function<double()>& unit) const {
  if (cumulative_.empty() || !(cumulative_.back() > 0)) {
    return hull_.empty() ? Eigen::Vector2d::Zero() : hull_.front();
  }
  const double u = unit() * cumulative_.back();
  const size_t t = std::min<size_t>(
      std::upper_bound(cumulative_.begin(), cumulative_.end(), u) - cumulative_.begin(),
      cumulative_.size() - 1);
  // Uniform in the triangle (hull_[0], hull_[t+1], hull_[t+2]) by folding the unit square.
  double r = unit();
  double s = unit();
  if (r + s > 1) r = 1 - r, s = 1 - s;
  return hull_[0] + r * (hull_[t + 1] - hull_[0]) + s * (hull_[t + 2] - hull_[0]);
}

Eigen::Vector2d ComponentSampler::Sample(const std::function<double()>& unit) const {
  Eigen::Vector2d p = SampleHull(unit);
  for (int attempt = 0; attempt < kMaxRejections && !Contains(p); ++attempt) p = SampleHull(unit);
  return p;
}

Eigen::Vector2d ComponentSampler::Sample(RandomEngine& rng) const {
  return Sample([&rng] { return UniformReal(rng, 0.0, 1.0); });
}

}  // namespace acdplan::planning::internal
