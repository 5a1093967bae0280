#include "acd/internal/canonical_hull.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "acd/convex_hull3d.h"

namespace acdplan::acd::internal {
namespace {

bool Less(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

double Cross2(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

}  // namespace

CanonicalHull MakeCanonicalHull(const std::vector<Eigen::Vector3d>& points) {
  CanonicalHull out;
  out.planes.resize(0, 4);
  const TriangleMesh raw = ConvexHull3(points, 0.0);
  std::vector<Eigen::Vector3d> v(static_cast<size_t>(raw.vertices.rows()));
  for (size_t i = 0; i < v.size(); ++i) v[i] = raw.vertices.row(static_cast<Eigen::Index>(i));
  std::sort(v.begin(), v.end(), Less);
  v.erase(std::unique(v.begin(), v.end()), v.end());
  if (v.size() < 4) {
    out.mesh = raw;
    return out;
  }
  Eigen::Vector3d lo = v[0], hi = v[0], centroid = Eigen::Vector3d::Zero();
  for (const auto& p : v) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p), centroid += p;
  centroid /= static_cast<double>(v.size());
  const double tol = 1e-9 * (hi - lo).norm();
  std::set<std::vector<int>> facets;
  for (Eigen::Index f = 0; f < raw.triangles.rows(); ++f) {
    const Eigen::Vector3d a = raw.vertices.row(raw.triangles(f, 0));
    const Eigen::Vector3d b = raw.vertices.row(raw.triangles(f, 1));
    const Eigen::Vector3d c = raw.vertices.row(raw.triangles(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if (!(n.norm() > 0)) continue;
    const Eigen::Vector3d u = n.normalized();
    std::vector<int> on;
    for (size_t i = 0; i < v.size(); ++i) {
      if (std::abs(u.dot(v[i] - a)) <= tol) on.push_back(static_cast<int>(i));
    }
    if (on.size() >= 3) facets.insert(on);
  }
  std::vector<Eigen::Vector4d> planes;
  std::vector<Eigen::Vector3i> triangles;
  for (const std::vector<int>& on : facets) {
    // The plane through three of its vertices chosen by index: the first, the farthest from
    // it, the farthest from their line.
    const Eigen::Vector3d& p0 = v[static_cast<size_t>(on[0])];
    size_t i1 = 1;
    for (size_t i = 1; i < on.size(); ++i) {
      if ((v[static_cast<size_t>(on[i])] - p0).squaredNorm() > (v[static_cast<size_t>(on[i1])] - p0).squaredNorm()) i1 = i;
    }
    const Eigen::Vector3d axis = v[static_cast<size_t>(on[i1])] - p0;
    size_t i2 = 0;
    double far = -1;
    for (size_t i = 0; i < on.size(); ++i) {
      const double d = axis.cross(v[static_cast<size_t>(on[i])] - p0).squaredNorm();
      if (d > far) far = d, i2 = i;
    }
    Eigen::Vector3d n = axis.cross(v[static_cast<size_t>(on[i2])] - p0);
    if (!(n.norm() > 0)) continue;
    n.normalize();
    if (n.dot(centroid - p0) > 0) n = -n;
    planes.emplace_back(n.x(), n.y(), n.z(), n.dot(p0));
    // The facet polygon (Andrew's monotone chain in the plane, counter-clockwise about n),
    // fanned from its first vertex.
    const Eigen::Vector3d e1 = axis.normalized(), e2 = n.cross(e1);
    std::vector<std::pair<Eigen::Vector2d, int>> q;
    for (int i : on) q.emplace_back(Eigen::Vector2d(e1.dot(v[static_cast<size_t>(i)] - p0), e2.dot(v[static_cast<size_t>(i)] - p0)), i);
    std::sort(q.begin(), q.end(), [](const auto& a, const auto& b) {
      return a.first.x() < b.first.x() || (a.first.x() == b.first.x() && (a.first.y() < b.first.y() || (a.first.y() == b.first.y() && a.second < b.second)));
    });
    std::vector<std::pair<Eigen::Vector2d, int>> chain(2 * q.size());
    size_t k = 0;
    for (size_t i = 0; i < q.size(); ++i) {
      while (k >= 2 && Cross2(chain[k - 2].first, chain[k - 1].first, q[i].first) <= 0) --k;
      chain[k++] = q[i];
    }
    for (size_t i = q.size() - 1, t = k + 1; i > 0; --i) {
      while (k >= t && Cross2(chain[k - 2].first, chain[k - 1].first, q[i - 1].first) <= 0) --k;
      chain[k++] = q[i - 1];
    }
    chain.resize(k - 1);
    for (size_t i = 1; i + 1 < chain.size(); ++i) {
      triangles.emplace_back(chain[0].second, chain[i].second, chain[i + 1].second);
    }
  }
  out.mesh = MakeTriangleMesh(v, triangles);
  out.planes.resize(static_cast<Eigen::Index>(planes.size()), 4);
  for (size_t i = 0; i < planes.size(); ++i) out.planes.row(static_cast<Eigen::Index>(i)) = planes[i];
  return out;
}

}  // namespace acdplan::acd::internal
