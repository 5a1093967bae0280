#pragma once
// Validation and cleaning of raw polygons before decomposition.

#include <string>

#include "acd/polygon2d.h"

namespace acdplan::acd {

/// Validates `raw` and returns its cleaned form (see Polygon2d's invariants).
///
/// Cleans what is valid but untidy: re-orients rings (outer counter-clockwise, holes
/// clockwise), drops consecutive duplicate vertices (and a repeated closing vertex), drops
/// collinear vertices and zero-width spikes.
///
/// Checks, in this order: every coordinate finite; cleaning; each ring keeps at least 3
/// vertices and a non-zero area; each ring is simple (a vertex on a non-adjacent edge, or two
/// vertices at one point, count as self-intersection); each hole strictly inside the outer
/// ring (not crossing or touching it); holes pairwise disjoint (no crossing, touching or
/// nesting).
///
/// Messages name rings as "outer ring" or "hole k" (k the 0-based index in `raw.holes`) and
/// vertices by their 0-based index in the ring as given in `raw` (for a .poly file: after its
/// vertex order is applied), e.g. "monkey.poly: polygon 0: outer ring is not simple: edges
/// (3,4) and (7,8) intersect at (0.5, 1.25)". Where several pairs intersect, the pair that
/// comes first in the cleaned ring's order is named.
///
/// O(n log n) for n vertices in all when the input is valid (CGAL's surface sweep, a
/// Bentley-Ottmann variant, stopping at the first intersection) plus O(h * m) point-in-ring
/// tests for h holes of m vertices; naming the offending edges after a failure can take
/// O(n^2) in the worst case.
///
/// @param where  names the element in messages, e.g. "monkey.poly: polygon 0".
/// @throws InputError, one message naming `where`, the ring and the rule, when a coordinate is
///         NaN or infinite; a ring has fewer than 3 distinct, non-collinear vertices or zero
///         area; a ring is self-intersecting (the message names the two edges by vertex index
///         and the point); a hole is outside its outer ring, crosses it or touches it; two
///         holes overlap, touch or nest. All predicates are exact (CGAL's Epick kernel).
Polygon2d PreparePolygon(const Polygon2d& raw, const std::string& where);

}  // namespace acdplan::acd
