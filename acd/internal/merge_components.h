#pragma once
// Giving back cuts that were not needed (solid ACD, after Algorithm 1): each cut is chosen for
// the piece in hand, so some leave a piece its neighbour could take back with the union still
// tau-convex, such as a rounding-level sliver beside a cut through a vertex, or a thin shell
// wrapped on its neighbour. Internal: DecomposeSolid() calls it.

#include "acd/decomposition3d.h"
#include "acd/internal/solid_concavity.h"

namespace acdplan::acd::internal {

/// The solid ACD's component for the closed, outward piece `mesh` that `concavity` measured
/// (MeasureSolidConcavity()); its hull is the measure's, or the points' hull when the piece is
/// flat. Either way the hull's vertices are exactly the piece's extreme points.
Component3d SolidComponent(TriangleMesh mesh, const SolidConcavity& concavity, int source);

/// Merges components that share an opening while their union
///  - is one closed shell of genus 0 that stays a valid solid in doubles (the two meshes glued
///    along identical faces, else their UniteByWinding(), where the shared faces, triangulated
///    differently on the two sides, cancel; 10x faster than CGAL's corefinement on hips),
///  - has concavity <= tau (MeasureSolidConcavity(), as the cuts were judged), and
///  - has a hull that adds at most `max_growth` x the two hulls' volume over them;
/// the pair whose hull adds least (relative, ties by index) first, again and again, so a merged
/// component can merge on. The hull test comes first: it needs only the points' hull, and rules
/// out most pairs before any union is formed. A tree leaf of a merged component points to the
/// union, so several leaves can share one component: unlike the surface ACD's patch merge, no
/// leaf leaves the tree, because its internal nodes' cut planes are where ComputeOpenings()
/// finds the openings. Neighbours are the components that `decomposition->openings` join (all
/// it reads of them: ComputeOpenings() with OpeningDetail::kAdjacency suffices). After a merge,
/// components are renumbered by their first leaf in depth-first order, and the openings are
/// recomputed in full; without one, both stay as they were. `max_growth` < 0: no merging.
/// Returns the number of merges.
int MergeComponents(double tau, double max_growth, Decomposition3d* decomposition);

}  // namespace acdplan::acd::internal
