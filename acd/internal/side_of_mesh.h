#pragma once
// Point-in-solid queries by ray parity (CGAL::Side_of_triangle_mesh) whose query rays stay rays
// wherever the point lies. Internal: include only from .cpp files (it brings in CGAL).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace acdplan::acd::internal {

/// Epick, except that a ray from a point along a vector ends its defining segment 2^24 times
/// the point's magnitude away. Side_of_triangle_mesh shoots its rays from the query point
/// along unit vectors (vertical first, then random ones until a ray meets no edge or vertex),
/// and Epick's ray keeps the point p + v: once |p| exceeds 2^53 |v| (coordinates from about
/// 1e16) that rounds back to p, the ray is degenerate, every traversal is inconclusive, and
/// the query retried forever (a cube of side 4e16 hung; fuzz_decompose3d). The ray is the
/// exact ray through its two points, so only its direction differs from the one asked for
/// (by the rounding of the far point), and the parity is still decided by exact predicates.
struct FarRayKernel : CGAL::Epick {
  struct Construct_ray_3 {
    using result_type = Ray_3;
    Ray_3 operator()(const Point_3& p, const Point_3& q) const { return Ray_3(p, q); }
    Ray_3 operator()(const Point_3& p, const Direction_3& d) const {
      return (*this)(p, d.vector());
    }
    Ray_3 operator()(const Point_3& p, const Vector_3& v) const {
      const double v_max = std::max({std::abs(v.x()), std::abs(v.y()), std::abs(v.z())});
      if (!(v_max > 0.0)) return Ray_3(p, p + v);  // Degenerate as asked; CGAL's precondition.
      const double p_max = std::max(
          {std::abs(p.x()), std::abs(p.y()), std::abs(p.z()), std::numeric_limits<double>::min()});
      // A power of two, so v times it is exact, keeping the far point below 2^1000.
      const int exponent = std::clamp(std::ilogb(p_max) + 24 - std::ilogb(v_max), 0,
                                      std::max(0, 1000 - std::ilogb(v_max)));
      return Ray_3(p, p + std::ldexp(1.0, exponent) * v);
    }
  };
  Construct_ray_3 construct_ray_3_object() const { return {}; }
};

/// CGAL::Side_of_triangle_mesh on FarRayKernel: ON_BOUNDED_SIDE, ON_BOUNDARY or
/// ON_UNBOUNDED_SIDE of a closed triangle mesh, exactly, at any coordinate magnitude.
template <typename Mesh>
using SideOfMesh = CGAL::Side_of_triangle_mesh<Mesh, FarRayKernel>;

}  // namespace acdplan::acd::internal
