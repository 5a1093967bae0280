#pragma once
// Surface ACD (dissertation Sec. V.B with the rules for open surfaces): partitions a surface
// into nearly convex patches. Internal: Decompose3d() dispatches here.

#include "acd/decomposition3d.h"
#include "acd/prepare_mesh.h"

namespace acdplan::acd::internal {

/// Partitions every part of `prepared` (open or closed surfaces) into patches whose concavity
/// is at most `tau` [units] (Algorithm 1 on patches: measure, cut along the resolving feature,
/// recurse; then adjacent patches whose union is within tau are merged, least concave union
/// first, so a cut's two sides that are nearly convex together become one patch again). Fills
/// components (patch meshes, their hulls, area centroids, volume 0), openings (the polylines two
/// patches share), tree, roots and stats (stats.surface = true; time_ms is left to the caller).
Decomposition3d DecomposeSurface(const PreparedMesh& prepared, double tau);

}  // namespace acdplan::acd::internal
