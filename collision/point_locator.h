#pragma once
// Point location: is a point inside an obstacle? Exact, or on the ACD hulls (dissertation
// Algorithm 8, Ch. VI.A) with a uniform grid over the hulls.

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "collision/obstacle_set.h"

namespace acdplan::collision {

/// How PointLocator answers.
enum class LocateMethod {
  /// Exact inside/outside. 2D: ray crossing on the obstacle polygons (holes included) with
  /// exact orientation predicates. 3D: CGAL Side_of_triangle_mesh on each closed part of an
  /// obstacle and the nonzero winding rule over its parts: a part counts +1, or -1 when it is
  /// nested
  /// in an odd number of other parts that it does not meet (a cavity), whatever way its faces
  /// point; so overlapping closed shells mean their union, nested ones alternate
  /// (internal/solid_locator.h, ExactObstacleLocator).
  kExact,
  /// Algorithm 8 on the hulls of the obstacle pieces, through a uniform grid over the hulls
  /// instead of a loop over all of them (a cell inside one hull answers at once; otherwise only
  /// the hulls that reach the cell are tested). Never says outside where kExact says inside; may
  /// say
  /// inside for a point near a concave feature (inside a hull, outside its component).
  kHulls,
};

/// "exact" or "hulls".
std::string ToString(LocateMethod method);

/// Inverse of ToString(). @throws InputError for any other name.
LocateMethod ParseLocateMethod(const std::string& name);

/// Answers Inside(p) for the obstacles of an ObstacleSet. Boundary points count as inside.
/// Thread-safe: queries are const and share no mutable state.
class PointLocator {
 public:
  /// @throws InputError for kExact on a 3D set with an open piece (the message names the
  ///         obstacle and the number of edges not shared by exactly two triangles).
  PointLocator(std::shared_ptr<const ObstacleSet> obstacles, LocateMethod method);
  ~PointLocator();
  PointLocator(PointLocator&&) noexcept;
  PointLocator& operator=(PointLocator&&) noexcept;

  /// True if `p` is inside (or on) an obstacle. A 2D point is taken at z = 0.
  bool Inside(const Eigen::Vector3d& p) const;
  bool Inside(const Eigen::Vector2d& p) const { return Inside(Eigen::Vector3d(p.x(), p.y(), 0)); }
  /// Inside() of each of `points`, in order: `inside` is resized to their number and entry i set
  /// to 1 or 0. For many points: one call, so the hulls' grid lookup runs in one loop, without a
  /// call per point (about 10% more points per second than a loop over Inside(p)).
  void Inside(const std::vector<Eigen::Vector3d>& points, std::vector<char>* inside) const;

  LocateMethod method() const { return method_; }
  const ObstacleSet& obstacles() const { return *obstacles_; }

 private:
  struct Impl;
  std::shared_ptr<const ObstacleSet> obstacles_;
  LocateMethod method_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace acdplan::collision
