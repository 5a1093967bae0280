#pragma once
// The topology a plane cut would leave a solid with, predicted in doubles before the exact cut
// is made: a handle (Sec. V.C) is cut by the best-ranked plane that lowers the genus, and most
// ranked planes do not (measured: mite at tau_rel 0.05 made 575 exact cuts that left a handle
// whole, 61% of its cuts).

#include <optional>

#include "acd/decomposition3d.h"
#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

/// What cutting a solid by a plane leaves.
struct CutTopology {
  int pieces = 0;  ///< Connected solids, both sides together.
  int genus = 0;   ///< Their total genus.
};

/// Predicts what the exact cut (SplitByPlane, ConnectedSolids, Topology) of `mesh`, a closed
/// surface of one shell and genus `genus`, by `plane` leaves. Computed in doubles, with a vertex
/// that may lie in the plane (its height within rounding of 0) counted above it; nullopt where
/// that could change the topology: where such vertices (alone, or joined by edges) form a saddle
/// (the section pinches there) or a face. The Euler characteristic of a solid of one shell of genus
/// g is 1 - g, and it adds over the two sides less the section's, which is (regions - holes), so
///   total genus after = pieces - (1 - genus) - regions + holes.
/// The section's loops are nested by ray parity in the plane (a loop inside an even number of
/// others bounds a region, inside an odd number a hole of the region around it); the pieces are
/// the sides' vertex components, joined where their loops bound one region. A cut cannot make a
/// cavity, so each piece has one shell. O(F log F + loops x section edges).
std::optional<CutTopology> PredictCutTopology(const TriangleMesh& mesh, int genus,
                                              const Plane3d& plane);

}  // namespace acdplan::acd::internal
