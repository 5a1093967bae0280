#pragma once
// Solid ACD (dissertation Sec. V.B-C): splits a solid into nearly convex pieces by plane cuts.
// Internal: Decompose3d() dispatches here.

#include "acd/decomposition3d.h"
#include "acd/prepare_mesh.h"

namespace acdplan::acd::internal {

/// Splits every part of `prepared` (prepared.solid() holds) into closed pieces whose concavity
/// is at most `tau` [units]. Fills components, openings (the cut polygons two pieces share),
/// tree, roots and stats (stats.surface = false; time_ms is left to the caller).
/// `max_hulls` > 0 caps the components (Decompose3dOptions::max_hulls): the hierarchy is
/// collapsed back up, the node whose piece's hull adds the least volume over its children's
/// first, so a merged component is an exact piece of the decomposition (its own cut's caps
/// never appear); merged components may exceed tau. `feature_grouping`: CutPlaneRanking also
/// tries the global cut's plane (Decompose3dOptions::feature_grouping). Then adjacent components
/// whose union is tau-convex merge while their hull grows by at most `merge_growth`
/// (MergeComponents(); Decompose3dOptions::merge_growth; < 0: no merging).
Decomposition3d DecomposeSolid(const PreparedMesh& prepared, double tau, int max_hulls = 0,
                               bool feature_grouping = false, double merge_growth = -1);

}  // namespace acdplan::acd::internal
