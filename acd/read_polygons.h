#pragma once
// Reads a polygon file of any supported format.

#include <string>
#include <vector>

#include "acd/polygon2d.h"

namespace acdplan::acd {

/// Options for ReadPolygons(); `{}` is valid (strict: invalid geometry is an error).
struct ReadPolygonsOptions {
  /// Make invalid polygons valid with RepairPolygon() (acd/repair_polygon.h) instead of
  /// rejecting them.
  bool repair = false;
  /// If given, receives one line per warning of the reader (e.g. a .poly file with more chains
  /// than it declares) and per repair change, each naming the file.
  std::vector<std::string>* notes = nullptr;
  /// Hold the members of each MULTIPOLYGON (GeoJSON MultiPolygon) to OGC's rule that their
  /// interiors be disjoint (they may touch), as a region to decompose must: overlapping members
  /// are an error naming the first pair; with `repair`, each set of overlapping members is
  /// rebuilt together by the even-odd rule (area covered an even number of times is left out,
  /// as ST_MakeValid's default does). Off for obstacles, which may overlap.
  bool disjoint_members = false;
  /// If given, receives per returned polygon the index of the file's polygon it comes from, as
  /// the messages count them ("polygon k"): the pieces of one polygon share it, and a set of
  /// overlapping MULTIPOLYGON members rebuilt together takes its first member's. This is how a
  /// result maps back to the file's polygons (`features`, below, to its features).
  std::vector<int>* sources = nullptr;
  /// If given, receives per returned polygon the feature of the file it comes from, the unit a
  /// GIS tool keeps attributes for: a shapefile's record (its FID, counted from 0), a GeoJSON
  /// FeatureCollection's feature, a GeoPackage layer's row (counted from 0 in the order of the
  /// feature ids), a KML Placemark, the k-th geometry of a WKT file, the k-th polygon of a .poly
  /// file. The members of a MULTIPOLYGON share their feature, as the pieces of one polygon do.
  std::vector<int>* features = nullptr;
  /// If given, receives per feature of the file (as `features` numbers them) its attributes as
  /// the text of a JSON object, to carry into output: a GeoJSON Feature's "properties" ("{}" if
  /// null), a shapefile record's row of the .dbf beside the .shp (acd/dbf_reader.h; its text
  /// encoding from the .cpg beside them if there is one), a GeoPackage row's columns but the id and
  /// the geometry (acd/geopackage_reader.h), a KML Placemark's name, description and
  /// ExtendedData (acd/kml_reader.h). Empty for formats without attributes
  /// (.poly, WKT, a GeoJSON geometry) and for a shapefile without a .dbf (with a note). A .dbf
  /// that breaks its format, or has no row for a record with a shape, is an error.
  std::vector<std::string>* feature_properties = nullptr;
  /// GeoJSON, GeoPackage, KML: skip points and lines (geometries without area) with a note instead
  /// of refusing the file, as a layer to decompose may hold a few among its polygons. Off for
  /// obstacles, where a line may stand for a wall.
  bool skip_non_areal = false;
};

/// The extensions ReadPolygons() reads, for messages.
inline constexpr char kPolygonFileExtensions[] =
    ".poly, .wkt, .geojson, .json, .shp, .gpkg, .kml or .kmz";

/// Whether ReadPolygons() reads `path`, by its extension (any case).
bool IsPolygonFile(const std::string& path);

/// Reads the polygons in `path`, chosen by extension: `.poly` (Lien's format, see
/// acd/poly_reader.h), `.wkt` (acd/wkt_reader.h), `.geojson` / `.json` (acd/geojson_reader.h),
/// `.shp` (an ESRI shapefile's polygons, acd/shapefile_reader.h), `.gpkg` (a GeoPackage layer's,
/// acd/geopackage_reader.h: `FILE.gpkg|layername=NAME`, as QGIS names a layer's source, reads
/// layer NAME; a file with one layer of polygons needs no name), `.kml` (its Placemarks' polygons,
/// acd/kml_reader.h) or `.kmz` (the KML inside; messages name it as FILE.kmz/doc.kml).
/// Every polygon is passed through PreparePolygons(), so the result is validated and clean; a
/// polygon whose rings touch at points may become several (in file order, so polygon k of the
/// result is not always polygon k of the file).
/// `reference_radii`, if given, receives ReferenceRadius() of each polygon as written in the
/// file, before cleaning drops collinear vertices (which moves the vertex mean): the radius the
/// dissertation's tables relate tau to (19.58 for neuron.poly; 19.54 after cleaning), one per
/// returned polygon (the pieces of one file polygon share its radius).
/// @throws InputError if the file cannot be read, the extension is unknown, or the content or
///         geometry breaks a rule (the message names the file and the line or element).
std::vector<Polygon2d> ReadPolygons(const std::string& path,
                                    std::vector<double>* reference_radii = nullptr,
                                    const ReadPolygonsOptions& options = {});

}  // namespace acdplan::acd
