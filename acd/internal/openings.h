#pragma once
// Openings between leaf components, read off the hierarchy's cuts.

#include <vector>

#include "acd/decomposition2d.h"

namespace acdplan::acd::internal {

/// The maximal segments shared by two leaf components. Every shared boundary lies on a cut, so
/// for each cut the leaf edges along it are gathered from both sides (as parameter intervals on
/// the cut) and intersected. Later cuts ending on a cut split it, which is why one cut can give
/// several openings. Rounding of cut end points is absorbed by a 1e-9 relative tolerance.
std::vector<Opening2d> FindOpenings(const Decomposition2d& decomposition);

}  // namespace acdplan::acd::internal
