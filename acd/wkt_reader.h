#pragma once

#include <istream>
#include <string>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd {

/// Parses Well-Known Text: one or more POLYGON or MULTIPOLYGON geometries (GEOMETRYCOLLECTION of
/// them too), case-insensitive, EMPTY allowed and skipped (also as a member of a MULTIPOLYGON,
/// and as a hole; a polygon whose exterior ring is EMPTY must have no other ring),
/// each optionally with PostGIS's EWKT prefix "SRID=<integer>;" (skipped). Rings must be closed
/// (the last point repeats the first; it is dropped); z and m values are ignored. Messages read
/// "<source>: <rule> at line L, column C, found '<word>'". Returns the polygons as written (not yet
/// cleaned or validated: see PreparePolygon()).
/// @param source  the file name used in messages.
/// @param multipolygons  if given, receives per returned polygon the index of the MULTIPOLYGON
///        it is a member of (counted in the order of the text), or -1 for a POLYGON.
/// @param features  if given, receives per returned polygon the index of the top-level
///        geometry it belongs to (counted from 0 in the order of the text): a file's features.
/// @throws InputError naming `source`, the line (or element) and the rule broken, e.g. a
///         malformed or non-finite number, a wrong count, a truncated file.
std::vector<Polygon2d> ReadWkt(std::istream& in, const std::string& source,
                               std::vector<int>* multipolygons = nullptr,
                               std::vector<int>* features = nullptr);

}  // namespace acdplan::acd
