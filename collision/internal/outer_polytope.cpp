#include "collision/internal/outer_polytope.h"

#include <algorithm>
#include <vector>

#include "acd/convex_hull3d.h"

namespace acdplan::collision::internal {
namespace {

// Directions closer than this cosine (about 0.8 degrees) add nothing.
constexpr double kSameDirection = 0.9999;

}  // namespace

acd::TriangleMesh OuterPolytope(const acd::TriangleMesh& hull,
                                const Eigen::Matrix<double, Eigen::Dynamic, 4>& planes,
                                int max_planes) {
  if (planes.rows() <= max_planes + 6 || hull.vertices.rows() == 0) return hull;

  // The directions: the six axes (the result is bounded), then farthest-point sampling of the
  // face normals on the sphere.
  std::vector<Eigen::Vector3d> directions;
  for (int k = 0; k < 3; ++k) {
    directions.push_back(Eigen::Vector3d::Unit(k));
    directions.push_back(-Eigen::Vector3d::Unit(k));
  }
  const Eigen::Index count = planes.rows();
  std::vector<double> nearest(static_cast<size_t>(count));  // max cosine to a chosen direction
  for (Eigen::Index r = 0; r < count; ++r) {
    const Eigen::Vector3d n = planes.row(r).head<3>().transpose();
    nearest[static_cast<size_t>(r)] = n.cwiseAbs().maxCoeff();
  }
  for (int chosen = 0; chosen < max_planes; ++chosen) {
    const auto next = std::min_element(nearest.begin(), nearest.end());  // first of ties
    if (*next > kSameDirection) break;
    const Eigen::Vector3d n = planes.row(next - nearest.begin()).head<3>().transpose();
    directions.push_back(n);
    for (Eigen::Index r = 0; r < count; ++r) {
      const double c = n.dot(planes.row(r).head<3>().transpose());
      nearest[static_cast<size_t>(r)] = std::max(nearest[static_cast<size_t>(r)], c);
    }
  }

  // Each half-space supports the hull, loosened by the slack; their intersection's corners are
  // the dual hull's faces, about an interior point (the mean of the hull's vertices).
  const Eigen::Vector3d center = hull.vertices.colwise().mean().transpose();
  const double slack =
      1e-9 * (hull.vertices.colwise().maxCoeff() - hull.vertices.colwise().minCoeff()).norm();
  std::vector<Eigen::Vector3d> dual;
  for (const Eigen::Vector3d& n : directions) {
    const double support = (hull.vertices * n).maxCoeff() + slack;
    dual.push_back(n / (support - n.dot(center)));  // > 0: the center is inside
  }
  const acd::TriangleMesh dual_hull = acd::ConvexHull3(dual, 0.0);
  const Eigen::Matrix<double, Eigen::Dynamic, 4> dual_planes = acd::HullPlanes(dual_hull);
  std::vector<Eigen::Vector3d> corners;
  for (Eigen::Index r = 0; r < dual_planes.rows(); ++r) {
    // The dual face m . y = e is the corner x with (x - center) = m / e.
    corners.push_back(center + dual_planes.row(r).head<3>().transpose() / dual_planes(r, 3));
  }
  acd::TriangleMesh outer = acd::ConvexHull3(corners, 0.0);
  // Rounding moves the corners by far less than the slack; should a sliver of the dual hull
  // move one more, the hull is kept.
  const Eigen::Matrix<double, Eigen::Dynamic, 4> outer_planes = acd::HullPlanes(outer);
  const Eigen::MatrixXd heights =
      (hull.vertices * outer_planes.leftCols<3>().transpose()).rowwise() -
      outer_planes.col(3).transpose();
  if (outer.triangles.rows() == 0 || !(heights.maxCoeff() <= 0)) return hull;
  return outer;
}

}  // namespace acdplan::collision::internal
