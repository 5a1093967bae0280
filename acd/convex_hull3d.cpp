#include "acd/convex_hull3d.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace acdplan::acd {
namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// CGAL 5.5.1's quickhull starts from the plane of the first three non-collinear points; when
// every other point lies on one side of it (those three span a hull facet), it erases a list node
// twice (valgrind: use after free, e.g. on a patch of a torus). Starting the list with a point
// strictly inside the hull (the centroid of a large tetrahedron of the points, checked exactly)
// makes that first plane cut through the hull, so points lie on both sides. Being interior, the
// extra point is never a hull vertex.
void LeadWithAnInteriorPoint(std::vector<Kernel::Point_3>* pts) {
  std::vector<Kernel::Point_3>& p = *pts;
  if (p.size() < 4) return;
  size_t a = 0, b = 0;
  for (size_t i = 1; i < p.size(); ++i) {
    if (p[i].x() < p[a].x()) a = i;
    if (p[i].x() > p[b].x()) b = i;
  }
  if (a == b) return;
  const Kernel::Line_3 line(p[a], p[b]);
  size_t c = a;
  double far = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    const double d = CGAL::to_double(CGAL::squared_distance(line, p[i]));
    if (d > far) far = d, c = i;
  }
  if (c == a || CGAL::collinear(p[a], p[b], p[c])) return;
  const Kernel::Plane_3 plane(p[a], p[b], p[c]);
  size_t d = a;
  far = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    const double e = CGAL::to_double(CGAL::squared_distance(plane, p[i]));
    if (e > far) far = e, d = i;
  }
  const CGAL::Orientation o = CGAL::orientation(p[a], p[b], p[c], p[d]);
  if (o == CGAL::COPLANAR) return;
  const Kernel::Point_3 m((p[a].x() + p[b].x() + p[c].x() + p[d].x()) / 4,
                          (p[a].y() + p[b].y() + p[c].y() + p[d].y()) / 4,
                          (p[a].z() + p[b].z() + p[c].z() + p[d].z()) / 4);
  // Strictly inside the tetrahedron: on the inner side of each of its four faces.
  if (CGAL::orientation(m, p[b], p[c], p[d]) != o || CGAL::orientation(p[a], m, p[c], p[d]) != o ||
      CGAL::orientation(p[a], p[b], m, p[d]) != o || CGAL::orientation(p[a], p[b], p[c], m) != o) {
    return;
  }
  p.insert(p.begin(), m);
}

}  // namespace

TriangleMesh ConvexHull3(const std::vector<Eigen::Vector3d>& points, double thickness) {
  if (points.empty()) throw std::logic_error("ConvexHull3(): no points");
  // Distinct points only, and three points hulled here: CGAL 5.5.1's convex_hull_3 reads and
  // writes freed list nodes (valgrind) for some sets of exactly three points, and thickening by
  // 0 would only repeat points.
  std::vector<Eigen::Vector3d> distinct = points;
  std::sort(distinct.begin(), distinct.end(),
            [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
              return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
            });
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  if (distinct.size() == 3 && thickness == 0) {
    const bool collinear = (distinct[1] - distinct[0]).cross(distinct[2] - distinct[0]).norm() == 0;
    return collinear ? MakeTriangleMesh(distinct, {})
                     : MakeTriangleMesh(distinct, {Eigen::Vector3i(0, 1, 2)});
  }
  // Thicken a flat or degenerate set along its missing principal directions, so the hull is a
  // solid (FCL's GJK and the half-space test both want a volume).
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : distinct) mean += p;
  mean /= static_cast<double>(distinct.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : distinct) cov += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const double largest = std::max(eig.eigenvalues()(2), 0.0);
  std::vector<Kernel::Point_3> pts;
  pts.reserve(distinct.size() * 2);
  for (const auto& p : distinct) pts.emplace_back(p.x(), p.y(), p.z());
  for (int axis = 0; axis < 3; ++axis) {
    const double spread = std::sqrt(std::max(eig.eigenvalues()(axis), 0.0));
    if ((spread > 1e-9 * std::sqrt(largest) && largest > 0) || !(thickness > 0)) continue;
    const Eigen::Vector3d dir = eig.eigenvectors().col(axis) * thickness;
    const size_t count = pts.size();
    for (size_t i = 0; i < count; ++i) {
      pts.emplace_back(pts[i].x() + dir.x(), pts[i].y() + dir.y(), pts[i].z() + dir.z());
    }
  }
  LeadWithAnInteriorPoint(&pts);
  CGAL::Surface_mesh<Kernel::Point_3> hull;
  CGAL::convex_hull_3(pts.begin(), pts.end(), hull);
  std::vector<Eigen::Vector3d> v;
  std::map<CGAL::Surface_mesh<Kernel::Point_3>::Vertex_index, int> index;
  for (auto vi : hull.vertices()) {
    const auto& p = hull.point(vi);
    index[vi] = static_cast<int>(v.size());
    v.emplace_back(p.x(), p.y(), p.z());
  }
  std::vector<Eigen::Vector3i> tris;
  for (auto f : hull.faces()) {
    std::vector<int> ids;
    for (auto vi : CGAL::vertices_around_face(hull.halfedge(f), hull)) ids.push_back(index[vi]);
    for (size_t i = 1; i + 1 < ids.size(); ++i) tris.emplace_back(ids[0], ids[i], ids[i + 1]);
  }
  // CGAL's element order depends on memory addresses: sort vertices by position and triangles by
  // their (rotated) indices, so the same points give the same mesh in every run.
  std::vector<int> order(v.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(), [&v](int a, int b) {
    return std::lexicographical_compare(v[a].data(), v[a].data() + 3, v[b].data(), v[b].data() + 3);
  });
  std::vector<int> rank(v.size());
  std::vector<Eigen::Vector3d> sorted(v.size());
  for (size_t i = 0; i < order.size(); ++i) {
    rank[static_cast<size_t>(order[i])] = static_cast<int>(i);
    sorted[i] = v[static_cast<size_t>(order[i])];
  }
  for (Eigen::Vector3i& t : tris) {
    t = Eigen::Vector3i(rank[t(0)], rank[t(1)], rank[t(2)]);
    while (t(0) > t(1) || t(0) > t(2)) t = Eigen::Vector3i(t(1), t(2), t(0));
  }
  std::sort(tris.begin(), tris.end(), [](const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  return MakeTriangleMesh(sorted, tris);
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
