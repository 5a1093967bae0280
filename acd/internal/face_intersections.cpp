#include "acd/internal/face_intersections.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>

#include "acd/internal/exact_rounding.h"

namespace acdplan::acd::internal {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, int>;

template <class K>
typename K::Point_3 PointOf(const TriangleMesh& mesh, int v) {
  return typename K::Point_3(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2));
}

// The rule of the header, for triangles f != g.
bool FacesIntersect(const TriangleMesh& mesh, int f, int g) {
  std::array<int, 3> a{mesh.triangles(f, 0), mesh.triangles(f, 1), mesh.triangles(f, 2)};
  std::array<int, 3> b{mesh.triangles(g, 0), mesh.triangles(g, 1), mesh.triangles(g, 2)};
  int shared = 0, ia = -1, ib = -1;  // Corners of the last shared vertex in a and b.
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (a[i] == b[j]) {
        ++shared;
        ia = i;
        ib = j;
      }
    }
  }
  if (shared == 3) return true;  // The same triangle twice (excluded by the caller).
  auto p = [&](int v) { return PointOf<Epick>(mesh, v); };
  if (shared == 2) {
    // The corners not on the shared edge.
    int ca = -1, cb = -1;
    for (int i = 0; i < 3; ++i) {
      if (std::find(b.begin(), b.end(), a[i]) == b.end()) ca = a[i];
      if (std::find(a.begin(), a.end(), b[i]) == a.end()) cb = b[i];
    }
    int e0 = -1, e1 = -1;
    for (int i = 0; i < 3; ++i) {
      if (a[i] == ca) continue;
      (e0 < 0 ? e0 : e1) = a[i];
    }
    return CGAL::coplanar(p(e0), p(e1), p(ca), p(cb)) &&
           CGAL::coplanar_orientation(p(e0), p(e1), p(ca), p(cb)) == CGAL::POSITIVE;
  }
  const Epick::Triangle_3 ta(p(a[0]), p(a[1]), p(a[2]));
  const Epick::Triangle_3 tb(p(b[0]), p(b[1]), p(b[2]));
  if (shared == 1) {
    const Epick::Segment_3 sa(p(a[(ia + 1) % 3]), p(a[(ia + 2) % 3]));
    const Epick::Segment_3 sb(p(b[(ib + 1) % 3]), p(b[(ib + 2) % 3]));
    return CGAL::do_intersect(ta, sb) || CGAL::do_intersect(tb, sa);
  }
  return CGAL::do_intersect(ta, tb);
}

// The box of face f.
CGAL::Bbox_3 BboxOf(const TriangleMesh& mesh, int f) {
  CGAL::Bbox_3 box;
  for (int k = 0; k < 3; ++k) box += PointOf<Epick>(mesh, mesh.triangles(f, k)).bbox();
  return box;
}

}  // namespace

std::vector<std::pair<int, int>> IntersectingFacePairs(const TriangleMesh& mesh) {
  std::vector<Box> boxes;
  boxes.reserve(static_cast<size_t>(mesh.triangles.rows()));
  for (int f = 0; f < static_cast<int>(mesh.triangles.rows()); ++f) {
    boxes.emplace_back(BboxOf(mesh, f), f);
  }
  std::vector<std::pair<int, int>> pairs;
  // Closed boxes: triangles that only touch are candidates too.
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
    const int f = std::min(x.info(), y.info()), g = std::max(x.info(), y.info());
    if (FacesIntersect(mesh, f, g)) pairs.emplace_back(f, g);
  });
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

bool AnyFaceIntersects(const TriangleMesh& mesh, const std::vector<int>& faces) {
  if (faces.empty()) return false;
  std::vector<CGAL::Bbox_3> boxes;
  boxes.reserve(static_cast<size_t>(mesh.triangles.rows()));
  for (int f = 0; f < static_cast<int>(mesh.triangles.rows()); ++f)
    boxes.push_back(BboxOf(mesh, f));
  std::vector<Box> some, all;
  CGAL::Bbox_3 around;
  for (const int f : faces) {
    some.emplace_back(boxes[static_cast<size_t>(f)], f);
    around += boxes[static_cast<size_t>(f)];
  }
  // Only faces that meet the box around all listed ones can meet one of them: the listed faces
  // of a cut piece lie along the cut, so this leaves box_intersection_d a fraction of the mesh.
  for (int f = 0; f < static_cast<int>(boxes.size()); ++f) {
    if (CGAL::do_overlap(around, boxes[static_cast<size_t>(f)])) {
      all.emplace_back(boxes[static_cast<size_t>(f)], f);
    }
  }
  std::vector<char> listed(static_cast<size_t>(mesh.triangles.rows()), 0);
  for (const int f : faces) listed[static_cast<size_t>(f)] = 1;
  bool found = false;
  CGAL::box_intersection_d(some.begin(), some.end(), all.begin(), all.end(),
                           [&](const Box& x, const Box& y) {
                             const int f = x.info(), g = y.info();
                             // Two listed faces meet twice, as (f, g) and (g, f): tested once.
                             if (found || f == g || (listed[static_cast<size_t>(g)] && g < f)) {
                               return;
                             }
                             found = FacesIntersect(mesh, std::min(f, g), std::max(f, g));
                           });
  return found;
}

Eigen::Vector3d FaceIntersectionPoint(const TriangleMesh& mesh, int f, int g) {
  auto triangle = [&](int t) {
    return Epeck::Triangle_3(PointOf<Epeck>(mesh, mesh.triangles(t, 0)),
                             PointOf<Epeck>(mesh, mesh.triangles(t, 1)),
                             PointOf<Epeck>(mesh, mesh.triangles(t, 2)));
  };
  auto to_eigen = [](const Epeck::Point_3& p) { return RoundToDouble(p); };
  const auto result = CGAL::intersection(triangle(f), triangle(g));
  if (!result) {  // Not expected for an intersecting pair; the centroid of f still locates it.
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) c += mesh.vertices.row(mesh.triangles(f, k)).transpose() / 3;
    return c;
  }
  // A point, a segment (its midpoint), a triangle or a polygon (the mean of its corners): a
  // point of the intersection either way, since the intersection is convex.
  if (const auto* point = boost::get<Epeck::Point_3>(&*result)) return to_eigen(*point);
  if (const auto* segment = boost::get<Epeck::Segment_3>(&*result)) {
    return to_eigen(CGAL::midpoint(segment->source(), segment->target()));
  }
  if (const auto* tri = boost::get<Epeck::Triangle_3>(&*result)) {
    return to_eigen(CGAL::centroid(tri->vertex(0), tri->vertex(1), tri->vertex(2)));
  }
  const auto& polygon = boost::get<std::vector<Epeck::Point_3>>(*result);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : polygon) mean += to_eigen(p);
  return mean / static_cast<double>(polygon.size());
}

}  // namespace acdplan::acd::internal
