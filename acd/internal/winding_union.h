#pragma once
// The solid that closed shells which cross themselves or each other bound by the positive
// winding rule: the repair of a self-crossing shell.

#include <optional>
#include <utility>
#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

/// What UniteByWinding() returns.
struct WindingUnion {
  TriangleMesh mesh;  ///< Closed, outward; a 2-manifold unless rounding broke it.
  int pinches = 0;    ///< Pinch vertices separated (step 5).
  int specks = 0;     ///< Shells dropped for their size (step 6).
};

/// The boundary of { x : w(x) > 0 }, where w is the winding number of the triangles `faces` of
/// `mesh`: closed shells, each consistently oriented (outward; a part turned inside out counts
/// negatively and is dropped), which may cross themselves and each other. `crossings` lists
/// every pair of `faces` that intersect (IntersectingFacePairs()).
///
/// Method, in exact arithmetic (CGAL Epeck) up to the final rounding:
/// 1. Refinement: each triangle that meets another is triangulated (constrained Delaunay, in
///    its plane projected on the axis plane it is least inclined to) with its intersections
///    as constraints, so the refined triangles meet only in shared edges and vertices, and
///    triangles that overlap in their plane become identical ones.
/// 2. Identical refined triangles are grouped; the group's multiplicity m is their count with
///    orientation (+1 along, -1 against), and crossing it from front to back raises w by m.
/// 3. Groups joined by an edge that only they use (in opposite directions, with equal m)
///    form a patch, in front of which w is constant: it is found once per patch by counting
///    the input triangles a ray from the patch crosses, with sign (a ray that passes through
///    an edge or a vertex is cast again in another direction, drawn from a fixed seed).
/// 4. A group is kept when w > 0 on exactly one of its sides, facing the other side.
/// 5. The result is rounded to doubles. A vertex where it meets itself in several fans (two
///    parts touching at a point, as a mirror-symmetric model's halves often do on their plane)
///    gets one copy per fan, moved by 1e-3 of the shortest edge at the vertex
///    (SeparatePinches()), so that the surface is a 2-manifold. A triangle that rounding
///    made flat (a corner on the opposite edge) is removed and its neighbour split there.
/// 6. Shells (edge-connected) enclosing less than 1e-9 of the largest one's volume are dropped:
///    specks and bubbles where two sheets crossed almost tangentially, of no use to a cut.
/// Vertices are in exact lexicographic (x, y, z) order (then the pinch copies), triangles (lowest
/// vertex first) sorted, so the result depends on the geometry alone. Rounding can make
/// nearly touching parts of it cross again: the caller diagnoses it. Empty when the result has
/// no triangle or no ray found a clear direction.
///
/// Complexity: O(k log k) for the k intersection points and their triangulations, plus
/// O(P x F) bounding-box tests for P patches and F triangles.
std::optional<WindingUnion> UniteByWinding(const TriangleMesh& mesh, const std::vector<int>& faces,
                                           const std::vector<std::pair<int, int>>& crossings);

}  // namespace acdplan::acd::internal
