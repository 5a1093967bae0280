#include "envs/free_space3d.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>

#include <map>
#include <numeric>

#include "acd/internal/cgal_surface_mesh.h"
#include "acd/internal/exact_rounding.h"
#include "acd/mesh_measures.h"
#include "acd/prepare_mesh.h"
#include "base/input_error.h"

namespace acdplan::envs {
namespace {

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Epeck::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

Mesh ToExact(const acd::TriangleMesh& mesh) {
  std::vector<int> faces(static_cast<size_t>(mesh.triangles.rows()));
  std::iota(faces.begin(), faces.end(), 0);
  Mesh exact = acd::internal::ToSurfaceMesh<Epeck>(mesh, faces);
  if (!PMP::is_outward_oriented(exact)) PMP::reverse_face_orientations(exact);
  return exact;
}

acd::TriangleMesh BoxMesh(const Eigen::AlignedBox3d& box) {
  acd::TriangleMesh mesh = acd::Cube(1.0);  // Centred unit cube, outward faces.
  for (int i = 0; i < mesh.vertices.rows(); ++i) {
    for (int k = 0; k < 3; ++k) {
      const double t = mesh.vertices(i, k) + 0.5;  // 0 or 1: pick the box's side exactly.
      mesh.vertices(i, k) = t < 0.5 ? box.min()[k] : box.max()[k];
    }
  }
  return mesh;
}

acd::TriangleMesh ToDoubles(Mesh& exact) {
  exact.collect_garbage();
  std::vector<Eigen::Vector3d> vertices;
  std::map<Mesh::Vertex_index, int> index;
  for (const Mesh::Vertex_index v : exact.vertices()) {
    const Epeck::Point_3& p = exact.point(v);
    index[v] = static_cast<int>(vertices.size());
    vertices.push_back(acd::internal::RoundToDouble(p));  // See RoundToDouble() on why.
  }
  std::vector<Eigen::Vector3i> triangles;
  for (const Mesh::Face_index f : exact.faces()) {
    Eigen::Vector3i t;
    int k = 0;
    for (const Mesh::Vertex_index v : CGAL::vertices_around_face(exact.halfedge(f), exact)) {
      if (k < 3) t(k) = index[v];
      ++k;
    }
    if (k == 3) triangles.push_back(t);
  }
  return acd::MakeTriangleMesh(vertices, triangles);
}

}  // namespace

FreeSpace3dResult FreeSpace3d(const Workspace3d& workspace) {
  if (workspace.bounds.isEmpty() || !(workspace.bounds.volume() > 0)) {
    throw InputError("FreeSpace3d(): the bounds are empty");
  }
  FreeSpace3dResult result;
  Mesh free = ToExact(BoxMesh(workspace.bounds));
  const Eigen::AlignedBox3d& bounds = workspace.bounds;
  for (size_t i = 0; i < workspace.obstacles.size(); ++i) {
    const std::string where = "obstacle " + std::to_string(i);
    const acd::TriangleMesh& obstacle = workspace.obstacles[i];
    acd::CheckTriangleMesh(obstacle, where);
    if (!bounds.intersects(acd::BoundingBox(obstacle))) continue;  // Nothing to subtract.
    acd::PrepareMeshOptions prepare;
    prepare.repair = true;  // Closes holes: an open box becomes the box.
    const acd::PreparedMesh prepared = acd::PrepareMesh(obstacle, prepare, where);
    if (!prepared.solid()) {
      result.notes.push_back(where + ": not a solid even after closing its holes (" +
                             prepared.defects.first +
                             "): not subtracted, left to the collision checker");
      continue;
    }
    Mesh solid = ToExact(prepared.mesh);
    Mesh copy = free;  // Corefinement refines its inputs; keep `free` whole if it fails.
    Mesh difference;
    bool ok = false;
    try {
      ok = PMP::corefine_and_compute_difference(copy, solid, difference);
    } catch (const std::exception&) {
      ok = false;
    }
    if (!ok) {
      result.notes.push_back(where +
                             ": its exact difference with the free space is not a 2-manifold "
                             "(it meets another obstacle along an edge or at a point): not "
                             "subtracted, left to the collision checker");
      continue;
    }
    free = std::move(difference);
  }
  result.mesh = ToDoubles(free);
  result.volume = result.mesh.triangles.rows() > 0 ? acd::MeshVolume(result.mesh) : 0.0;
  return result;
}

}  // namespace acdplan::envs
