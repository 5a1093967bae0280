#include "collision/internal/convex_separation.h"

namespace acdplan::collision::internal {
namespace {

// True if one plane of `faces` has all of `points` beyond it by more than `margin`.
bool OnePlaneSeparates(const ConvexPolytope& faces, const ConvexPolytope& points, double margin) {
  for (const Eigen::Vector4d& plane : faces.planes) {
    const Eigen::Vector3d n = plane.head<3>();
    const double limit = plane(3) + margin;
    bool all_beyond = true;
    for (const Eigen::Vector3d& v : points.vertices) {
      if (n.dot(v) <= limit) {
        all_beyond = false;
        break;
      }
    }
    if (all_beyond) return true;
  }
  return false;
}

}  // namespace

void ConvexPolytope::Transformed(const Eigen::Isometry3d& pose, ConvexPolytope* out) const {
  out->vertices.resize(vertices.size());
  for (size_t i = 0; i < vertices.size(); ++i) out->vertices[i] = pose * vertices[i];
  out->planes.resize(planes.size());
  for (size_t i = 0; i < planes.size(); ++i) {
    const Eigen::Vector3d n = pose.linear() * planes[i].head<3>();
    out->planes[i] << n, planes[i](3) + n.dot(pose.translation());
  }
}

bool SeparatedByAFacePlane(const ConvexPolytope& a, const ConvexPolytope& b, double margin) {
  return OnePlaneSeparates(a, b, margin) || OnePlaneSeparates(b, a, margin);
}

bool InsideBy(const ConvexPolytope& polytope, const Eigen::Vector3d& p, double margin) {
  if (polytope.planes.empty()) return false;
  for (const Eigen::Vector4d& plane : polytope.planes) {
    if (plane.head<3>().dot(p) >= plane(3) - margin) return false;
  }
  return true;
}

bool AVertexInside(const ConvexPolytope& a, const ConvexPolytope& b, double margin) {
  for (const Eigen::Vector3d& v : a.vertices) {
    if (InsideBy(b, v, margin)) return true;
  }
  return false;
}

}  // namespace acdplan::collision::internal
