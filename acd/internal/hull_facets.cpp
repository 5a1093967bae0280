#include "acd/internal/hull_facets.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <tuple>

namespace acdplan::acd::internal {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Point2 = Kernel::Point_2;
using HullMesh = CGAL::Surface_mesh<Point3>;

// CGAL's traits for Epick, as a type of our own: convex_hull_3 then tests a point against a
// plane with the kernel's filtered orientation (exact fallback on Mpzf), not with its special
// predicate for CGAL's own traits type, whose exact fallback converts to Gmpq. Both are exact,
// so the hull is the same; but points in a hull facet's plane (a cut's cap, a flat side) fail
// every filter, and there Gmpq cost a third of the hulls' time (perf, mite at tau_rel 0.02).
struct HullTraits : CGAL::Convex_hull_traits_3<Kernel, HullMesh, CGAL::Tag_true> {};

bool Less(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

Eigen::Vector3d ToEigen(const Point3& p) { return {p.x(), p.y(), p.z()}; }

// CGAL 5.5.1's quickhull starts from the plane of the first three non-collinear points; when
// every other point lies on one side of it (those three span a hull facet), it erases a list node
// twice (valgrind: use after free, e.g. on a patch of a torus). Starting the list with a point
// strictly inside the hull (the centroid of a large tetrahedron of the points, checked exactly)
// makes that first plane cut through the hull, so points lie on both sides. Being interior, the
// extra point is never a hull vertex.
void LeadWithAnInteriorPoint(std::vector<Point3>* pts) {
  std::vector<Point3>& p = *pts;
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
    const double d = CGAL::squared_distance(line, p[i]);
    if (d > far) far = d, c = i;
  }
  if (c == a || CGAL::collinear(p[a], p[b], p[c])) return;
  const Kernel::Plane_3 plane(p[a], p[b], p[c]);
  size_t d = a;
  far = 0.0;
  for (size_t i = 0; i < p.size(); ++i) {
    const double e = CGAL::squared_distance(plane, p[i]);
    if (e > far) far = e, d = i;
  }
  const CGAL::Orientation o = CGAL::orientation(p[a], p[b], p[c], p[d]);
  if (o == CGAL::COPLANAR) return;
  const Point3 m((p[a].x() + p[b].x() + p[c].x() + p[d].x()) / 4,
                 (p[a].y() + p[b].y() + p[c].y() + p[d].y()) / 4,
                 (p[a].z() + p[b].z() + p[c].z() + p[d].z()) / 4);
  // Strictly inside the tetrahedron: on the inner side of each of its four faces.
  if (CGAL::orientation(m, p[b], p[c], p[d]) != o || CGAL::orientation(p[a], m, p[c], p[d]) != o ||
      CGAL::orientation(p[a], p[b], m, p[d]) != o || CGAL::orientation(p[a], p[b], p[c], m) != o) {
    return;
  }
  p.insert(p.begin(), m);
}

// `distinct` (sorted, distinct points) thickened along its missing principal directions by
// `thickness`, so that the hull of a flat or degenerate set is a solid (FCL's GJK and the
// half-space test both want a volume).
std::vector<Point3> Thickened(const std::vector<Eigen::Vector3d>& distinct, double thickness) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : distinct) mean += p;
  mean /= static_cast<double>(distinct.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : distinct) cov += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const double largest = std::max(eig.eigenvalues()(2), 0.0);
  std::vector<Point3> pts;
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
  return pts;
}

// The coordinate plane (u, v) that a plane through `a`, `b`, `c` (not collinear) projects onto
// one to one, and the orientation of the three seen there: (x, y) unless the plane is parallel to
// z, then (y, z), then (z, x). The projected orientation is the sign of the normal's missing
// component, exactly.
struct Projection {
  int u = 0, v = 1;
  CGAL::Orientation orientation = CGAL::COLLINEAR;
};

Projection ProjectionOf(const Point3& a, const Point3& b, const Point3& c) {
  for (int u = 0; u < 3; ++u) {
    const int v = (u + 1) % 3;
    const CGAL::Orientation o =
        CGAL::orientation(Point2(a[u], a[v]), Point2(b[u], b[v]), Point2(c[u], c[v]));
    if (o != CGAL::COLLINEAR) return {u, v, o};
  }
  throw std::logic_error("ConvexHullFacets(): a hull triangle with collinear corners");
}

// The corners of the convex polygon of `ids` (indices into `points`, coplanar, not all
// collinear): the 2D convex hull in `projection` (Andrew's monotone chain with exact
// orientations; points on an edge dropped), counter-clockwise there.
std::vector<int> ConvexPolygon(const std::vector<Point3>& points, std::vector<int> ids,
                               const Projection& projection) {
  const int u = projection.u, v = projection.v;
  auto at = [&](int i) {
    const Point3& p = points[static_cast<size_t>(i)];
    return Point2(p[u], p[v]);
  };
  // Points that project to one point (ConvexCornersAlongAxis() takes any) are ordered by the
  // third coordinate, then the index: which of them is a corner must not be left to std::sort.
  const int w = 3 - u - v;
  std::sort(ids.begin(), ids.end(), [&](int a, int b) {
    const Point3& p = points[static_cast<size_t>(a)];
    const Point3& q = points[static_cast<size_t>(b)];
    return std::make_tuple(p[u], p[v], p[w], a) < std::make_tuple(q[u], q[v], q[w], b);
  });
  std::vector<int> chain(2 * ids.size());
  size_t k = 0;
  auto turns_left = [&](int c) {
    return CGAL::orientation(at(chain[k - 2]), at(chain[k - 1]), at(c)) == CGAL::LEFT_TURN;
  };
  for (int id : ids) {  // lower chain
    while (k >= 2 && !turns_left(id)) --k;
    chain[k++] = id;
  }
  for (size_t i = ids.size() - 1, lower = k + 1; i > 0; --i) {  // upper chain
    while (k >= lower && !turns_left(ids[i - 1])) --k;
    chain[k++] = ids[i - 1];
  }
  chain.resize(k - 1);  // the last one repeats the first
  return chain;
}

// The extreme points of a set with no facet (a point or a segment): its lexicographic
// extremes, which are the segment's ends.
HullFacets Ends(const std::vector<Eigen::Vector3d>& sorted_distinct) {
  HullFacets out;
  out.vertices.push_back(sorted_distinct.front());
  if (sorted_distinct.size() > 1) out.vertices.push_back(sorted_distinct.back());
  return out;
}

// `polygons` (each over indices into `points`) as HullFacets: the corners they use, sorted and
// renumbered; each polygon rotated to start at its smallest index; the polygons sorted.
HullFacets Renumbered(const std::vector<Point3>& points,
                      const std::vector<std::vector<int>>& polygons) {
  std::vector<int> used;
  for (const auto& polygon : polygons) used.insert(used.end(), polygon.begin(), polygon.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::sort(used.begin(), used.end(), [&points](int a, int b) {
    return Less(ToEigen(points[static_cast<size_t>(a)]), ToEigen(points[static_cast<size_t>(b)]));
  });
  HullFacets out;
  std::vector<int> rank(points.size(), -1);
  for (size_t i = 0; i < used.size(); ++i) {
    rank[static_cast<size_t>(used[i])] = static_cast<int>(i);
    out.vertices.push_back(ToEigen(points[static_cast<size_t>(used[i])]));
  }
  for (const auto& polygon : polygons) {
    std::vector<int> facet;
    for (int i : polygon) facet.push_back(rank[static_cast<size_t>(i)]);
    std::rotate(facet.begin(), std::min_element(facet.begin(), facet.end()), facet.end());
    out.facets.push_back(std::move(facet));
  }
  std::sort(out.facets.begin(), out.facets.end());
  return out;
}

// The one facet of the flat, not collinear set `points`, oriented counter-clockwise in its
// projection (so about the first of +z, +x, +y its plane is not parallel to).
HullFacets FlatHull(const std::vector<Point3>& points) {
  std::vector<int> ids(points.size());
  std::iota(ids.begin(), ids.end(), 0);
  // Three corners that span the plane: the first two and the first point off their line.
  size_t c = 2;
  while (c < points.size() && CGAL::collinear(points[0], points[1], points[c])) ++c;
  if (c == points.size()) throw std::logic_error("ConvexHullFacets(): a flat hull is a segment");
  const Projection projection = ProjectionOf(points[0], points[1], points[c]);
  return Renumbered(points, {ConvexPolygon(points, ids, projection)});
}

}  // namespace

HullFacets ConvexHullFacets(const std::vector<Eigen::Vector3d>& points, double thickness) {
  if (points.empty()) throw std::logic_error("ConvexHull3(): no points");
  std::vector<Eigen::Vector3d> distinct = points;
  // -0.0 and +0.0 compare equal, so which sign unique() kept would be the sort's choice: adding
  // +0.0 makes every zero +0.0.
  for (Eigen::Vector3d& p : distinct) {
    for (int k = 0; k < 3; ++k) p[k] += 0.0;
  }
  std::sort(distinct.begin(), distinct.end(), Less);
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  // Three points or fewer are hulled here: CGAL 5.5.1's convex_hull_3 reads and writes freed
  // list nodes (valgrind) for some sets of exactly three points, and thickening by 0 would only
  // repeat points.
  if (distinct.size() <= 3 && thickness == 0) {
    std::vector<Point3> pts;
    for (const auto& p : distinct) pts.emplace_back(p.x(), p.y(), p.z());
    if (pts.size() < 3 || CGAL::collinear(pts[0], pts[1], pts[2])) return Ends(distinct);
    return FlatHull(pts);
  }
  std::vector<Point3> pts = Thickened(distinct, thickness);
  LeadWithAnInteriorPoint(&pts);
  HullMesh mesh;
  CGAL::convex_hull_3(pts.begin(), pts.end(), mesh, HullTraits());
  std::vector<Point3> corners(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
  for (const HullMesh::Vertex_index v : mesh.vertices()) corners[v.idx()] = mesh.point(v);
  if (mesh.number_of_faces() == 0) {  // a point or a segment (only with thickness 0)
    std::vector<Eigen::Vector3d> all;
    for (const Point3& p : pts) all.push_back(ToEigen(p));
    std::sort(all.begin(), all.end(), Less);
    return Ends(all);
  }
  for (const HullMesh::Halfedge_index h : mesh.halfedges()) {
    if (mesh.is_border(h)) {  // one-sided: CGAL's flat hull, a triangulated polygon
      std::vector<Point3> flat;
      for (const HullMesh::Vertex_index v : mesh.vertices()) flat.push_back(mesh.point(v));
      return FlatHull(flat);
    }
  }
  // The facets: triangles joined across each edge whose four points are exactly coplanar. In a
  // convex polytope those are the triangles of one facet, and they are connected.
  const size_t face_slots = mesh.number_of_faces() + mesh.number_of_removed_faces();
  std::vector<size_t> group(face_slots);
  std::iota(group.begin(), group.end(), 0);
  auto find = [&group](size_t x) {
    while (group[x] != x) x = group[x] = group[group[x]];
    return x;
  };
  auto point = [&](HullMesh::Vertex_index v) -> const Point3& { return corners[v.idx()]; };
  for (const HullMesh::Halfedge_index h : mesh.halfedges()) {
    const HullMesh::Halfedge_index o = mesh.opposite(h);
    if (h.idx() > o.idx()) continue;  // each edge once
    const size_t f = mesh.face(h).idx(), g = mesh.face(o).idx();
    if (CGAL::coplanar(point(mesh.source(h)), point(mesh.target(h)),
                       point(mesh.target(mesh.next(h))), point(mesh.target(mesh.next(o))))) {
      const size_t a = find(f), b = find(g);
      if (a != b) group[std::max(a, b)] = std::min(a, b);
    }
  }
  std::vector<int> triangles_in(face_slots, 0);
  for (const HullMesh::Face_index f : mesh.faces()) ++triangles_in[find(f.idx())];
  std::vector<std::vector<int>> polygons;
  std::vector<std::vector<int>> members(face_slots);  // group root -> its triangles' corners
  std::vector<HullMesh::Face_index> sample(face_slots);
  for (const HullMesh::Face_index f : mesh.faces()) {
    const size_t root = find(f.idx());
    std::vector<int>& ids = triangles_in[root] == 1 ? polygons.emplace_back() : members[root];
    for (const HullMesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      ids.push_back(static_cast<int>(v.idx()));
    }
    sample[root] = f;
  }
  // A facet of one triangle is that triangle; the others are polygons of their points.
  for (size_t root = 0; root < face_slots; ++root) {
    std::vector<int>& ids = members[root];
    if (ids.empty()) continue;
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    const HullMesh::Halfedge_index h = mesh.halfedge(sample[root]);
    // Counter-clockwise in the projection, and the triangle is counter-clockwise seen from
    // outside: reversed when the projection looks at the facet from inside.
    const Projection projection = ProjectionOf(point(mesh.source(h)), point(mesh.target(h)),
                                               point(mesh.target(mesh.next(h))));
    std::vector<int> polygon = ConvexPolygon(corners, std::move(ids), projection);
    if (projection.orientation == CGAL::NEGATIVE) std::reverse(polygon.begin(), polygon.end());
    polygons.push_back(std::move(polygon));
  }
  return Renumbered(corners, polygons);
}

std::vector<int> ConvexCornersAlongAxis(const std::vector<Eigen::Vector3d>& points, int drop_axis) {
  if (points.size() <= 1) return std::vector<int>(points.size(), 0);
  std::vector<Point3> pts;
  pts.reserve(points.size());
  for (const auto& p : points) pts.emplace_back(p.x(), p.y(), p.z());
  std::vector<int> ids(points.size());
  std::iota(ids.begin(), ids.end(), 0);
  Projection projection;
  projection.u = (drop_axis + 1) % 3;
  projection.v = (drop_axis + 2) % 3;
  return ConvexPolygon(pts, std::move(ids), projection);
}

TriangleMesh FanTriangulation(const HullFacets& hull) {
  std::vector<Eigen::Vector3i> triangles;
  for (const std::vector<int>& facet : hull.facets) {
    for (size_t i = 1; i + 1 < facet.size(); ++i) {
      triangles.emplace_back(facet[0], facet[i], facet[i + 1]);
    }
  }
  std::sort(triangles.begin(), triangles.end(),
            [](const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
              return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
            });
  return MakeTriangleMesh(hull.vertices, triangles);
}

}  // namespace acdplan::acd::internal
