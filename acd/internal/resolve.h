#pragma once
// Resolve (dissertation Algorithm 5): the cut(s) that remove the most concave feature.

#include <array>
#include <utility>
#include <vector>

#include "acd/concavity.h"
#include "acd/decomposition2d.h"
#include "acd/internal/inherited_chain.h"
#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// Scoring of candidate cuts (Ch. IV.D.1).
struct ResolveOptions {
  double score_concavity = 0.1;  ///< s_c.
  double score_distance = 1.0;   ///< s_d.
  /// The length the score divides concavity by, so that ranking cuts is scale invariant.
  double concavity_unit = 1.0;
  bool steiner_cuts = true;  ///< Allow a cut to end on an edge (a new vertex).
  double tau = 0.0;          ///< Notches deeper than tau still need a cut of their own.
  /// Score factor for a diagonal that also resolves its other end, a notch deeper than tau: such
  /// a cut does the work of two, so it counts double (fewer pieces, as in Chazelle's X-patterns;
  /// at tau = 0 it takes nazca_monkey from 474 to 387 pieces).
  double double_resolve_bonus = 2.0;
  /// Whether such a diagonal outranks every cut that resolves one notch, whatever the scores.
  /// Right when every notch needs a cut of its own, i.e. when convex pieces are asked (tau = 0):
  /// each diagonal resolving two notches then saves a piece, and optimal convex partitions are
  /// made of them (Chazelle's X-patterns); the score orders them among themselves. At tau > 0 a
  /// notch deeper than tau may still come within tau once other cuts change its pocket, so
  /// there the bonus only weighs it. Texas at tau = 0: 51 -> 45 pieces (CGAL's optimum: 38).
  bool double_resolves_first = false;
};

/// Where the outer edges of a piece lie (edge i runs from vertex i to the next): edges 0 ...
/// outer_count - 1 on the resolved polygon's outer edges first_outer_edge, first_outer_edge + 1,
/// ... (cyclically; the first and the last perhaps in part), those `cuts` lists on cuts, the
/// others on holes.
struct PieceEdges {
  int first_outer_edge = 0;
  int outer_count = 0;
  std::vector<std::pair<int, int>> cuts;  ///< (edge, index into Resolution::cuts), by edge.
};

/// Two pieces and the cut(s) between them.
struct Resolution {
  std::array<Polygon2d, 2> pieces;
  /// Per piece, the outer vertices it copies from the resolved polygon's outer ring.
  std::array<InheritedChain, 2> inherited;
  /// Per piece, per hole, the resolved polygon's hole it copies (increasing).
  std::array<std::vector<int>, 2> hole_origins;
  /// Per piece, where its outer edges lie.
  std::array<PieceEdges, 2> edges;
  std::vector<Cut2d> cuts;
  Point2d witness;  ///< The feature resolved.
};

/// Resolves the witness of `concavity` in `polygon` (prepared orientation).
///  - An outer notch r gets the cut r -> x of highest score
///    f(r, x) = (1 + s_c concavity(x)) / (s_d dist(r, x)) (times `double_resolve_bonus` when
///    the cut resolves x as well) among the boundary points x that
///    resolve r (x in the cone of the extensions of r's two edges) and see r; x is a vertex or,
///    if `steiner_cuts`, the point where r's angle bisector first meets an edge.
///  - A hole whose antipodes p and cw(p) lie closer to another hole than to the outer boundary
///    is cut along a path: p and cw(p) each link to the closest visible point of another ring
///    (Eqn. 4.2's link), a hole reached is left at its vertex farthest from where it was entered
///    (its cw, Fig. 19) and linked on, until both ends reach the outer boundary; every hole on
///    the path is resolved by the one split. Should that walk shut itself in (among many holes),
///    each end walks again only ever ahead, away from the other.
///  - Otherwise a hole is connected at p to the closest visible outer vertex x (Algorithm 5)
///    and, so that the piece splits in two, at cw(p) by the best-scoring cut to the outer
///    boundary (the cut the next iteration would make at cw(p), the pocket's deepest point,
///    Fig. 19).
/// Both pieces are simple, counter-clockwise, with the remaining holes distributed.
/// Returns false only when no valid cut exists for any notch or hole (never for valid input).
/// The pieces are built in the storage `resolution` holds.
bool Resolve(const Polygon2d& polygon, const Concavity2d& concavity, const ResolveOptions& options,
             Resolution* resolution);

}  // namespace acdplan::acd::internal
