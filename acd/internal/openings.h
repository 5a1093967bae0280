#pragma once
// Openings between leaf components, read off the hierarchy's cuts.

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

/// The maximal segments shared by two leaf components. Every shared boundary lies on a cut, so
/// for each cut the leaf edges along it are gathered from both sides (as parameter intervals on
/// the cut) and intersected. Later cuts ending on a cut split it, which is why one cut can give
/// several openings. Rounding of cut end points is absorbed by a 1e-9 relative tolerance.
/// `cut_edges`: the outer edges of component c that lie on cuts, by edge, are those from
/// first[c] to first[c + 1], as the decomposition made them; the others lie on the input's
/// boundary.
std::vector<Opening2d> FindOpenings(const Decomposition2d& decomposition,
                                    const std::vector<CutEdge>& cut_edges,
                                    const std::vector<int>& first);

}  // namespace acdplan::acd::internal
