#include "acd/internal/canonical_hull.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "acd/internal/hull_facets.h"

namespace acdplan::acd::internal {

CanonicalHull MakeCanonicalHull(const std::vector<Eigen::Vector3d>& points) {
  CanonicalHull out;
  out.planes.resize(0, 4);
  const HullFacets hull = ConvexHullFacets(points, 0.0);
  out.mesh = FanTriangulation(hull);
  const std::vector<Eigen::Vector3d>& v = hull.vertices;  // sorted, distinct
  if (v.size() < 4) return out;
  Eigen::Vector3d lo = v[0], hi = v[0];
  for (const auto& p : v) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double tol = kInPlaneTolerance * (hi - lo).norm();
  // The plane through three of `ids`' vertices: the first, the farthest from it, the farthest
  // from their line (zero normal if they are collinear in doubles).
  auto plane_normal = [&v](const std::vector<int>& ids) {
    const Eigen::Vector3d& p0 = v[static_cast<size_t>(ids[0])];
    size_t i1 = 1;
    for (size_t i = 1; i < ids.size(); ++i) {
      if ((v[static_cast<size_t>(ids[i])] - p0).squaredNorm() >
          (v[static_cast<size_t>(ids[i1])] - p0).squaredNorm())
        i1 = i;
    }
    const Eigen::Vector3d axis = v[static_cast<size_t>(ids[i1])] - p0;
    size_t i2 = 0;
    double far = -1;
    for (size_t i = 0; i < ids.size(); ++i) {
      const double d = axis.cross(v[static_cast<size_t>(ids[i])] - p0).squaredNorm();
      if (d > far) far = d, i2 = i;
    }
    return Eigen::Vector3d(axis.cross(v[static_cast<size_t>(ids[i2])] - p0));
  };
  // Each facet regrouped: every hull vertex within tol of its plane. A sliver facet's own
  // computed normal is no guide (it can be off by degrees, and the vertices "within tol" of
  // that plane then make a plane that cuts through the hull: measured on a piece of hose.obj, a
  // plane with hull vertices 3 units outside it, so a face 0.56 deep measured 0).
  std::set<std::vector<int>> facets;
  std::map<std::vector<int>, Eigen::Vector3d> outward;
  for (const std::vector<int>& polygon : hull.facets) {
    std::vector<int> ids = polygon;
    std::sort(ids.begin(), ids.end());
    const Eigen::Vector3d n = plane_normal(ids);
    if (!(n.norm() > 0)) continue;
    const Eigen::Vector3d u = n.normalized();
    const Eigen::Vector3d& p0 = v[static_cast<size_t>(ids[0])];
    std::vector<int> on;
    for (size_t i = 0; i < v.size(); ++i) {
      if (std::abs(u.dot(v[i] - p0)) <= tol) on.push_back(static_cast<int>(i));
    }
    if (on.size() < 3) continue;
    // The facet's outward normal, summed over its fan (counter-clockwise seen from outside).
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    const Eigen::Vector3d& a = v[static_cast<size_t>(polygon[0])];
    for (size_t i = 1; i + 1 < polygon.size(); ++i) {
      normal += (v[static_cast<size_t>(polygon[i])] - a)
                    .cross(v[static_cast<size_t>(polygon[i + 1])] - a);
    }
    if (facets.insert(on).second) outward.emplace(on, normal);
  }
  std::vector<Eigen::Vector4d> planes;
  for (const std::vector<int>& on : facets) {
    Eigen::Vector3d n = plane_normal(on);
    if (!(n.norm() > 0)) continue;
    n.normalize();
    if (n.dot(outward.at(on)) < 0) n = -n;
    // A plane some hull vertex lies clearly outside of (a facet too thin for its normal to be
    // computed in doubles) is no face of the hull: dropped, so it measures no depth.
    double offset = -std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& p : v) offset = std::max(offset, n.dot(p));
    const double excess = offset - n.dot(v[static_cast<size_t>(on[0])]);
    if (excess > 10 * tol) continue;
    // Any other is moved out to the farthest vertex: a supporting plane. A point within a
    // distance of it is then within that distance of the hull's boundary, and its depth below
    // it at least its depth in the hull, so the concavity measured against these planes is
    // never below the true one. (Through its own vertex, a group's refitted plane can cut up to
    // 10 x tol into the hull, and a face that deep counted as on the hull.)
    planes.emplace_back(n.x(), n.y(), n.z(), offset);
  }
  out.planes.resize(static_cast<Eigen::Index>(planes.size()), 4);
  for (size_t i = 0; i < planes.size(); ++i)
    out.planes.row(static_cast<Eigen::Index>(i)) = planes[i];
  return out;
}

}  // namespace acdplan::acd::internal
