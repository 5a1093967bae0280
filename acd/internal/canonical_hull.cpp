#include "acd/internal/canonical_hull.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <utility>

#include "acd/convex_hull3d.h"

namespace acdplan::acd::internal {
namespace {

using Inexact = CGAL::Exact_predicates_inexact_constructions_kernel;

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
  out.closed = raw;
  std::vector<Eigen::Vector3d> v(static_cast<size_t>(raw.vertices.rows()));
  for (size_t i = 0; i < v.size(); ++i) v[i] = raw.vertices.row(static_cast<Eigen::Index>(i));
  std::sort(v.begin(), v.end(), Less);
  v.erase(std::unique(v.begin(), v.end()), v.end());
  if (v.size() < 4) {
    out.mesh = raw;
    return out;
  }
  Eigen::Vector3d lo = v[0], hi = v[0];
  for (const auto& p : v) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double tol = 1e-9 * (hi - lo).norm();
  auto index_of = [&](const Eigen::Vector3d& p) {
    return static_cast<int>(std::lower_bound(v.begin(), v.end(), p, Less) - v.begin());
  };
  // The hull's true facets: raw triangles joined across an edge when exactly coplanar (exact
  // predicates on the doubles). A raw triangle's own normal is no guide to its facet: a sliver
  // triangle's computed normal can be off by degrees, and the vertices "within tol" of that
  // plane then make a plane that cuts through the hull (measured on a piece of hose.obj: a
  // plane with hull vertices 3 units outside it, so a face 0.56 deep measured 0).
  const Eigen::Index nt = raw.triangles.rows();
  std::vector<int> group(static_cast<size_t>(nt));
  std::iota(group.begin(), group.end(), 0);
  auto find = [&](int x) {
    while (group[static_cast<size_t>(x)] != x)
      x = group[static_cast<size_t>(x)] = group[static_cast<size_t>(group[static_cast<size_t>(x)])];
    return x;
  };
  auto corner = [&](Eigen::Index f, int k) {
    const Eigen::Vector3d p = raw.vertices.row(raw.triangles(f, k));
    return Inexact::Point_3(p.x(), p.y(), p.z());
  };
  std::map<std::pair<int, int>, std::pair<Eigen::Index, int>> edge_owner;  // -> (face, apex)
  for (Eigen::Index f = 0; f < nt; ++f) {
    for (int k = 0; k < 3; ++k) {
      int a = raw.triangles(f, k), b = raw.triangles(f, (k + 1) % 3);
      if (a > b) std::swap(a, b);
      auto [it, inserted] =
          edge_owner.emplace(std::make_pair(a, b), std::make_pair(f, (k + 2) % 3));
      if (inserted) continue;
      const Eigen::Index g = it->second.first;
      if (CGAL::orientation(corner(g, 0), corner(g, 1), corner(g, 2), corner(f, (k + 2) % 3)) ==
          CGAL::COPLANAR) {
        const int ra = find(static_cast<int>(f)), rb = find(static_cast<int>(g));
        if (ra != rb) group[static_cast<size_t>(std::max(ra, rb))] = std::min(ra, rb);
      }
    }
  }
  std::map<int, std::vector<int>> facet_vertices;  // group root -> indices into v
  std::map<int, Eigen::Vector3d> facet_normal;     // group root -> sum of raw normals (outward)
  for (Eigen::Index f = 0; f < nt; ++f) {
    const int r = find(static_cast<int>(f));
    const Eigen::Vector3d a = raw.vertices.row(raw.triangles(f, 0));
    const Eigen::Vector3d b = raw.vertices.row(raw.triangles(f, 1));
    const Eigen::Vector3d c = raw.vertices.row(raw.triangles(f, 2));
    auto [it, inserted] = facet_normal.emplace(r, (b - a).cross(c - a));
    if (!inserted) it->second += (b - a).cross(c - a);
    for (const Eigen::Vector3d* p : {&a, &b, &c}) facet_vertices[r].push_back(index_of(*p));
  }
  // Each facet's plane through three of its own vertices (the first, the farthest from it, the
  // farthest from their line), then regrouped: every hull vertex within tol of that plane.
  std::set<std::vector<int>> facets;
  std::map<std::vector<int>, Eigen::Vector3d> outward;
  for (auto& [root, ids] : facet_vertices) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    if (ids.size() < 3) continue;
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
    const Eigen::Vector3d n = axis.cross(v[static_cast<size_t>(ids[i2])] - p0);
    if (!(n.norm() > 0)) continue;
    const Eigen::Vector3d u = n.normalized();
    std::vector<int> on;
    for (size_t i = 0; i < v.size(); ++i) {
      if (std::abs(u.dot(v[i] - p0)) <= tol) on.push_back(static_cast<int>(i));
    }
    if (on.size() < 3) continue;
    if (facets.insert(on).second) outward.emplace(on, facet_normal[root]);
  }
  std::vector<Eigen::Vector4d> planes;
  std::vector<Eigen::Vector3i> triangles;
  for (const std::vector<int>& on : facets) {
    // The plane through three of its vertices chosen by index: the first, the farthest from
    // it, the farthest from their line.
    const Eigen::Vector3d& p0 = v[static_cast<size_t>(on[0])];
    size_t i1 = 1;
    for (size_t i = 1; i < on.size(); ++i) {
      if ((v[static_cast<size_t>(on[i])] - p0).squaredNorm() >
          (v[static_cast<size_t>(on[i1])] - p0).squaredNorm())
        i1 = i;
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
    if (n.dot(outward.at(on)) < 0) n = -n;
    // A plane some hull vertex lies clearly outside of (a facet too thin for its normal to be
    // computed in doubles) is no face of the hull: dropped, so it measures no depth.
    double excess = 0;
    for (const Eigen::Vector3d& p : v) excess = std::max(excess, n.dot(p - p0));
    if (excess > 1e3 * tol) continue;
    planes.emplace_back(n.x(), n.y(), n.z(), n.dot(p0));
    // The facet polygon (Andrew's monotone chain in the plane, counter-clockwise about n),
    // fanned from its first vertex.
    const Eigen::Vector3d e1 = axis.normalized(), e2 = n.cross(e1);
    std::vector<std::pair<Eigen::Vector2d, int>> q;
    for (int i : on)
      q.emplace_back(Eigen::Vector2d(e1.dot(v[static_cast<size_t>(i)] - p0),
                                     e2.dot(v[static_cast<size_t>(i)] - p0)),
                     i);
    std::sort(q.begin(), q.end(), [](const auto& a, const auto& b) {
      return a.first.x() < b.first.x() ||
             (a.first.x() == b.first.x() &&
              (a.first.y() < b.first.y() || (a.first.y() == b.first.y() && a.second < b.second)));
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
  for (size_t i = 0; i < planes.size(); ++i)
    out.planes.row(static_cast<Eigen::Index>(i)) = planes[i];
  return out;
}

}  // namespace acdplan::acd::internal
