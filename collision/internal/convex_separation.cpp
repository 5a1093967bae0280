#include "collision/internal/convex_separation.h"

#include <algorithm>
#include <utility>

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

// True if the projections of `a`'s vertices and of `t` on `axis` are disjoint intervals.
bool AxisSeparates(const ConvexPolytope& a, const Triangle3& t, const Eigen::Vector3d& axis) {
  const double t0 = axis.dot(t[0]), t1 = axis.dot(t[1]), t2 = axis.dot(t[2]);
  const double t_min = std::min({t0, t1, t2}), t_max = std::max({t0, t1, t2});
  double a_min = axis.dot(a.vertices[0]), a_max = a_min;
  for (size_t i = 1; i < a.vertices.size(); ++i) {
    const double p = axis.dot(a.vertices[i]);
    a_min = std::min(a_min, p);
    a_max = std::max(a_max, p);
    if (a_min <= t_max && a_max >= t_min) return false;
  }
  return a_max < t_min || a_min > t_max;
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

std::vector<Eigen::Vector3d> EdgeDirections(const Eigen::MatrixX3d& vertices,
                                            const Eigen::MatrixX3i& triangles) {
  std::vector<std::pair<int, int>> edges;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int u = triangles(f, k), v = triangles(f, (k + 1) % 3);
      edges.emplace_back(std::min(u, v), std::max(u, v));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<Eigen::Vector3d> directions;
  for (const auto& [u, v] : edges) {
    directions.push_back((vertices.row(v) - vertices.row(u)).transpose());
  }
  return directions;
}

bool TouchesTriangle(const ConvexPolytope& a, const std::vector<Eigen::Vector3d>& a_edges,
                     const Triangle3& t) {
  // a's face planes first: the cheapest axes, and near a robot most triangles lie beyond one.
  for (const Eigen::Vector4d& plane : a.planes) {
    const Eigen::Vector3d n = plane.head<3>();
    if (n.dot(t[0]) > plane(3) && n.dot(t[1]) > plane(3) && n.dot(t[2]) > plane(3)) return false;
  }
  const std::array<Eigen::Vector3d, 3> t_edges = {t[1] - t[0], t[2] - t[1], t[0] - t[2]};
  const Eigen::Vector3d normal = t_edges[0].cross(t_edges[1]);
  if (normal != Eigen::Vector3d::Zero() && AxisSeparates(a, t, normal)) return false;
  for (const Eigen::Vector3d& e : a_edges) {
    for (const Eigen::Vector3d& f : t_edges) {
      const Eigen::Vector3d axis = e.cross(f);
      if (axis != Eigen::Vector3d::Zero() && AxisSeparates(a, t, axis)) return false;
    }
  }
  return true;
}

}  // namespace acdplan::collision::internal
