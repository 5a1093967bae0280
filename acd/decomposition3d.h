#pragma once
// The result of a 3D approximate convex decomposition (dissertation Ch. V).

#include <Eigen/Core>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::acd {

/// A tau-convex piece of the input: a leaf of the hierarchy, or the union of adjacent leaves that
/// the solid ACD merged after its cuts (Decompose3dOptions::merge_growth).
struct Component3d {
  /// Solid ACD: the piece, closed and outward-oriented (its cut faces included). Surface ACD:
  /// the patch of the input surface (open).
  TriangleMesh mesh;
  TriangleMesh hull;  ///< Convex hull of `mesh`, closed, counter-clockwise seen from outside.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< Volume centroid (surface: area).
  double volume = 0.0;       ///< Volume of `mesh` [units^3]; 0 for a surface patch.
  double hull_volume = 0.0;  ///< Volume of `hull` [units^3].
  double concavity = 0.0;    ///< Concavity of `mesh` (Sec. V.B.1) [units]; 0 if convex.
  int source = 0;            ///< Index of the PreparedMesh part this component came from.
};

/// A planar region shared by two leaf components (solid ACD): an opening between them, where a
/// cut went through; one connected region, possibly with holes. Surface ACD: the polyline two
/// patches share (`area` 0, `normal` zero, no holes).
struct Opening3d {
  /// The region's outline, vertices in order; counter-clockwise seen from the tip of `normal`
  /// (solid ACD).
  std::vector<Eigen::Vector3d> polygon;
  /// Holes of the region, each clockwise seen from the tip of `normal`; usually none.
  std::vector<std::vector<Eigen::Vector3d>> holes;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< Unit, from component_a into component_b.
  double area = 0.0;  ///< Of the region: the polygon's less its holes' [units^2].
  int component_a = -1, component_b = -1;  ///< Indices into Decomposition3d::components, a < b.
};

/// A cut plane { x : normal . x = offset }.
struct Plane3d {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< Unit.
  double offset = 0.0;
  /// The signed distance of `p` from the plane, positive on the side the normal points to.
  double SignedDistance(const Eigen::Vector3d& p) const { return normal.dot(p) - offset; }
};

/// A node of the hierarchy tree (Ch. III, Fig. 9(b)), as in 2D.
struct HierarchyNode3d {
  double concavity = 0.0;                             ///< Of the piece at this node [units].
  Eigen::Vector3d witness = Eigen::Vector3d::Zero();  ///< Its most concave point.
  Plane3d cut;                ///< At an internal node: the plane that split the piece.
  int parent = -1;            ///< -1 at a root.
  std::vector<int> children;  ///< A plane cut leaves >= 2 connected pieces; empty at a leaf.
  int component =
      -1;         ///< Index into Decomposition3d::components at a leaf; merged leaves share one.
  int depth = 0;  ///< 0 at a root.
};

/// Summary figures (the JSON's "stats").
struct DecompositionStats3d {
  int vertices = 0;   ///< Of the prepared input.
  int triangles = 0;  ///< Of the prepared input.
  int components = 0;
  double volume = 0.0;         ///< Sum of component volumes [units^3].
  double hull_volume = 0.0;    ///< Sum of component hull volumes [units^3].
  double max_concavity = 0.0;  ///< Largest component concavity [units].
  bool surface = false;        ///< The surface ACD was used.
  double time_ms = 0.0;        ///< Decomposition alone, without I/O.
};

/// Everything Decompose3d() returns.
struct Decomposition3d {
  double tau = 0.0;                     ///< Absolute tolerance used [units].
  int max_hulls = 0;                    ///< The cap asked for; 0 = none.
  double merge_growth = -1;             ///< The hull growth a merge was allowed; < 0: no merging.
  std::vector<Component3d> components;  ///< The leaves, in depth-first order of the tree.
  std::vector<Opening3d> openings;
  std::vector<HierarchyNode3d> tree;
  std::vector<int> roots;  ///< One root per PreparedMesh part.
  DecompositionStats3d stats;
};

/// The component adjacency graph: for each component, the indices of the components it shares
/// an opening with (sorted, no duplicates).
std::vector<std::vector<int>> ComponentGraph(const Decomposition3d& decomposition);

}  // namespace acdplan::acd
