#pragma once
// An independent validity check of a 3D decomposition; tests, tools and fuzzing call it.

#include "acd/check_decomposition.h"
#include "acd/decomposition3d.h"
#include "acd/prepare_mesh.h"

namespace acdplan::acd {

/// Checks `decomposition` of `input`:
///  - solid ACD: every component mesh is closed, outward-oriented and free of
///    self-intersections; the component volumes sum to the input's (1e-6 relative); interiors
///    are disjoint (sampled points inside one component are inside no other); every component
///    lies inside the input;
///  - surface ACD: every input face belongs to exactly one patch (by area, 1e-9 relative);
///  - every component's concavity, re-measured, is at most tau (+1e-9 relative, + 2e-6 of the
///    component's size: the measure's in-plane tolerance) unless a
///    max_hulls cap merged it; every hull contains its component's vertices, and the stored
///    volume, hull volume and centroid agree with the meshes;
///  - every opening lies in the boundaries of both of its components.
DecompositionCheck CheckDecomposition3d(const PreparedMesh& input,
                                        const Decomposition3d& decomposition);

}  // namespace acdplan::acd
