#pragma once
// Reads a polygon file of any supported format.

#include <string>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd {

/// Reads the polygons in `path`, chosen by extension: `.poly` (Lien's format, see
/// acd/poly_reader.h), `.wkt` (acd/wkt_reader.h), `.geojson` / `.json` (acd/geojson_reader.h).
/// Every polygon is passed through PreparePolygon(), so the result is validated and clean.
/// `reference_radii`, if given, receives ReferenceRadius() of each polygon as written in the
/// file, before cleaning drops collinear vertices (which moves the vertex mean): the radius the
/// dissertation's tables relate tau to (19.58 for neuron.poly; 19.54 after cleaning).
/// @throws InputError if the file cannot be read, the extension is unknown, or the content or
///         geometry breaks a rule (the message names the file and the line or element).
std::vector<Polygon2d> ReadPolygons(const std::string& path,
                                    std::vector<double>* reference_radii = nullptr);

}  // namespace acdplan::acd
