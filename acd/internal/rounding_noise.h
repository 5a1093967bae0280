#pragma once
// The noise band of rounded coordinates that the 2D code's exact predicates allow for.
// Internal: include only from .cpp files of the acd library.

#include "acd/polygon2d.h"

namespace acdplan::acd::internal {

/// Rounding noise of a coordinate computed from others (a cut's end on an edge, a notch's
/// turn), relative to the coordinates' magnitude: a few hundred ulps. IsNotch()'s noise floor,
/// and the clearance Resolve() keeps a constructed cut end from other edges and vertices.
constexpr double kRoundingNoise = 1e-13;

/// The largest absolute coordinate of `p`: the magnitude that rounding noise scales with.
inline double MaxAbs(const Point2d& p) { return p.cwiseAbs().maxCoeff(); }

}  // namespace acdplan::acd::internal
