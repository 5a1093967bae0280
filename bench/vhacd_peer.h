#pragma once
// V-HACD v4.1 (kmammou/v-hacd, BSD-3-Clause) as the peer of the 3D ACD benchmark. Its single
// header is not part of the repository: the build compiles it in only when configured with
// -DACDPLAN_VHACD_INCLUDE_DIR=<folder holding VHACD.h> (tools/acd3d_bench.md).

#include <vector>

#include "acd/triangle_mesh.h"

namespace acdplan::bench {

/// Whether this build has V-HACD.
bool HaveVhacd();

/// V-HACD's convex hulls of `mesh`, with its default parameters (64 hulls, 400,000 voxels, 1%
/// volume error, depth 10, flood fill, shrink-wrap) but synchronous, on the calling thread
/// (CreateVHACD() and m_asyncACD = false), so that its time compares with our single-threaded
/// decomposition. Hulls are closed, counter-clockwise seen from outside (V-HACD's orientation).
/// @throws std::runtime_error if the build has no V-HACD or its Compute() fails.
std::vector<acd::TriangleMesh> VhacdHulls(const acd::TriangleMesh& mesh);

}  // namespace acdplan::bench
