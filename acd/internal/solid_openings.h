#pragma once
// The openings of a solid decomposition: the regions of cuts that two leaves share.

#include "acd/decomposition3d.h"

namespace acdplan::acd::internal {

/// Replaces `decomposition->openings` with the polygons the leaves share across the cut planes
/// of the tree's internal nodes: for each internal node, the faces of the leaves below it that
/// lie in its plane (to within kInPlaneTolerance of their size, as the cut made its cap;
/// outward normal +n on the negative side, -n on the positive side) are
/// intersected pairwise in the plane (an opening split by later cuts is only its shared
/// parts). Each connected shared region is one opening: its outline and holes, exact up to
/// the rounding of their vertices (EvenOddRegions(), where the region is not convex), without
/// regions and holes below 1e-10 x the squared diagonal (rounding specks). Ordered by
/// (component_a, component_b, node), then by position, stable.
/// `kAdjacency`: only which components share an opening, one Opening3d per shared set of parts
/// with its components, normal and area but no polygon (the merge pass needs no more, and the
/// exact regions are most of the cost).
enum class OpeningDetail { kFull, kAdjacency };
void ComputeOpenings(Decomposition3d* decomposition, OpeningDetail detail = OpeningDetail::kFull);

}  // namespace acdplan::acd::internal
