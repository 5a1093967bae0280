#pragma once
// Triangles of a TriangleMesh as a CGAL Surface_mesh, for the Polygon_mesh_processing calls
// that need a halfedge structure. Internal, and CGAL-heavy: include only from the .cpp files
// that call CGAL on surfaces.

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <map>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

/// The triangles `faces` of `mesh` as a Surface_mesh over kernel K's points. A vertex where the
/// triangles meet in several fans (a pinch) becomes one vertex per fan, as a halfedge structure
/// needs (PMP::orient_polygon_soup), so `faces` may be any edge-manifold, orientable set; their
/// orientation is kept where it is consistent.
template <class K>
CGAL::Surface_mesh<typename K::Point_3> ToSurfaceMesh(const TriangleMesh& mesh,
                                                      const std::vector<int>& faces) {
  using Point = typename K::Point_3;
  std::map<int, size_t> local;
  std::vector<Point> points;
  std::vector<std::array<size_t, 3>> triangles;
  triangles.reserve(faces.size());
  for (const int f : faces) {
    std::array<size_t, 3> t{};
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles(f, k);
      auto [it, inserted] = local.emplace(v, points.size());
      if (inserted)
        points.emplace_back(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2));
      t[static_cast<size_t>(k)] = it->second;
    }
    triangles.push_back(t);
  }
  CGAL::Polygon_mesh_processing::orient_polygon_soup(points, triangles);
  CGAL::Surface_mesh<Point> surface;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, surface);
  return surface;
}

}  // namespace acdplan::acd::internal
