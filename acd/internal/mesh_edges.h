#pragma once
// The undirected edges of a triangle mesh and the triangles on each.

#include <array>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

/// An undirected edge a-b (a < b) and where its triangles are listed in EdgeTable::faces.
struct MeshEdge {
  int a = 0, b = 0;
  int first = 0;  ///< Index of its first triangle in EdgeTable::faces.
  int count = 0;  ///< Number of triangles on it: 1 on a boundary, 2 on a closed manifold.
};

/// Every edge of a mesh with its triangles.
struct EdgeTable {
  std::vector<MeshEdge> edges;  ///< Sorted by (a, b).
  std::vector<int> faces;       ///< Triangles of each edge, ascending, edge after edge.
  /// face_edges[f][k]: index in `edges` of the edge from corner k to corner k + 1 of f.
  std::vector<std::array<int, 3>> face_edges;
};

/// The edge table of `mesh` (indices valid). O(F log F) for F triangles.
EdgeTable BuildEdgeTable(const TriangleMesh& mesh);

/// True if triangle `f` of `mesh` runs along its edge from `a` to `b` (corner a followed by b),
/// false if from b to a. Requires a-b to be an edge of f.
bool RunsForward(const TriangleMesh& mesh, int f, int a, int b);

}  // namespace acdplan::acd::internal
