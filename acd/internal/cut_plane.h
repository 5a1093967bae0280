#pragma once
// The cut plane that resolves a piece's most concave feature (dissertation Sec. V.B.3).

#include <vector>

#include "acd/decomposition3d.h"
#include "acd/internal/solid_concavity.h"
#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

/// Candidate cut planes through the witness of `concavity`, best first. Candidates:
///  - the planes of the faces at the witness (extending a notch's walls, as the 2D Resolve
///    extends an edge of the notch);
///  - with `feature_grouping`, the plane best fitting the global cut (FindGlobalCut(),
///    Sec. V.B.2-3), and the plane parallel to it through the witness. After the walls, so
///    that they win ties: on a coarse block the edge-graph cycle crosses big faces on their
///    diagonals (an L-block's would cut it on the diagonal, an opening of area sqrt(2) where
///    its wall extended gives 1, both convex);
///  - the three axis-aligned planes through the witness;
///  - the principal planes of the witness's pocket (the PCA fit of Eq. 5.3 and the two
///    planes across it, which cut a pocket's walls or a handle open, Sec. V.C);
///  - the bisectors of the dihedral angles at the witness's edges.
/// Each is scored without building meshes (the guide's cheap scoring): the vertices of each
/// side plus the points where edges cross the plane are hulled, and a side's concavity is
/// estimated as the largest distance of its vertices to its hull's planes. Ranked by that
/// estimate of the worse side, in bins of tau / 4 above tau (all sides within tau are equal),
/// then by the sum of the two hulls' volumes, then by the order above. Planes that leave a
/// side without a vertex strictly on it are dropped. O(C V log V) for C candidates.
std::vector<Plane3d> RankCutPlanes(const TriangleMesh& mesh, const SolidConcavity& concavity,
                                   double tau, bool feature_grouping = false);

}  // namespace acdplan::acd::internal
