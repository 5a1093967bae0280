#pragma once
// Uniform points inside one ACD component (private to planning).

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "acd/decomposition2d.h"
#include "base/random.h"

namespace acdplan::planning::internal {

/// Draws points uniformly inside a component's polygon (not its hull): a uniform point of the
/// convex hull (a triangle fan, each triangle picked by its area), rejected until it falls
/// inside the polygon (even-odd over the outer ring and the holes). An ACD component is
/// tau-convex, so its area is close to its hull's and few draws are rejected; after
/// `kMaxRejections` misses the last point of the hull is returned (never outside the hull).
class ComponentSampler {
 public:
  static constexpr int kMaxRejections = 64;

  explicit ComponentSampler(const acd::Component2d& component);

  /// A point inside the component (see the class comment).
  Eigen::Vector2d Sample(RandomEngine& rng) const;
  /// As Sample(), drawing from `unit` (uniform in [0, 1); e.g. OMPL's RNG in a Decomposition).
  Eigen::Vector2d Sample(const std::function<double()>& unit) const;
  /// True if `p` lies inside the polygon (even-odd; boundary points either way).
  bool Contains(const Eigen::Vector2d& p) const;
  /// Area of the component's polygon [units^2].
  double area() const { return area_; }

 private:
  Eigen::Vector2d SampleHull(const std::function<double()>& unit) const;

  acd::Polygon2d polygon_;
  std::vector<Eigen::Vector2d> hull_;
  std::vector<double> cumulative_;  ///< Prefix sums of the fan triangles' areas.
  double area_ = 0.0;
};

}  // namespace acdplan::planning::internal
