#pragma once
// An independent validity check of a decomposition; tests and tools call it.

#include <string>
#include <vector>

#include "acd/decomposition2d.h"
#include "acd/polygon2d.h"

namespace acdplan::acd {

/// What CheckDecomposition() found; ok() when `problems` is empty.
struct DecompositionCheck {
  std::vector<std::string> problems;  ///< One line each, naming the component and the rule.
  bool ok() const { return problems.empty(); }
};

/// Checks `decomposition` of `input` (the prepared polygons it was computed from):
///  - every component is a simple counter-clockwise polygon with >= 3 vertices (holes simple,
///    clockwise, inside), and its hull, centroid and area agree with its polygon;
///  - the union of the components equals the input and their interiors are disjoint (area sum
///    equals the input's area to 1e-9 relative, every component lies inside its input polygon,
///    no two components overlap; tolerances absorb the rounding of cut end points on edges: the
///    slivers they make on input edges, and a thousand ulps of each such point times the
///    lengths of the component edges at it);
///  - every component's concavity, re-measured with the decomposition's measure, is at most tau
///    (+1e-9 relative) unless min_convexity was used (then area / hull area >= min_convexity
///    or the piece is convex); with tau == 0 every component is convex (no IsNotch() vertex);
///  - every opening lies on the boundaries of both of its components.
DecompositionCheck CheckDecomposition(const std::vector<Polygon2d>& input,
                                      const Decomposition2d& decomposition);

}  // namespace acdplan::acd
