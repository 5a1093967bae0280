#pragma once
// Reads the polygons of a KML file (Google Earth's format, OGC KML 2.2).

#include <istream>
#include <string>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd {

/// What ReadKml() returns besides the polygons.
struct KmlExtras {
  /// Per polygon: its feature, the Placemark it belongs to, counted from 0 in document order.
  std::vector<int> features;
  /// Per Placemark: its attributes as the text of a JSON object: "name" and "description" where
  /// it has them, then its ExtendedData (Data's value, SchemaData's SimpleData) as strings.
  std::vector<std::string> properties;
  /// One line per thing read though untidy, or passed over, naming the file.
  std::vector<std::string> warnings;
};

/// Parses KML (OGC 07-147r2): the Polygons of every Placemark, in Documents and Folders to any
/// depth, also inside MultiGeometry (whose polygons are not held to be disjoint): the
/// outerBoundaryIs ring and the innerBoundaryIs rings (several LinearRings in one allowed).
/// The root is <kml>, or a Document, Folder or Placemark (a fragment, which Google Earth opens
/// too); elements may carry a namespace prefix (kml:Polygon). Coordinates are "lon,lat[,alt]"
/// tuples separated by white space (spaces beside the commas tolerated); the altitude is ignored,
/// the closing tuple (it repeats the first) dropped, an unclosed ring taken as it is with a
/// warning. Points, LineStrings, LinearRings outside a Polygon, Models and tracks have no area:
/// an error naming the line, or with `skip_non_areal` passed over with a note.
/// Returns the polygons as written (not yet cleaned or validated: see PreparePolygon()).
/// @throws InputError "<source>:<line>: <rule>" for malformed XML, a malformed or non-finite
///         coordinate, a tuple of fewer than 2 or more than 3 numbers, a polygon without an
///         outer boundary but with inner ones.
std::vector<Polygon2d> ReadKml(std::istream& in, const std::string& source, bool skip_non_areal,
                               KmlExtras* extras);

/// The root document of the KMZ archive `path` (a zip file, Google Earth's default for saving):
/// its first entry whose name ends in ".kml" (any case), as OGC 07-147r2 Sec. 16 takes it
/// (usually doc.kml); `entry` receives that name.
/// @throws InputError naming the file: not a readable zip archive, no .kml entry, a damaged or
///         encrypted entry, an entry over 1 GiB uncompressed.
std::string ReadKmzRoot(const std::string& path, std::string* entry);

}  // namespace acdplan::acd
