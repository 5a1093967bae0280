#pragma once

#include <istream>
#include <string>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd {

/// Parses a .poly file: Triangle's format (acd/triangle_poly_reader.h) when IsTrianglePoly()
/// tells it by its header, else Lien's, as follows.
/// Lien's .poly format (data/polygons/acd2d/POLY_FORMAT.txt): a chain count, then
/// per chain "<n> out|in", n lines "x y", and one line with the 1-based vertex order. Several "out"
/// chains may appear; each "in" chain is a hole of the preceding "out" chain. Text after '#' on a
/// line is a comment. Returns the polygons as written (not yet cleaned or validated: see
/// PreparePolygon()).
/// @param source  the file name used in messages.
/// The file is read word by word (a vertex order may span several lines); every message has
/// the form "<source>:<line>: <rule>", e.g. "bird.poly:47: malformed number '-6.64248.788605'".
/// @throws InputError naming `source`, the line (or element) and the rule broken, e.g. a
///         malformed or non-finite number, a wrong count, a truncated file, a vertex order that
///         is not a permutation of 1..n (index out of range, repeated, missing), an "in" chain
///         before any "out" chain, or content after the declared number of chains that is not
///         a chain (or any such content when `warnings` is null).
/// @param warnings  if given, chains beyond the declared count (Lien's simple5.poly declares 1
///        and holds 2) are read as well and one line is added here, naming the file and the
///        line where they start: "simple5.poly:380: 1 chain(s) more than the 1 declared on
///        line 1; read all 2 (wrong chain count in the file)".
std::vector<Polygon2d> ReadPoly(std::istream& in, const std::string& source,
                                std::vector<std::string>* warnings = nullptr);

}  // namespace acdplan::acd
