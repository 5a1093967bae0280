#pragma once
// Orientation and nesting of closed shells: the exact tests that decide which way a shell
// faces and which shell is a cavity of which.

#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

/// The sign (-1, 0, +1) of the volume enclosed by the triangles `faces` of `mesh`, a closed,
/// consistently oriented shell: +1 when they face outward. Exact: the sum of the tetrahedra's
/// determinants in doubles decides when it exceeds its rounding-error bound; otherwise the sum
/// is redone in exact rationals. O(n).
int VolumeSign(const TriangleMesh& mesh, const std::vector<int>& faces);
/// The same for all the faces of `mesh` (a solid: its shells, cavities facing inward).
int VolumeSign(const TriangleMesh& mesh);

/// For closed shells `shells` (triangle lists of `mesh`), each free of self-intersections and
/// no two crossing: enclosing[i] lists, ascending, the shells j whose bounded side holds shell
/// i, tested at a vertex of i that is not on j by the parity of j's faces a ray from it
/// crosses (exact predicates; upward, and in random directions, seeded, where that ray meets
/// an edge or a vertex). Shells that share all their vertices are never nested. O(S^2)
/// bounding-box tests, and per shell j tested, one box intersection of its faces with the
/// upward rays of all its tests.
std::vector<std::vector<int>> EnclosingShells(const TriangleMesh& mesh,
                                              const std::vector<std::vector<int>>& shells);

}  // namespace acdplan::acd::internal
