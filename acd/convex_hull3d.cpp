#include "acd/convex_hull3d.h"

#include <algorithm>
#include <cmath>

#include "acd/internal/hull_facets.h"

namespace acdplan::acd {

TriangleMesh ConvexHull3(const std::vector<Eigen::Vector3d>& points, double thickness) {
  return internal::FanTriangulation(internal::ConvexHullFacets(points, thickness));
}

bool IsFlatHull(const TriangleMesh& hull) {
  const Eigen::Index triangles = hull.triangles.rows();
  return triangles == 0 || triangles < 2 * hull.vertices.rows() - 4;
}

Eigen::Matrix<double, Eigen::Dynamic, 4> HullPlanes(const TriangleMesh& hull) {
  std::vector<Eigen::Vector4d> planes;
  for (Eigen::Index f = 0; f < hull.triangles.rows(); ++f) {
    const Eigen::Vector3d a = hull.vertices.row(hull.triangles(f, 0));
    const Eigen::Vector3d b = hull.vertices.row(hull.triangles(f, 1));
    const Eigen::Vector3d c = hull.vertices.row(hull.triangles(f, 2));
    Eigen::Vector3d n = (b - a).cross(c - a);
    const double len = n.norm();
    if (!(len > 0)) continue;  // a sliver face adds no constraint its neighbours lack
    n /= len;
    const double d = n.dot(a);
    bool duplicate = false;
    for (const auto& q : planes) {
      if (q.head<3>().dot(n) > 1 - 1e-12 && std::abs(q(3) - d) <= 1e-12 * (1 + std::abs(d))) {
        duplicate = true;
        break;
      }
    }
    if (!duplicate) planes.emplace_back(n.x(), n.y(), n.z(), d);
  }
  // Each plane moved out to the hull's support in its direction: the normal of a sliver facet
  // (three nearly collinear corners, which cuts of nearly coplanar pieces produce) is rounding
  // noise, so its plane through the facet can cut through the hull (measured: 0.17 on a torus
  // piece of size 1.7). As a supporting plane, whatever its direction, it keeps every hull point
  // inside; for a sound facet it moves by rounding only.
  for (Eigen::Vector4d& plane : planes) {
    for (Eigen::Index i = 0; i < hull.vertices.rows(); ++i) {
      plane(3) = std::max(plane(3), plane.head<3>().dot(hull.vertices.row(i).transpose()));
    }
  }
  Eigen::Matrix<double, Eigen::Dynamic, 4> out(static_cast<Eigen::Index>(planes.size()), 4);
  for (size_t i = 0; i < planes.size(); ++i) out.row(static_cast<Eigen::Index>(i)) = planes[i];
  return out;
}
}  // namespace acdplan::acd
