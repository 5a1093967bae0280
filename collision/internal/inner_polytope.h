#pragma once
// A convex polytope inside an obstacle, from the planes of an ACD piece's hull: a point inside it
// is inside the obstacle without a query on the obstacle's triangles. The exact confirmation of a
// hull hit (CollisionMode::kHullsExact) takes it as a shortcut. Internal.

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "collision/internal/convex_separation.h"

namespace acdplan::collision::internal {

/// The polytope K = { x : n . x <= d - delta_n - margin for every hull plane (n, d) }: the part
/// inside the hull of each triangle T of `surface` is assigned to the plane it lies least deep
/// under (the smallest max over its corners of d - n . v, at least 0), and delta_n is the deepest
/// of n's triangles. So no
/// triangle of `surface` meets K's interior, and an inside/outside rule that changes only across
/// `surface` (the obstacle's winding rule, when `surface` holds every triangle of the obstacle's
/// closed parts that meets the hull) is the same at every point of K: K is kept only when
/// `center` lies in it by `margin` and `inside(center)`. `hull_planes`: #H by 4, unit outward n
/// (acd::HullPlanes()); `margin` [units] > 0 exceeds the rounding of the dot products, so K stays
/// clear of the triangles after rounding. Returns K's planes (no vertices), or no planes.
/// O(triangles x planes x clipped corners) plus one call of `inside`.
ConvexPolytope InnerPolytope(const std::vector<Triangle3>& surface,
                             const Eigen::Matrix<double, Eigen::Dynamic, 4>& hull_planes,
                             const Eigen::Vector3d& center, double margin,
                             const std::function<bool(const Eigen::Vector3d&)>& inside);

}  // namespace acdplan::collision::internal
