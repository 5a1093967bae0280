#pragma once
// Openings between leaf components, read off the hierarchy's cuts and the seams between input
// polygons.

#include <vector>

#include "acd/decomposition2d.h"

namespace acdplan::acd::internal {

/// An outer edge of a piece (from vertex `edge` to the next) that lies on cuts[`cut`] of
/// hierarchy node `node`.
struct CutEdge {
  int edge;
  int node;
  int cut;
};

/// Where two input polygons meet along their rings (edges on one line, running opposite ways,
/// overlapping by more than a point): there their leaf components open into each other though
/// no cut of theirs made the boundary, as where PreparePolygons() cut a pinched polygon apart.
struct Seam {
  Cut2d segment;  ///< The overlap, in the direction of `polygon_a`'s edge.
  int polygon_a, polygon_b;
};

/// The seams between `polygons`, found by a sweep over their ring edges' boxes and exact
/// tests, in order of polygon_a's edges. None for fewer than two polygons.
std::vector<Seam> FindSeams(const std::vector<Polygon2d>& polygons);

/// The maximal segments shared by two leaf components. Every shared boundary lies on a cut or a
/// seam, so for each the leaf edges along it are gathered from both sides (as parameter
/// intervals on it) and intersected. Later cuts ending on a cut split it, which is why one cut
/// can give several openings. Rounding of cut end points is absorbed by a 1e-9 relative
/// tolerance. `cut_edges`: the outer edges of component c that lie on cuts, by edge, are those
/// from first[c] to first[c + 1], as the decomposition made them; the others lie on the input's
/// boundary or on seams (those are found by a sweep over the leaves' edges).
std::vector<Opening2d> FindOpenings(const Decomposition2d& decomposition,
                                    const std::vector<CutEdge>& cut_edges,
                                    const std::vector<int>& first,
                                    const std::vector<Seam>& seams = {});

}  // namespace acdplan::acd::internal
