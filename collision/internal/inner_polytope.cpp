#include "collision/internal/inner_polytope.h"

#include <algorithm>
#include <limits>

namespace acdplan::collision::internal {
namespace {

// The part of `triangle` in { x : n . x <= d for every plane }, as the corners of a convex
// polygon (none when it misses). Sutherland-Hodgman; the constructed corners are rounded, which
// the margin of InnerPolytope() covers.
std::vector<Eigen::Vector3d> Clipped(const Triangle3& triangle,
                                     const Eigen::Matrix<double, Eigen::Dynamic, 4>& planes) {
  std::vector<Eigen::Vector3d> polygon(triangle.begin(), triangle.end()), next;
  for (Eigen::Index i = 0; i < planes.rows() && !polygon.empty(); ++i) {
    const Eigen::Vector3d n = planes.row(i).head<3>().transpose();
    next.clear();
    for (size_t k = 0; k < polygon.size(); ++k) {
      const Eigen::Vector3d& a = polygon[k];
      const Eigen::Vector3d& b = polygon[(k + 1) % polygon.size()];
      const double sa = n.dot(a) - planes(i, 3), sb = n.dot(b) - planes(i, 3);
      if (sa <= 0) next.push_back(a);
      if ((sa < 0 && sb > 0) || (sa > 0 && sb < 0)) next.push_back(a + (sa / (sa - sb)) * (b - a));
    }
    polygon.swap(next);
  }
  return polygon;
}

}  // namespace

ConvexPolytope InnerPolytope(const std::vector<Triangle3>& surface,
                             const Eigen::Matrix<double, Eigen::Dynamic, 4>& hull_planes,
                             const Eigen::Vector3d& center, double margin,
                             const std::function<bool(const Eigen::Vector3d&)>& inside) {
  ConvexPolytope inner;
  const Eigen::Index planes = hull_planes.rows();
  if (planes == 0) return inner;
  std::vector<double> delta(static_cast<size_t>(planes), 0.0);
  for (const Triangle3& triangle : surface) {
    // Only the part of the triangle inside the hull can meet K.
    const std::vector<Eigen::Vector3d> inside_hull = Clipped(triangle, hull_planes);
    if (inside_hull.empty()) continue;
    Eigen::Index best = 0;
    double best_depth = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < planes && best_depth > 0; ++i) {
      const Eigen::Vector3d n = hull_planes.row(i).head<3>().transpose();
      double depth = 0.0;
      for (const Eigen::Vector3d& v : inside_hull)
        depth = std::max(depth, hull_planes(i, 3) - n.dot(v));
      if (depth < best_depth) {
        best_depth = depth;
        best = i;
      }
    }
    delta[static_cast<size_t>(best)] = std::max(delta[static_cast<size_t>(best)], best_depth);
  }
  for (Eigen::Index i = 0; i < planes; ++i) {
    Eigen::Vector4d plane = hull_planes.row(i).transpose();
    plane(3) -= delta[static_cast<size_t>(i)] + margin;
    inner.planes.push_back(plane);
  }
  if (!InsideBy(inner, center, margin) || !inside(center)) inner.planes.clear();
  return inner;
}

}  // namespace acdplan::collision::internal
