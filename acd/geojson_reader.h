#pragma once

#include <istream>
#include <string>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd {

/// What ReadGeoJson() does with geometries that have no area.
struct GeoJsonSkipOptions {
  /// Skip Point, MultiPoint, LineString and MultiLineString geometries (a layer of buildings may
  /// hold entrances as points) instead of refusing them; one note says how many of each type and
  /// where the first is, naming the source.
  bool non_areal = false;
  std::vector<std::string>* warnings = nullptr;  ///< Receives that note, if any is skipped.
};

/// Parses GeoJSON (RFC 7946): a Polygon, MultiPolygon, Feature or FeatureCollection (features of
/// other geometry types are an error naming the feature index, unless `skip` skips them), or a
/// GeometryCollection of those.
/// Rings must be closed (the last position repeats the first; it is dropped); a third or
/// further coordinate is ignored; a Feature with a null geometry holds no polygon, nor does a
/// Polygon with empty "coordinates" or an empty polygon in a MultiPolygon's. Messages
/// read "<source>: <element path>: <rule>", e.g.
/// "shape.geojson: features[2].geometry: unsupported type 'LineString' (...)".
/// Returns the polygons as written (not yet cleaned or validated: see PreparePolygon()).
/// @param source  the file name used in messages.
/// @param multipolygons  if given, receives per returned polygon the index of the MultiPolygon
///        it is a member of (counted in document order), or -1 for a Polygon.
/// @param features  if given, receives per returned polygon the feature it belongs to: its index
///        in the root FeatureCollection's "features" (or the root GeometryCollection's
///        "geometries"), 0 when the root is a single Feature or geometry.
/// @param properties  if given, receives per Feature (in the order `features` counts them) its
///        "properties" as JSON object text, members in the file's order ("{}" where they are
///        null or missing); nothing when
///        the root holds no Feature (a geometry, a GeometryCollection).
/// @throws InputError naming `source`, the line (or element) and the rule broken, e.g. a
///         malformed or non-finite number, a wrong count, a truncated file.
std::vector<Polygon2d> ReadGeoJson(std::istream& in, const std::string& source,
                                   std::vector<int>* multipolygons = nullptr,
                                   std::vector<int>* features = nullptr,
                                   std::vector<std::string>* properties = nullptr,
                                   const GeoJsonSkipOptions& skip = {});

}  // namespace acdplan::acd
