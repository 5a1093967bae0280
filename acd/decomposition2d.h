#pragma once
// The result of a 2D approximate convex decomposition.

#include <string>
#include <vector>

#include "acd/concavity_measure.h"
#include "acd/polygon2d.h"

namespace acdplan::acd {

/// A leaf of the decomposition: a tau-convex piece of the input.
struct Component2d {
  Polygon2d polygon;  ///< Boundary counter-clockwise; holes (clockwise) only while unresolved.
  Ring2d hull;        ///< Convex hull of the boundary, counter-clockwise, no collinear vertices.
  Point2d centroid = Point2d::Zero();  ///< Area centroid of `polygon`.
  double concavity = 0.0;  ///< Concavity of `polygon` under the measure used [units]; 0 if convex.
  int source = 0;          ///< Index of the input polygon this component came from.
};

/// A maximal segment shared by two leaf components: an opening between them.
struct Opening2d {
  Point2d a = Point2d::Zero(), b = Point2d::Zero();  ///< End points.
  int component_a = -1, component_b = -1;  ///< Indices into Decomposition2d::components, a < b.
};

/// A cut made by Resolve (Algorithm 5): a segment across the piece, from the resolved notch.
struct Cut2d {
  Point2d from, to;
};

/// A node of the hierarchy tree (Ch. III, Fig. 9(b)). Internal nodes keep the cut(s) that split
/// them, and with Decompose2dOptions::keep_pieces their pieces, so coarser levels of detail can
/// be read back.
struct HierarchyNode2d {
  /// The piece at this node: at a root always (the input); elsewhere with keep_pieces only (a
  /// leaf's piece is components[component].polygon in any case).
  Polygon2d piece;
  double concavity = 0.0;  ///< Its concavity [units].
  /// At a leaf, the piece's most concave point; at an internal node, the feature its cut(s)
  /// resolved (the most concave point unless no valid cut started there, or the piece's holes
  /// were halved rather than peeled: then where the path left the hole it started from).
  Point2d witness = Point2d::Zero();
  /// One cut (an outer notch), or k + 1 cuts along a path from the outer boundary through the
  /// k >= 1 holes the split resolves and back (a hole: two, at p and cw(p)).
  std::vector<Cut2d> cuts;
  int parent = -1;             ///< Index of the parent node; -1 at a root.
  int children[2] = {-1, -1};  ///< Indices of the two children; -1 at a leaf.
  int component = -1;          ///< Index into Decomposition2d::components at a leaf.
  int depth = 0;               ///< 0 at a root.
};

/// Summary figures (DESIGN.md's decomposition JSON "stats").
struct DecompositionStats2d {
  int vertices = 0;  ///< Vertices of the (cleaned) input.
  int notches = 0;   ///< Reflex vertices of the input (outer and hole boundaries).
  int components = 0;
  double max_concavity = 0.0;  ///< Largest component concavity [units].
  double convexity = 1.0;      ///< Sum of component areas / sum of their hull areas (Eqn. 4.4).
  double time_ms = 0.0;        ///< Decomposition alone, without I/O.
};

/// Everything Decompose2d() returns.
struct Decomposition2d {
  ConcavityMeasure measure = ConcavityMeasure::kShortestPath;
  double tau = 0.0;                     ///< Absolute tolerance used [units].
  double min_convexity = 0.0;           ///< > 0 when Algorithm 9 (shape decomposition) was used.
  std::vector<Component2d> components;  ///< The leaves, in depth-first order.
  std::vector<Opening2d> openings;      ///< Shared segments between leaves.
  std::vector<HierarchyNode2d> tree;    ///< Node 0.. roots: one root per input polygon.
  std::vector<int> roots;               ///< Indices of the root nodes in `tree`.
  DecompositionStats2d stats;
};

/// The component adjacency graph: for each component, the indices of the components it shares
/// an opening with (sorted, no duplicates).
std::vector<std::vector<int>> ComponentGraph(const Decomposition2d& decomposition);

}  // namespace acdplan::acd
