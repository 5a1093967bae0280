#pragma once
// Feature grouping (dissertation Sec. V.B.2): knots on pocket borders, pocket cuts between
// them, and the global cut, a closed loop on the surface whose best-fit plane resolves a
// piece's most concave feature together with the features it lines up with.

#include <Eigen/Core>
#include <vector>

#include "acd/decomposition3d.h"
#include "acd/internal/solid_concavity.h"
#include "acd/triangle_mesh.h"

namespace acdplan::acd::internal {

/// Douglas-Peucker simplification of the open polyline `chain` (Algorithm 7): the indices of the
/// points kept, ascending, always the first and the last. A point is kept when it lies farther
/// than `delta` [units] from the line through the ends of the stretch it splits (from the
/// point itself when the ends coincide). O(n^2) worst case, O(n log n) typical.
std::vector<int> DouglasPeucker(const std::vector<Eigen::Vector2d>& chain, double delta);

/// The border loops of pocket `pocket` (an id of `face_pocket`: per face, its pocket or -1):
/// each a cycle of vertex indices running with the pocket on its left seen from outside
/// (along its faces' orientation), starting at its smallest vertex. A vertex where the pocket
/// touches itself starts a new loop there. A pocket with no border (a cavity shell) has none.
/// O(F log F).
std::vector<std::vector<int>> PocketBorderLoops(const TriangleMesh& mesh,
                                                const std::vector<int>& face_pocket, int pocket);

/// Knots of one border loop (Sec. V.B.2.b): the loop is drawn in concavity space (Eq. 5.1:
/// arc length along the loop against the vertex's concavity), opened at its least concave
/// vertex (the first one), simplified by DouglasPeucker() with `delta`, and the simplified
/// vertices that are notches there (peaks: the simplified chain turns downward, clockwise in
/// (arc length, concavity)) with concavity above `delta` are the knots. Returned as vertex
/// indices in loop order. `concavity` is per mesh vertex.
std::vector<int> FindKnots(const TriangleMesh& mesh, const std::vector<int>& loop,
                           const std::vector<double>& concavity, double delta);

/// The global cut of a piece and the plane that resolves it.
struct GlobalCut {
  bool found = false;       ///< False: no cut (convex piece, a pocket without a border, ...).
  std::vector<int> knots;   ///< The knots of the witness's pocket (and the fallback rim points).
  std::vector<int> cycle;   ///< The cut: a closed vertex loop (last joins first), root cut first.
  int root_cut_length = 0;  ///< cycle[0 .. root_cut_length) is the pocket cut through the witness.
  bool cup = false;         ///< The witness vertex is not a knot (Fig. 42's cup-shaped pocket).
  double weight = 0.0;      ///< W(cycle) = omega * gamma (Eq. 5.2), see FindGlobalCut().
  Plane3d plane;            ///< The plane best fitting the cycle (Eq. 5.3 by weighted PCA).
};

/// Options for FindGlobalCut(); `{}` is valid.
struct FeatureGroupingOptions {
  double delta_fraction = 0.1;  ///< delta = this x tau: DP and knot threshold; in [0.01, 0.1].
  int max_knots = 12;           ///< The deepest knots of the pocket kept; >= 2.
  int max_cuts = 1;             ///< FindGlobalCuts(): the lightest cycles returned; >= 1.
};

/// The global cut through the witness of `concavity` (a measure of `mesh`, closed and outward):
///  1. knots: FindKnots() on every border loop of the witness's pocket, delta = tau / 10;
///  2. pocket cuts (Sec. V.B.2.c): paths through the pocket (over edges between two of its
///     faces) from the witness vertex to each knot, by Dijkstra with edge cost
///     |e| (c_max + delta - c(e)) / (c_max + delta), c(e) the mean concavity of its ends, so
///     the path follows the deepest valley; the root pocket cut joins two of them, so it always
///     passes the most concave vertex. When the witness is not a knot (a cup-shaped pocket) this
///     is Fig. 42's remedy without rebuilding bridges: the cut is forced through it. A pocket
///     with fewer than two knots gets, per loop, its start and its vertex farthest from it;
///  3. the cycle: the root cut closed from its end back to its start outside its pocket
///     (never re-entering it: Sec. V.B.2.e), by Dijkstra with the same cost over the rest of
///     the surface, so it runs through the valleys of other pockets where there are any and
///     is a geodesic-like shortest path over the hull (Lien's added shortest pocket cuts). This
///     is an exact minimum-cost cycle through each root cut, in place of the tree growth;
///  4. the weight of a cycle (Eq. 5.2): W = omega * gamma with omega = |cycle| / sum of its
///     vertices' concavity (the reciprocal mean concavity) and gamma the accumulated edge
///     curvature, estimated per edge as |e| (1 + beta_e / pi), beta_e its signed exterior
///     dihedral angle (> 0 convex, < 0 reflex): |e| beta_e is the edge's integrated mean
///     curvature (no polynomial fit), and the shift by |e| keeps W positive, so short cuts
///     along reflex creases through deep vertices weigh least. The lightest cycle over the
///     knot pairs is the global cut;
///  5. the plane: the least-squares plane of the cycle's vertices weighted by
///     (concavity + delta) x their half edge lengths (Eq. 5.3's concavity weighting; delta lets
///     the shallow part of the loop set the plane's turn about the deep part).
/// O(K E log V) for K knots and E edges.
GlobalCut FindGlobalCut(const TriangleMesh& mesh, const SolidConcavity& concavity, double tau,
                        const FeatureGroupingOptions& options = {});

/// The `options.max_cuts` lightest cycles of FindGlobalCut()'s step 4 with distinct planes,
/// lightest first (empty where FindGlobalCut() finds none): the next best global cuts, for a
/// caller that scores planes itself.
std::vector<GlobalCut> FindGlobalCuts(const TriangleMesh& mesh, const SolidConcavity& concavity,
                                      double tau, const FeatureGroupingOptions& options = {});

}  // namespace acdplan::acd::internal
