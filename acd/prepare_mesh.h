#pragma once
// Preparing a triangle mesh for the 3D decomposition: cleaning, orientation, parts, and the
// diagnosis that decides between the solid and the surface ACD (dissertation Ch. V).

#include <string>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::acd {

/// Options for PrepareMesh(); `{}` is valid.
struct PrepareMeshOptions {
  /// Close holes (boundary loops, triangulated) and remove self-intersections (the union of
  /// overlapping closed parts) so that the solid ACD can run; every change is reported in
  /// PreparedMesh::notes. Without it, defects are only diagnosed.
  bool repair = false;
};

/// The defects PrepareMesh() found in the cleaned mesh (after repair, when asked).
struct MeshDefects {
  int boundary_edges = 0;      ///< Edges with one incident face: the surface is open.
  int non_manifold_edges = 0;  ///< Edges with three or more incident faces.
  int self_intersections = 0;  ///< Pairs of faces that meet other than in a shared edge/vertex.
  /// The first defect, naming the rule, an element and a point, e.g. "edge 12-40 at (0.5, 1, 0)
  /// has 3 faces (a solid needs exactly 2)"; empty when there is none.
  std::string first;
  bool none() const {
    return boundary_edges == 0 && non_manifold_edges == 0 && self_intersections == 0;
  }
};

/// A mesh ready for Decompose3d().
struct PreparedMesh {
  /// The cleaned mesh: vertices at identical positions merged, unreferenced vertices and
  /// degenerate (zero-area) faces dropped, faces oriented consistently (outward when closed).
  TriangleMesh mesh;
  /// Its parts, each a solid (one outer shell and the cavity shells inside it, all closed and
  /// outward-oriented so that the enclosed volume is positive) when solid(), else a connected
  /// surface patch. Decompose3d() decomposes each part; components keep the part's index.
  std::vector<TriangleMesh> parts;
  MeshDefects defects;             ///< What stands between this mesh and a solid.
  std::vector<std::string> notes;  ///< What preparation changed, one line each.
  /// Closed, manifold, free of self-intersections, every part bounding a positive volume: the
  /// solid ACD applies.
  bool solid() const { return defects.none() && !parts.empty(); }
};

/// Cleans and diagnoses `mesh` (CGAL Polygon_mesh_processing for orientation, connected parts,
/// holes and self-intersections); with `options.repair`, repairs first. Never throws on a
/// valid TriangleMesh whatever its defects: they are reported in `defects`.
/// @throws InputError "<where>: <rule>" if `mesh` fails CheckTriangleMesh() or has no face of
///         positive area.
PreparedMesh PrepareMesh(const TriangleMesh& mesh, const PrepareMeshOptions& options = {},
                         const std::string& where = "mesh");

/// @throws InputError "<where>: not a solid: <defects.first> (use --repair to close holes and
///         remove self-intersections, or --surface)" unless `prepared.solid()`.
void RequireSolid(const PreparedMesh& prepared, const std::string& where);

/// Radius of the minimum enclosing sphere of the mesh's vertices: the unit of tau_rel in 3D
/// (the dissertation normalises models to a unit enclosing sphere, Tables 4 and 5).
double ReferenceRadius(const TriangleMesh& mesh);

}  // namespace acdplan::acd
