#pragma once
// The openings of a solid decomposition: the cut polygons two leaves share.

#include "acd/decomposition3d.h"

namespace acdplan::acd::internal {

/// Replaces `decomposition->openings` with the polygons the leaves share across the cut planes
/// of the tree's internal nodes: for each internal node, the faces of the leaves below it that
/// lie in its plane (outward normal +n on the negative side, -n on the positive side) are
/// intersected pairwise in the plane (an opening split by later cuts is only its shared
/// parts). Each connected shared region is one opening: its outline and holes, exact up to
/// the rounding of their vertices (EvenOddRegions(), where the region is not convex), without
/// regions and holes below 1e-10 x the squared diagonal (rounding specks). Ordered by
/// (component_a, component_b, node), then by position, stable.
void ComputeOpenings(Decomposition3d* decomposition);

}  // namespace acdplan::acd::internal
