#pragma once
// The openings of a solid decomposition: the cut polygons two leaves share.

#include "acd/decomposition3d.h"

namespace acdplan::acd::internal {

/// Replaces `decomposition->openings` with the polygons the leaves share across the cut planes
/// of the tree's internal nodes: for each internal node, the faces of the leaves below it that
/// lie in its plane (outward normal +n on the negative side, -n on the positive side) are
/// intersected pairwise in the plane. `area` is the exact area of the shared part (an opening
/// split by later cuts is only its shared parts); `polygon` is the shared part's outline when
/// it is one convex piece, else the convex outline of its parts (exact whenever the section is
/// convex). Ordered by (component_a, component_b, node).
void ComputeOpenings(Decomposition3d* decomposition);

}  // namespace acdplan::acd::internal
