#pragma once

#include <istream>
#include <string>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd {

/// Parses the main file (.shp) of an ESRI Shapefile (ESRI Shapefile Technical Description,
/// 1998): shape types Polygon (5), PolygonZ (15) and PolygonM (25), whose z and m values are
/// ignored; the .shx index is not needed (the .dbf attributes beside it: ReadDbf()). A null shape
/// (a record without geometry) or a record without parts holds no polygon. The format gives a
/// record's rings no structure beyond their orientation, so they are grouped by how they nest,
/// as GIS readers do (internal::PolygonsByNesting(): outer rings, holes, islands in holes);
/// a record whose rings form several polygons is a MultiPolygon. A ring's closing point (the
/// spec repeats the first) is dropped; a ring written without one is taken as it is, with a
/// warning. Messages read "<source>: record R[, part P][, point K]: <rule>" (R counted from 1
/// as the format numbers records, P and K from 0) or name the byte offset of a damaged header.
/// Returns the polygons as written (not yet cleaned or validated: see PreparePolygon()).
/// @param source  the file name used in messages.
/// @param multipolygons  if given, receives per returned polygon the number R of the record it
///        comes from when that record holds several polygons (a MultiPolygon), else -1.
/// @param warnings  if given, receives a line for what was read though untidy: the first ring
///        written without its closing point (with how many more), bytes past the declared length.
/// @param features  if given, receives per returned polygon its record's index counted from 0
///        (record R is feature R - 1, OGR's FID: the row of the .dbf beside it).
/// @throws InputError naming `source` and the record or byte offset, e.g. a file that is no
///         shapefile, a shape type other than polygons, a truncated record, inconsistent part
///         offsets, a non-finite coordinate.
std::vector<Polygon2d> ReadShapefile(std::istream& in, const std::string& source,
                                     std::vector<int>* multipolygons = nullptr,
                                     std::vector<std::string>* warnings = nullptr,
                                     std::vector<int>* features = nullptr);

}  // namespace acdplan::acd
