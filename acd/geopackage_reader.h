#pragma once
// Reads the polygons of one layer of an OGC GeoPackage (.gpkg), the SQLite container GIS tools
// (QGIS, GDAL, ArcGIS) write vector data to.

#include <string>
#include <utility>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd {

/// What ReadGeoPackage() read from one layer.
struct GeoPackageLayer {
  std::string name;  ///< The layer (feature table) read.
  /// Its polygons as written (not yet cleaned or validated: see PreparePolygon()), in the order
  /// of the features' ids, each feature's in the order its geometry holds them.
  std::vector<Polygon2d> polygons;
  /// Per polygon: the MultiPolygon it is a member of, counted over the layer from 0, or -1.
  std::vector<int> multipolygons;
  /// Per polygon: its feature, counted from 0 in the order of the features' ids.
  std::vector<int> features;
  /// Per feature: its attributes (every column but the id and the geometry) as the text of a
  /// JSON object in column order; a BLOB column's value is null. Filled only if asked for.
  std::vector<std::string> properties;
  /// The definition (WKT) of the layer's spatial reference system, "" if it has none.
  std::string crs_wkt;
  /// One line per thing read though untidy, or passed over, naming the file and layer.
  std::vector<std::string> warnings;
};

/// Splits "FILE|layername=NAME", the form QGIS shows as a GeoPackage layer's source, into FILE and
/// NAME; a path without it is FILE, with NAME "".
std::pair<std::string, std::string> SplitLayerName(const std::string& path);

/// Reads the polygons of layer `layer` of the GeoPackage `file` (OGC 12-128r18; versions 1.0 -
/// 1.4): a feature table listed in gpkg_contents and gpkg_geometry_columns, its geometries in
/// GeoPackageBinary (the header's envelope skipped, the Well-Known Binary read by ReadWkb()).
/// With `layer` "", the only feature layer whose geometry type can hold polygons; none or several
/// of those are an error listing the layers. A feature whose geometry is NULL or
/// flagged empty holds no polygon. Points and lines are an error naming the first, or with
/// `skip_non_areal` passed over with a note of how many of each type.
/// @param with_properties  fill GeoPackageLayer::properties.
/// @throws InputError naming the file, the layer and the feature (its index and id) and the rule
///         broken: not an SQLite database or no GeoPackage, an unknown layer, a geometry that is
///         no GeoPackageBinary or whose WKB is malformed, a curved or extended geometry type.
GeoPackageLayer ReadGeoPackage(const std::string& file, const std::string& layer,
                               bool skip_non_areal, bool with_properties);

/// ReadGeoPackage() of a file's bytes (`source` names it in messages): for fuzzing and tests.
GeoPackageLayer ReadGeoPackageBytes(const std::string& bytes, const std::string& source,
                                    const std::string& layer, bool skip_non_areal,
                                    bool with_properties);

}  // namespace acdplan::acd
