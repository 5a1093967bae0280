#pragma once
// Geodesic (shortest-path) distances inside simple polygons: the engine behind SP-concavity
// (dissertation Ch. IV.A.1.b, Algorithm 2) and the geodesic diameter estimate of a hole.

#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// Shortest-path tree inside a simple polygon from one of its vertices.
struct ShortestPathTree {
  std::vector<int> parent;       ///< Previous vertex on the path to the source; -1 at the source.
  std::vector<double> distance;  ///< Geodesic distance to the source [units].
};

/// Shortest paths from vertex `source` to every vertex of the simple, counter-clockwise `ring`,
/// staying inside the closed polygon (Lee & Preparata funnel over a triangulation of the
/// ring). O(n) funnel steps on top of the triangulation in typical cases.
ShortestPathTree ComputeShortestPathTree(const Ring2d& ring, int source);

/// Geodesic distances from every vertex of a pocket chain to its bridge (Algorithm 2).
///
/// `chain` runs from the bridge end beta- = chain.front() to beta+ = chain.back() and, with the
/// bridge segment (back() -> front()), bounds a simple polygon (the pocket polygon P_rho,
/// Fig. 16(a)); every chain vertex but the two ends lies strictly on one side of the bridge
/// line. Returns, per chain vertex, the length of the shortest path inside P_rho to any point
/// of the bridge segment (0 at both ends). A path ends either perpendicular to the bridge or at
/// an end (Lemma A.2).
std::vector<double> ShortestPathsToBridge(const Ring2d& chain);

}  // namespace acdplan::acd::internal
