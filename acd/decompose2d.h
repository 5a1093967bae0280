#pragma once
// 2D approximate convex decomposition (dissertation Algorithm 1 and Algorithm 9).

#include <vector>

#include "acd/concavity_measure.h"
#include "acd/decomposition2d.h"
#include "acd/polygon2d.h"

namespace acdplan::acd {

/// Options for Decompose2d(); `{}` is valid (exact convex decomposition with SP-concavity).
struct Decompose2dOptions {
  double tau = 0.0;  ///< Concavity tolerated per component [units]; >= 0; 0 = convex pieces.
  ConcavityMeasure measure = ConcavityMeasure::kShortestPath;  ///< Ch. IV.A.
  HoleDiameter hole_diameter = HoleDiameter::kAuto;            ///< Ch. IV.A.2.b.
  /// In (0, 1]: shape decomposition (Algorithm 9): a piece is accepted once
  /// area / hull area >= min_convexity, instead of the concavity test. 0 = off.
  double min_convexity = 0.0;
  /// s_c of the diagonal score (Ch. IV.D.1); >= 0. The score reads concavity in hundredths of
  /// the input's ReferenceRadius(), so the chosen cuts do not depend on the input's units (on
  /// nazca_monkey, radius 81.7, that unit is 0.82, close to the raw units s_c = 0.1 was tuned in).
  double score_concavity = 0.1;
  double score_distance = 1.0;  ///< s_d of the diagonal score; > 0.
  bool steiner_cuts = true;     ///< Let a cut end on an edge (a new vertex) when it scores best.
  /// Keep every node's piece in the hierarchy (HierarchyNode2d::piece). Without it a root keeps
  /// its input and the other nodes keep none (a leaf's piece is its component's polygon): the
  /// pieces of all levels add up to the input's size times the tree's depth, and their first
  /// writes were a quarter of the cache misses of a decomposition started with cold caches
  /// (nazca_monkey, callgrind's cache model).
  bool keep_pieces = false;
};

/// Splits `polygon` (prepared by PreparePolygon()) into components whose concavity is at most
/// `options.tau`, resolving the most concave feature first (Algorithm 1; Resolve is Algorithm 5
/// with the scored diagonals of Ch. IV.D.1; holes are resolved first, Eqn. 4.2). Roughly
/// O(n r) time for n vertices and r notches (Theorem C.5).
/// @throws InputError if an option is out of range.
Decomposition2d Decompose2d(const Polygon2d& polygon, const Decompose2dOptions& options = {});

/// Decomposes each polygon and concatenates the results (components keep their `source`). Where
/// two polygons meet along their boundaries (as the pieces PreparePolygons() cuts a pinched
/// polygon into), the openings join their components too.
Decomposition2d Decompose2d(const std::vector<Polygon2d>& polygons,
                            const Decompose2dOptions& options = {});

}  // namespace acdplan::acd
