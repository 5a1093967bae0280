#include "collision/internal/mesh_building.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <vector>

#include "acd/internal/nesting_levels.h"

namespace acdplan::collision::internal {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

struct FaceInfo {
  int nesting = -1;  // -1: not visited; odd: inside the polygon
  bool inside() const { return nesting % 2 == 1; }
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using Fbb = CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel>;
using Fb = CGAL::Constrained_triangulation_face_base_2<Kernel, Fbb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

void AddRingWalls(const acd::Ring2d& ring, int bottom0, int top0, int ring_offset,
                  std::vector<Eigen::Vector3i>* tris) {
  const int n = static_cast<int>(ring.size());
  for (int i = 0; i < n; ++i) {
    const int a = ring_offset + i, b = ring_offset + (i + 1) % n;
    // Outward for a CCW outer ring and for a CW hole: the wall normal is e x z.
    tris->emplace_back(bottom0 + a, bottom0 + b, top0 + b);
    tris->emplace_back(bottom0 + a, top0 + b, top0 + a);
  }
}

}  // namespace

acd::TriangleMesh ExtrudePolygon(const acd::Polygon2d& polygon, double z0, double z1) {
  std::vector<const acd::Ring2d*> rings{&polygon.outer};
  for (const acd::Ring2d& hole : polygon.holes) rings.push_back(&hole);
  std::vector<Eigen::Vector2d> flat;
  for (const acd::Ring2d* ring : rings) flat.insert(flat.end(), ring->begin(), ring->end());
  const int n = static_cast<int>(flat.size());

  std::vector<Eigen::Vector3d> v;
  v.reserve(2 * static_cast<size_t>(n));
  for (const auto& p : flat) v.emplace_back(p.x(), p.y(), z0);
  for (const auto& p : flat) v.emplace_back(p.x(), p.y(), z1);
  std::vector<Eigen::Vector3i> tris;

  int offset = 0;
  for (const acd::Ring2d* ring : rings) {
    AddRingWalls(*ring, 0, n, offset, &tris);
    offset += static_cast<int>(ring->size());
  }

  Cdt cdt;
  offset = 0;
  for (const acd::Ring2d* ring : rings) {
    const int m = static_cast<int>(ring->size());
    std::vector<Cdt::Vertex_handle> handles;
    for (int i = 0; i < m; ++i) {
      const auto& p = (*ring)[static_cast<size_t>(i)];
      Cdt::Vertex_handle h = cdt.insert(Kernel::Point_2(p.x(), p.y()));
      h->info() = offset + i;
      handles.push_back(h);
    }
    for (int i = 0; i < m; ++i) cdt.insert_constraint(handles[i], handles[(i + 1) % m]);
    offset += m;
  }
  acd::internal::MarkNestingLevels(cdt);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->info().inside()) continue;
    const int a = f->vertex(0)->info(), b = f->vertex(1)->info(), c = f->vertex(2)->info();
    tris.emplace_back(n + a, n + b, n + c);  // CDT faces are CCW: top cap faces +z
    tris.emplace_back(a, c, b);              // bottom cap faces -z
  }
  return acd::MakeTriangleMesh(v, tris);
}

acd::TriangleMesh ExtrudeConvexRing(const acd::Ring2d& hull, double z0, double z1) {
  const int n = static_cast<int>(hull.size());
  std::vector<Eigen::Vector3d> v;
  for (const auto& p : hull) v.emplace_back(p.x(), p.y(), z0);
  for (const auto& p : hull) v.emplace_back(p.x(), p.y(), z1);
  std::vector<Eigen::Vector3i> tris;
  AddRingWalls(hull, 0, n, 0, &tris);
  for (int i = 1; i + 1 < n; ++i) {
    tris.emplace_back(n, n + i, n + i + 1);
    tris.emplace_back(0, i + 1, i);
  }
  return acd::MakeTriangleMesh(v, tris);
}

acd::TriangleMesh SubMesh(const acd::TriangleMesh& mesh, const std::vector<int>& triangles) {
  std::vector<int> index(static_cast<size_t>(mesh.vertices.rows()), -1);
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> faces;
  for (int f : triangles) {
    Eigen::Vector3i face;
    for (int k = 0; k < 3; ++k) {
      int& i = index[static_cast<size_t>(mesh.triangles(f, k))];
      if (i < 0) {
        i = static_cast<int>(vertices.size());
        vertices.push_back(mesh.vertices.row(mesh.triangles(f, k)).transpose());
      }
      face[k] = i;
    }
    faces.push_back(face);
  }
  return acd::MakeTriangleMesh(vertices, faces);
}

bool EqualsItsHull(const acd::TriangleMesh& piece, const acd::TriangleMesh& hull) {
  auto point = [](const acd::TriangleMesh& mesh, Eigen::Index i) {
    return Kernel::Point_3(mesh.vertices(i, 0), mesh.vertices(i, 1), mesh.vertices(i, 2));
  };
  std::vector<Kernel::Point_3> corners;
  for (Eigen::Index i = 0; i < hull.vertices.rows(); ++i) corners.push_back(point(hull, i));
  for (Eigen::Index f = 0; f < piece.triangles.rows(); ++f) {
    const Kernel::Point_3 a = point(piece, piece.triangles(f, 0));
    const Kernel::Point_3 b = point(piece, piece.triangles(f, 1));
    const Kernel::Point_3 c = point(piece, piece.triangles(f, 2));
    if (CGAL::collinear(a, b, c)) continue;  // No plane; its edges lie on neighbouring faces.
    // POSITIVE: in front of the counter-clockwise face, i.e. outside the piece at this face.
    for (const Kernel::Point_3& corner : corners) {
      if (CGAL::orientation(a, b, c, corner) == CGAL::POSITIVE) return false;
    }
  }
  return piece.triangles.rows() > 0;
}

}  // namespace acdplan::collision::internal
