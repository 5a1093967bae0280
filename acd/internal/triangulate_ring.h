#pragma once
// Triangulation of a simple polygon, used by the shortest-path concavity (Algorithm 2).

#include <array>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// Ear-clipping triangulation of the simple, counter-clockwise `ring` (n >= 3 vertices; may
/// contain collinear vertices). Returns n - 2 triangles as counter-clockwise index triples
/// into `ring`. Ear tests use exact orientation predicates; only reflex vertices are tested
/// for containment. Tolerates weakly simple rings (a vertex position repeated).
std::vector<std::array<int, 3>> TriangulateRing(const Ring2d& ring);

}  // namespace acdplan::acd::internal
