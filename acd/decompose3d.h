#pragma once
// 3D approximate convex decomposition of polyhedra (dissertation Ch. V, Algorithm 1).

#include "acd/decomposition3d.h"
#include "acd/prepare_mesh.h"

namespace acdplan::acd {

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
  /// shell wrapped on its neighbour. The default merges where the hulls barely grow, so the
  /// hulls stay as tight; a large value merges every tau-convex pair it can (fewest parts);
  /// < 0 turns merging off. Not with the surface ACD.
  double merge_growth = 0.01;
};

/// Splits every part of `prepared` into components whose concavity is at most `options.tau`,
/// resolving the most concave feature first (Algorithm 1): solid ACD (Sec. V.B-C) when
/// `prepared.solid()` and not `options.surface`, else surface ACD. The same input and options
/// give the same output, bit for bit; so does the same mesh numbered otherwise (each part is
/// decomposed in its CanonicallyNumbered() form).
/// @throws InputError if an option is out of range.
Decomposition3d Decompose3d(const PreparedMesh& prepared, const Decompose3dOptions& options);

}  // namespace acdplan::acd
