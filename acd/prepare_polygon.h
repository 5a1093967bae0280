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
/// @param where  names the element in messages, e.g. "monkey.poly: polygon 1".
/// @throws InputError, one message naming `where`, the ring and the rule, when a coordinate is
///         NaN or infinite; a ring has fewer than 3 distinct, non-collinear vertices; a ring is
///         self-intersecting (the message names the two edges by vertex index and the point);
///         a hole is outside its outer ring, crosses it or touches it; two holes overlap or
///         touch. All predicates are exact (CGAL's Epick kernel).
Polygon2d PreparePolygon(const Polygon2d& raw, const std::string& where);

}  // namespace acdplan::acd
