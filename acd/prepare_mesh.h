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
  /// Vertices where a closed part meets itself in several fans of faces that could not be
  /// separated (their edges there too short to move them apart; see step 5 below).
  int pinch_vertices = 0;
  /// The first defect, naming the rule, an element and a point, e.g. "edge 12-40 at (0.5, 1, 0)
  /// has 3 faces (a solid needs exactly 2)"; empty when there is none.
  std::string first;
  bool none() const {
    return boundary_edges == 0 && non_manifold_edges == 0 && self_intersections == 0 &&
           pinch_vertices == 0;
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
  /// Per part: every edge of it has exactly two triangles, so ray parity defines an inside
  /// (true for every part of a solid; a closed shell that crosses itself or another one is
  /// closed but not solid).
  std::vector<bool> closed_parts;
  MeshDefects defects;             ///< What stands between this mesh and a solid.
  std::vector<std::string> notes;  ///< What preparation changed, one line each.
  /// Closed, manifold, free of self-intersections, every part bounding a positive volume: the
  /// solid ACD applies.
  bool solid() const { return defects.none() && !parts.empty(); }
};

/// Cleans and diagnoses `mesh`; with `options.repair`, repairs what it can. Never throws on a
/// valid TriangleMesh whatever its defects: they are reported in `defects`.
///
/// Steps, each reported in `notes` when it changes something ("merged 1203 duplicate
/// vertices", "dropped 4 degenerate faces (first: face 17)", face numbers of the input):
/// 1. Cleaning: vertices at identical positions merged (exact comparison); triangles with a
///    repeated corner or three collinear corners (exact predicate) dropped, as are repeats of a
///    triangle (same three vertices, either orientation: the first is kept) and the vertices no
///    triangle uses. Vertices and triangles keep their relative order.
/// 2. Patches: triangles connected across edges that have exactly two triangles. Each is
///    oriented consistently from its lowest triangle; each closed one outward (the exact sign of
///    its enclosed volume).
/// 3. Diagnosis on the cleaned mesh: edges with one triangle (boundary), with three or more
///    (non-manifold), pairs of triangles that cross (exact predicates; shells of different
///    parts that cross count too). `defects.first` names the first defect in that order, by
///    the cleaned mesh's vertex and face numbers: "edge 12-40 at (0.5, 1, 0) has 1 face (a
///    solid's edges have exactly 2)", "faces 3 and 17 intersect at (x, y, z) (a solid's
///    surface does not cross itself)".
/// 4. Parts: with no defect, the closed shells are nested (CGAL Side_of_triangle_mesh): a shell
///    inside an odd number of others is a cavity, turned inward and put in the part of the
///    innermost shell around it; a shell inside an even number starts a part. Otherwise the
///    parts are the patches. Parts are ordered by their lowest triangle.
/// 5. Pinches: a vertex where a solid part meets itself in several fans of triangles (a cavity
///    touching the outer shell, two lobes touching at a point) gets one copy per fan, moved 1e-3
///    of the shortest edge there (internal::SeparatePinches; the outer shell's fan stays), so
///    that every part is a 2-manifold that cuts can split; then steps 1-4 run again. Parts that
///    touch each other at a vertex keep it: each is decomposed on its own. A pinch left (its
///    edges too short for a copy to move off it in doubles) is a defect, "vertex 3 at (x, y, z)
///    is a pinch: ...", and the parts are then the patches.
/// Repair (options.repair, when there are defects): first, a triangle the input gives as often
/// facing one way as the other (a two-sided sheet, a face two closed shells share back to back)
/// is dropped with all its copies, since by the winding rule below it bounds nothing (unless
/// every triangle is such); then boundary loops are triangulated without new vertices
/// (PMP::triangulate_hole_polyline, 2D constrained Delaunay when the loop is nearly planar);
/// then, if the mesh is closed and manifold, each group of closed shells that cross each other
/// or themselves is replaced by the solid they bound by the positive winding rule, their union
/// when none crosses itself (internal::UniteByWinding, exact, rounded to doubles at the end).
/// The result is cleaned and diagnosed again; what repair could not mend stays in `defects`.
///
/// Complexity: O(F log F) for F triangles plus O(k) for k crossing candidate pairs (box
/// intersection), O(S^2) bounding-box tests for S closed shells; repair adds the hole
/// triangulations and the exact unions. About 0.2 s for 40k triangles (Release).
/// @throws InputError "<where>: <rule>" if `mesh` fails CheckTriangleMesh() or has no face of
///         positive area ("<where>: mesh has no face of positive area (all 3 faces are
///         degenerate)").
PreparedMesh PrepareMesh(const TriangleMesh& mesh, const PrepareMeshOptions& options = {},
                         const std::string& where = "mesh");

/// @throws InputError "<where>: not a solid: <defects.first> (use --repair to close holes and
///         remove self-intersections, or --surface)" unless `prepared.solid()`.
void RequireSolid(const PreparedMesh& prepared, const std::string& where);

/// Radius of the minimum enclosing sphere of the mesh's vertices: the unit of tau_rel in 3D
/// (the dissertation normalises models to a unit enclosing sphere, Tables 4 and 5).
double ReferenceRadius(const TriangleMesh& mesh);

}  // namespace acdplan::acd
