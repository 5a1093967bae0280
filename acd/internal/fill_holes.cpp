#include "acd/internal/fill_holes.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <queue>

#include "acd/internal/mesh_edges.h"

namespace acdplan::acd::internal {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
namespace PMP = CGAL::Polygon_mesh_processing;

// A boundary halfedge: from `from` to `to`, opposite to the edge of triangle `face` whose
// third corner is `apex` (the hole's filling should not fold onto that triangle).
struct BorderHalfedge {
  int from, to, apex;
};

// Chains the border halfedges into simple loops (vertex lists). Halfedges that do not close
// into a loop are counted in `*broken`.
std::vector<std::vector<const BorderHalfedge*>> TraceLoops(
    const std::vector<BorderHalfedge>& border, int* broken) {
  std::multimap<int, size_t> outgoing;  // Ordered: the lowest halfedge is followed first.
  for (size_t i = 0; i < border.size(); ++i) outgoing.emplace(border[i].from, i);
  std::vector<bool> used(border.size(), false);
  std::vector<std::vector<const BorderHalfedge*>> loops;
  for (size_t start = 0; start < border.size(); ++start) {
    if (used[start]) continue;
    std::vector<const BorderHalfedge*> path;
    std::map<int, size_t> position;  // Vertex -> index in path of the halfedge leaving it.
    size_t current = start;
    while (true) {
      used[current] = true;
      const BorderHalfedge& h = border[current];
      position[h.from] = path.size();
      path.push_back(&h);
      auto found = position.find(h.to);
      if (found != position.end()) {         // Back at a vertex of the path: a loop closes.
        const size_t begin = found->second;  // Copied: the loop below erases `found`.
        loops.emplace_back(path.begin() + static_cast<std::ptrdiff_t>(begin), path.end());
        for (size_t i = begin; i < path.size(); ++i) position.erase(path[i]->from);
        path.resize(begin);
        if (path.empty()) break;
      }
      // Continue from the end of the path (h.to, or the vertex a closed loop returned to).
      const int tip = path.empty() ? h.to : path.back()->to;
      size_t next = border.size();
      for (auto [it, end] = outgoing.equal_range(tip); it != end; ++it) {
        if (!used[it->second]) {
          next = it->second;
          break;
        }
      }
      if (next == border.size()) {  // Dead end: an inconsistently oriented boundary.
        *broken += static_cast<int>(path.size());
        break;
      }
      current = next;
    }
  }
  return loops;
}

using PatchTriangle = CGAL::Triple<int, int, int>;

// The triangles of the hole `points` (in loop order) when the hole is nearly planar, as
// index triples in ascending order (CGAL's hole filling gives them so; the order of the
// loop orients them). A constrained Delaunay triangulation of the loop's projection along
// the dominant axis of its normal, when that projection is a simple polygon: the projection
// drops a coordinate, so it is exact, and simplicity and the triangulation are decided by
// exact predicates. CGAL's own planar path (use_2d_constrained_delaunay_triangulation)
// projects along an averaged normal with rounded constructions, which can call a loop simple
// and then build an inconsistent triangulation (undefined behaviour inside CGAL; found by
// fuzz_decompose3d). "Nearly planar" is CGAL's default rule: every point within a quarter of
// the bounding box's diagonal of the plane through the centroid. Empty when the loop is not
// nearly planar or its projection is not simple: the caller then uses CGAL's 3D search.
std::vector<PatchTriangle> TriangulatePlanarHole(const std::vector<Epick::Point_3>& points) {
  const int n = static_cast<int>(points.size());
  if (n < 3) return {};
  // Newell's normal and the centroid; rounding here only chooses between two valid methods.
  std::array<double, 3> normal = {0, 0, 0}, centroid = {0, 0, 0};
  for (int i = 0; i < n; ++i) {
    const Epick::Point_3& p = points[i];
    const Epick::Point_3& q = points[(i + 1) % n];
    normal[0] += (p.y() - q.y()) * (p.z() + q.z());
    normal[1] += (p.z() - q.z()) * (p.x() + q.x());
    normal[2] += (p.x() - q.x()) * (p.y() + q.y());
    for (int k = 0; k < 3; ++k) centroid[k] += p[k] / n;
  }
  const double length =
      std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  if (!(length > 0.0)) return {};
  const CGAL::Bbox_3 box = CGAL::bbox_3(points.begin(), points.end());
  const double quarter_diagonal = 0.25 * std::sqrt(CGAL::square(box.xmax() - box.xmin()) +
                                                   CGAL::square(box.ymax() - box.ymin()) +
                                                   CGAL::square(box.zmax() - box.zmin()));
  for (const Epick::Point_3& p : points) {
    double distance = 0.0;
    for (int k = 0; k < 3; ++k) distance += (p[k] - centroid[k]) * normal[k] / length;
    if (std::abs(distance) > quarter_diagonal) return {};
  }
  const int drop = static_cast<int>(
      std::max_element(normal.begin(), normal.end(),
                       [](double a, double b) { return std::abs(a) < std::abs(b); }) -
      normal.begin());
  std::vector<Epick::Point_2> projected;
  projected.reserve(points.size());
  for (const Epick::Point_3& p : points) {
    projected.emplace_back(p[drop == 0 ? 1 : 0], p[drop == 2 ? 1 : 2]);
  }
  if (!CGAL::is_simple_2(projected.begin(), projected.end(), Epick())) return {};

  // A simple polygon: its edges cross nowhere and pass through no other vertex.
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, Epick>;
  using Fb = CGAL::Constrained_triangulation_face_base_2<
      Epick, CGAL::Triangulation_face_base_with_info_2<bool, Epick>>;
  using Cdt = CGAL::Constrained_Delaunay_triangulation_2<
      Epick, CGAL::Triangulation_data_structure_2<Vb, Fb>, CGAL::No_constraint_intersection_tag>;
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> vertices;
  vertices.reserve(points.size());
  for (int i = 0; i < n; ++i) {
    vertices.push_back(cdt.insert(projected[i]));
    vertices.back()->info() = i;
  }
  for (int i = 0; i < n; ++i) cdt.insert_constraint(vertices[i], vertices[(i + 1) % n]);
  // Outside: the faces reached from the infinite one without crossing a constraint.
  for (const Cdt::Face_handle f : cdt.all_face_handles()) f->info() = false;
  std::queue<Cdt::Face_handle> outside;
  outside.push(cdt.infinite_face());
  cdt.infinite_face()->info() = true;
  while (!outside.empty()) {
    const Cdt::Face_handle f = outside.front();
    outside.pop();
    for (int k = 0; k < 3; ++k) {
      const Cdt::Face_handle g = f->neighbor(k);
      if (!g->info() && !cdt.is_constrained({f, k})) {
        g->info() = true;
        outside.push(g);
      }
    }
  }
  std::vector<PatchTriangle> triangles;
  for (const Cdt::Face_handle f : cdt.finite_face_handles()) {
    if (f->info()) continue;
    std::array<int, 3> corner = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    std::sort(corner.begin(), corner.end());
    triangles.emplace_back(corner[0], corner[1], corner[2]);
  }
  return triangles;
}

}  // namespace

HoleFilling FillHoles(const TriangleMesh& mesh) {
  const EdgeTable table = BuildEdgeTable(mesh);
  std::vector<BorderHalfedge> border;
  for (const MeshEdge& e : table.edges) {
    if (e.count != 1) continue;
    const int f = table.faces[static_cast<size_t>(e.first)];
    int apex = -1;
    for (int k = 0; k < 3; ++k) {
      if (mesh.triangles(f, k) != e.a && mesh.triangles(f, k) != e.b) apex = mesh.triangles(f, k);
    }
    // The hole runs against its triangle.
    if (RunsForward(mesh, f, e.a, e.b)) {
      border.push_back({e.b, e.a, apex});
    } else {
      border.push_back({e.a, e.b, apex});
    }
  }
  HoleFilling filling;
  int broken = 0;
  auto point = [&](int v) {
    return Epick::Point_3(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2));
  };
  for (const auto& loop : TraceLoops(border, &broken)) {
    std::vector<Epick::Point_3> points, apexes;
    for (const BorderHalfedge* h : loop) {
      points.push_back(point(h->from));
      apexes.push_back(point(h->apex));
    }
    std::vector<PatchTriangle> patch = TriangulatePlanarHole(points);
    if (patch.empty()) {
      try {
        PMP::triangulate_hole_polyline(
            points, apexes, std::back_inserter(patch),
            CGAL::parameters::use_2d_constrained_delaunay_triangulation(false));
      } catch (const CGAL::Failure_exception&) {
        patch.clear();  // A precondition CGAL checks on odd loops: the hole stays open.
      }
    }
    if (patch.empty()) {
      ++filling.failed;
      continue;
    }
    ++filling.filled;
    for (const auto& t : patch) {
      filling.triangles.emplace_back(loop[static_cast<size_t>(t.first)]->from,
                                     loop[static_cast<size_t>(t.second)]->from,
                                     loop[static_cast<size_t>(t.third)]->from);
    }
  }
  if (broken > 0) ++filling.failed;
  return filling;
}

}  // namespace acdplan::acd::internal
