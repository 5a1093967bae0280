#pragma once
// 3D approximate convex decomposition of polyhedra (dissertation Ch. V, Algorithm 1).

#include <optional>

#include "acd/decomposition3d.h"
#include "acd/prepare_mesh.h"

namespace acdplan::acd {

/// The solid ACD's default merge allowance per unit of relative tolerance: a merge may grow the
/// hulls by kMergeGrowthPerTauRel x tau / ReferenceRadius() (Decompose3dOptions::merge_growth).
/// A tau-convex piece of size R already leaves up to tau of empty depth under its hull, of the
/// order of tau / R of its hull's volume; a merge that adds half that loosens the hulls less
/// than tau itself allows. So a coarse tau, asked for few parts, merges more than a fine one.
/// On the V-HACD meshes: 0.01 at tau_rel 0.02 (as the earlier fixed default); at 0.2, 687
/// parts in all instead of 800 (bunny 6, Table 5's count, instead of 8) for hull volume / mesh
/// volume up to 4% higher (lamp 1.23 -> 1.28); at 0.05, 1,881 instead of 1,968 for at most
/// 0.5% higher.
inline constexpr double kMergeGrowthPerTauRel = 0.5;

/// Options for Decompose3d(); tau must be set (> 0 unless the input is convex).
struct Decompose3dOptions {
  double tau = 0.0;  ///< Concavity tolerated per component [units]; >= 0.
  /// Partition the surface into nearly convex patches (surface ACD) even when the input is a
  /// solid. Open or otherwise non-solid inputs always get the surface ACD.
  bool surface = false;
  /// > 0: after the decomposition, merge the adjacent pair whose merged hull adds the least
  /// volume until at most this many components remain (a cap for physics engines; the merged
  /// components may then exceed tau). 0 = no cap.
  int max_hulls = 0;
  /// Solid ACD: also try the plane of the global cut (feature grouping, Sec. V.B.2: knots,
  /// pocket cuts and the lightest cycle through the most concave vertex) when resolving a
  /// piece; the cheap score still picks among it and the planes through the witness. Off by
  /// default: on the V-HACD meshes it gave about 2 % fewer parts but 2-8 % more hull volume
  /// over the mesh's, and up to 30 % more parts on some (docs/bench/acd3d_solid.md).
  bool feature_grouping = false;
  /// Solid ACD: after the cuts, merge adjacent components whose union is still tau-convex (one
  /// genus-0 shell) while the union's hull adds at most this fraction of the two hulls' volume,
  /// the cheapest pair first. Each cut is chosen for the piece in hand, so some leave a piece a
  /// neighbour can take back: a rounding-level sliver beside a cut through a vertex, a thin
  /// shell wrapped on its neighbour. Unset: kMergeGrowthPerTauRel x tau / ReferenceRadius() of
  /// the prepared mesh (0.01 at tau_rel 0.02, 0.1 at 0.2). A large value merges every
  /// tau-convex pair it can (fewest parts); < 0 turns merging off. Not with the surface ACD.
  std::optional<double> merge_growth = std::nullopt;
};

/// Splits every part of `prepared` into components whose concavity is at most `options.tau`,
/// resolving the most concave feature first (Algorithm 1): solid ACD (Sec. V.B-C) when
/// `prepared.solid()` and not `options.surface`, else surface ACD. The same input and options
/// give the same output, bit for bit; so does the same mesh numbered otherwise (each part is
/// decomposed in its CanonicallyNumbered() form).
/// @throws InputError if an option is out of range.
Decomposition3d Decompose3d(const PreparedMesh& prepared, const Decompose3dOptions& options);

}  // namespace acdplan::acd
