#pragma once

#include <istream>
#include <string>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd {

/// Parses Lien's .poly format (../shared/data/polygons/acd2d/POLY_FORMAT.txt): a chain count, then per chain "<n> out|in", n lines "x y", and one line with the 1-based vertex order. Several "out" chains may appear; each "in" chain is a hole of the preceding "out" chain. Text after '#' on a line is a comment.
/// Returns the polygons as written (not yet cleaned or validated: see PreparePolygon()).
/// @param source  the file name used in messages.
/// @throws InputError naming `source`, the line (or element) and the rule broken, e.g. a
///         malformed or non-finite number, a wrong count, a truncated file.
std::vector<Polygon2d> ReadPoly(std::istream& in, const std::string& source);

}  // namespace acdplan::acd
