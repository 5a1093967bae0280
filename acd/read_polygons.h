#pragma once
// Reads a polygon file of any supported format.

#include <string>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd {

/// Reads the polygons in `path`, chosen by extension: `.poly` (Lien's format, see
/// acd/poly_reader.h), `.wkt` (acd/wkt_reader.h), `.geojson` / `.json` (acd/geojson_reader.h).
/// Every polygon is passed through PreparePolygon(), so the result is validated and clean.
/// @throws InputError if the file cannot be read, the extension is unknown, or the content or
///         geometry breaks a rule (the message names the file and the line or element).
std::vector<Polygon2d> ReadPolygons(const std::string& path);

}  // namespace acdplan::acd
