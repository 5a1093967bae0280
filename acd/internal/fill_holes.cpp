#include "acd/internal/fill_holes.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <map>

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
    std::vector<CGAL::Triple<int, int, int>> patch;
    try {
      PMP::triangulate_hole_polyline(
          points, apexes, std::back_inserter(patch),
          CGAL::parameters::use_2d_constrained_delaunay_triangulation(true));
    } catch (const CGAL::Failure_exception&) {
      patch.clear();  // A precondition CGAL checks on odd loops: the hole stays open.
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
