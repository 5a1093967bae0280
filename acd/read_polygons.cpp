#include "acd/read_polygons.h"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <sstream>
#include <utility>

#include "acd/dbf_reader.h"
#include "acd/geojson_reader.h"
#include "acd/geopackage_reader.h"
#include "acd/internal/box_sweep.h"
#include "acd/internal/disjoint_sets.h"
#include "acd/internal/even_odd_regions.h"
#include "acd/internal/text_parsing.h"
#include "acd/kml_reader.h"
#include "acd/poly_reader.h"
#include "acd/prepare_polygon.h"
#include "acd/repair_polygon.h"
#include "acd/shapefile_reader.h"
#include "acd/wkt_reader.h"
#include "base/file_io.h"
#include "base/input_error.h"

namespace acdplan::acd {
namespace {

std::vector<Ring2d> RingsOf(const Polygon2d& polygon) {
  std::vector<Ring2d> rings = {polygon.outer};
  rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
  return rings;
}

// The pairs (i, j), i < j, of valid `polygons` of one group (groups[i] == groups[j] >= 0)
// whose interiors intersect, in lexicographic order; `first_only`: the first pair only. Pairs
// whose bounding boxes overlap (internal::ForEachSelfOverlap()) are decided exactly: the two
// polygons' common area (internal::EvenOddRegions() with one layer each) is empty or not.
std::vector<std::pair<size_t, size_t>> OverlappingPairs(const std::vector<Polygon2d>& polygons,
                                                        const std::vector<int>& groups,
                                                        bool first_only) {
  std::vector<internal::IdBox> boxes;  // Of the members of MULTIPOLYGONs only.
  for (size_t k = 0; k < polygons.size(); ++k) {
    if (groups[k] < 0) continue;
    boxes.push_back(internal::RingBox(polygons[k].outer, static_cast<int>(k)));
  }
  std::vector<std::pair<size_t, size_t>> candidates;
  internal::ForEachSelfOverlap(boxes, [&](int a, int b) {
    if (groups[a] == groups[b]) {
      candidates.emplace_back(static_cast<size_t>(std::min(a, b)),
                              static_cast<size_t>(std::max(a, b)));
    }
  });
  std::sort(candidates.begin(), candidates.end());
  std::vector<std::pair<size_t, size_t>> overlapping;
  for (const auto& [i, j] : candidates) {
    if (internal::EvenOddRegions({RingsOf(polygons[i]), RingsOf(polygons[j])}).empty()) continue;
    overlapping.emplace_back(i, j);
    if (first_only) break;
  }
  return overlapping;
}

// "0 and 1", "0, 1 and 4".
std::string ListOf(const std::vector<int>& numbers) {
  std::string text;
  for (size_t k = 0; k < numbers.size(); ++k) {
    if (k > 0) text += k + 1 == numbers.size() ? " and " : ", ";
    text += std::to_string(numbers[k]);
  }
  return text;
}

// Replaces each set of `polygons` joined by `overlapping` pairs with their even-odd region, where
// the set's first member was, and says so in `notes` (if given). `sources`: per polygon, its
// polygon in the file (for the messages); they and `radii` follow the polygons (a set's pieces
// take its first member's).
void RebuildOverlapping(const std::string& path,
                        const std::vector<std::pair<size_t, size_t>>& overlapping,
                        std::vector<int>* sources, std::vector<Polygon2d>* polygons,
                        std::vector<double>* radii, std::vector<std::string>* notes) {
  const int count = static_cast<int>(polygons->size());
  internal::DisjointSets sets(count);
  for (const auto& [i, j] : overlapping) sets.Unite(static_cast<int>(i), static_cast<int>(j));
  std::vector<std::vector<int>> members(static_cast<size_t>(count));
  for (int k = 0; k < count; ++k) members[static_cast<size_t>(sets.Find(k))].push_back(k);
  std::vector<Polygon2d> rebuilt;
  std::vector<double> rebuilt_radii;
  std::vector<int> rebuilt_sources;
  for (int k = 0; k < count; ++k) {
    const std::vector<int>& set = members[static_cast<size_t>(k)];
    if (set.size() == 1) {
      rebuilt.push_back(std::move((*polygons)[k]));
      rebuilt_radii.push_back((*radii)[k]);
      rebuilt_sources.push_back((*sources)[k]);
    }
    if (set.size() <= 1) continue;
    std::vector<Ring2d> rings;
    std::vector<int> names;
    for (const int m : set) {
      const std::vector<Ring2d> own = RingsOf((*polygons)[m]);
      rings.insert(rings.end(), own.begin(), own.end());
      if (names.empty() || names.back() != (*sources)[m]) names.push_back((*sources)[m]);
    }
    const std::string where = path + ": polygons " + ListOf(names);
    int pieces = 0;
    double area = 0.0;
    for (const Polygon2d& region : internal::EvenOddRegions({rings})) {
      for (Polygon2d& piece : PreparePolygons(region, where)) {
        area += Area(piece);
        ++pieces;
        rebuilt.push_back(std::move(piece));
        rebuilt_radii.push_back((*radii)[k]);
        rebuilt_sources.push_back((*sources)[k]);
      }
    }
    if (notes != nullptr) {
      std::ostringstream change;
      change << where << ": repaired: they overlap: rebuilt together by the even-odd rule into "
             << pieces << " polygon(s), area " << area
             << " (area covered an even number of times left out)";
      notes->push_back(change.str());
    }
  }
  *polygons = std::move(rebuilt);
  *radii = std::move(rebuilt_radii);
  *sources = std::move(rebuilt_sources);
}

// The file beside a shapefile's .shp with the same name and extension `lower` or `upper`
// (shapefiles come in either case), or "" if there is none.
std::string BesideShapefile(const std::string& shp_path, const char* lower, const char* upper) {
  std::filesystem::path candidate(shp_path);
  candidate.replace_extension(lower);
  if (std::filesystem::exists(candidate)) return candidate.string();
  candidate.replace_extension(upper);
  return std::filesystem::exists(candidate) ? candidate.string() : std::string();
}

// A note when `wkt`, the coordinate reference system of the polygons of `where` (a shapefile's
// .prj, a GeoPackage layer's definition, KML's fixed WGS 84), is geographic (WKT 1's GEOGCS, WKT
// 2's GEOGCRS or GEODCRS at the top): they are decomposed as planar x = longitude, y = latitude, so
// shapes are stretched east-west by 1 / cos(latitude) and tau is in degrees.
void NoteGeographicCoordinates(const std::string& where, const std::string& wkt,
                               std::vector<std::string>* notes) {
  const size_t start = wkt.find_first_not_of(" \t\r\n\xEF\xBB\xBF");  // (And a byte order mark.)
  const size_t bracket = wkt.find('[', start);
  if (start == std::string::npos || bracket == std::string::npos) return;
  const std::string keyword = internal::ToLower(wkt.substr(start, bracket - start));
  if (keyword != "geogcs" && keyword != "geogcrs" && keyword != "geodcrs") return;
  const size_t name_begin = wkt.find('"', bracket);
  const size_t name_end =
      name_begin == std::string::npos ? name_begin : wkt.find('"', name_begin + 1);
  const std::string name = name_end == std::string::npos
                               ? std::string()
                               : " " + wkt.substr(name_begin, name_end - name_begin + 1);
  notes->push_back(where + ": geographic coordinates (" + wkt.substr(start, bracket - start) +
                   name +
                   "): decomposed as planar x = longitude, y = latitude, so shapes are stretched "
                   "east-west and tau is in degrees; project the data first for true shapes");
}

// The attributes of a shapefile's records, per FID: the .dbf beside `shp_path`, read in the
// encoding the .cpg beside it names; none without a .dbf. Every record with a polygon (its FID
// in `features`) must have its row.
std::vector<std::string> ShapefileAttributes(const std::string& shp_path,
                                             const std::vector<int>& features,
                                             std::vector<std::string>* notes) {
  const std::string dbf_path = BesideShapefile(shp_path, ".dbf", ".DBF");
  if (dbf_path.empty()) {
    notes->push_back(shp_path + ": no .dbf beside it: its features carry no attributes");
    return {};
  }
  const std::string cpg_path = BesideShapefile(shp_path, ".cpg", ".CPG");
  const DbfEncoding encoding =
      cpg_path.empty() ? DbfEncoding::kAuto : DbfEncodingFromCpg(ReadFile(cpg_path));
  std::istringstream in(ReadFile(dbf_path));
  std::vector<std::string> rows = ReadDbf(in, dbf_path, encoding, notes);
  const int last = features.empty() ? -1 : *std::max_element(features.begin(), features.end());
  if (last >= static_cast<int>(rows.size())) {
    throw InputError(dbf_path + ": holds " + std::to_string(rows.size()) + " records, but " +
                     shp_path + "'s record " + std::to_string(last + 1) +
                     " has a shape (the .dbf has a row per record of the .shp)");
  }
  return rows;
}

// The formats ReadPolygons() reads, told by the file's extension (any case).
enum class PolygonFormat { kPoly, kWkt, kGeoJson, kShapefile, kGeoPackage, kKml, kKmz, kUnknown };

// The format of `path`, a file or a GeoPackage's layer ("FILE|layername=NAME").
PolygonFormat FormatOf(const std::string& path) {
  static constexpr std::pair<const char*, PolygonFormat> kExtensions[] = {
      {".poly", PolygonFormat::kPoly},       {".wkt", PolygonFormat::kWkt},
      {".geojson", PolygonFormat::kGeoJson}, {".json", PolygonFormat::kGeoJson},
      {".shp", PolygonFormat::kShapefile},   {".gpkg", PolygonFormat::kGeoPackage},
      {".kml", PolygonFormat::kKml},         {".kmz", PolygonFormat::kKmz},
  };
  const std::string extension =
      internal::ToLower(std::filesystem::path(SplitLayerName(path).first).extension().string());
  for (const auto& [name, format] : kExtensions) {
    if (extension == name) return format;
  }
  return PolygonFormat::kUnknown;
}

}  // namespace

bool IsPolygonFile(const std::string& path) { return FormatOf(path) != PolygonFormat::kUnknown; }

std::vector<Polygon2d> ReadPolygons(const std::string& path, std::vector<double>* reference_radii,
                                    const ReadPolygonsOptions& options) {
  const PolygonFormat format = FormatOf(path);
  using Reader = std::function<std::vector<Polygon2d>(std::istream&, const std::string&)>;
  Reader reader = nullptr;
  std::vector<std::string> warnings;
  std::vector<int> multipolygons;  // Per polygon of the file: its MULTIPOLYGON, or -1.
  std::vector<int> features;       // Per polygon of the file: its feature (default: itself).
  if (options.feature_properties != nullptr) options.feature_properties->clear();
  switch (format) {
    case PolygonFormat::kPoly:
      reader = [&](std::istream& in, const std::string& source) {
        return ReadPoly(in, source, &warnings);
      };
      break;
    case PolygonFormat::kWkt:
      reader = [&](std::istream& in, const std::string& source) {
        return ReadWkt(in, source, &multipolygons, &features);
      };
      break;
    case PolygonFormat::kGeoJson:
      reader = [&](std::istream& in, const std::string& source) {
        return ReadGeoJson(in, source, &multipolygons, &features, options.feature_properties,
                           {options.skip_non_areal, &warnings});
      };
      break;
    case PolygonFormat::kShapefile:
      reader = [&](std::istream& in, const std::string& source) {
        return ReadShapefile(in, source, &multipolygons, &warnings, &features);
      };
      break;
    case PolygonFormat::kKml:
    case PolygonFormat::kKmz:
      reader = [&](std::istream& in, const std::string& source) {
        KmlExtras extras;
        std::vector<Polygon2d> polygons = ReadKml(in, source, options.skip_non_areal, &extras);
        features = std::move(extras.features);
        if (options.feature_properties != nullptr) {
          *options.feature_properties = std::move(extras.properties);
        }
        warnings = std::move(extras.warnings);
        // KML's coordinates are WGS 84 longitude/latitude, always (OGC 07-147r2, 6.2).
        NoteGeographicCoordinates(source, "GEOGCS[\"WGS 84\"]", &warnings);
        return polygons;
      };
      break;
    case PolygonFormat::kGeoPackage:
      break;
    case PolygonFormat::kUnknown:
      throw InputError(path + ": unknown polygon file extension '" +
                       internal::ToLower(std::filesystem::path(path).extension().string()) +
                       "' (expected " + kPolygonFileExtensions + ")");
  }
  const auto [file, layer_name] = SplitLayerName(path);
  if (format != PolygonFormat::kGeoPackage && !layer_name.empty()) {
    throw InputError(path + ": '|layername=' names a layer of a GeoPackage (.gpkg) file only");
  }
  std::vector<Polygon2d> polygons;
  if (format == PolygonFormat::kGeoPackage) {
    GeoPackageLayer layer = ReadGeoPackage(file, layer_name, options.skip_non_areal,
                                           options.feature_properties != nullptr);
    polygons = std::move(layer.polygons);
    multipolygons = std::move(layer.multipolygons);
    features = std::move(layer.features);
    if (options.feature_properties != nullptr) {
      *options.feature_properties = std::move(layer.properties);
    }
    warnings = std::move(layer.warnings);
    NoteGeographicCoordinates(file + ": layer '" + layer.name + "'", layer.crs_wkt, &warnings);
  } else if (format == PolygonFormat::kKmz) {
    std::string entry;
    std::istringstream in(ReadKmzRoot(path, &entry));
    polygons = reader(in, path + "/" + entry);
  } else {
    std::ifstream in = OpenFile(path);
    polygons = reader(in, path);
    CheckRead(in, path);
  }
  if (polygons.empty()) throw InputError(path + ": no polygon in file");
  multipolygons.resize(polygons.size(), -1);
  for (size_t k = features.size(); k < polygons.size(); ++k) {
    features.push_back(static_cast<int>(k));
  }
  if (format == PolygonFormat::kShapefile) {
    const std::string prj_path = BesideShapefile(path, ".prj", ".PRJ");
    if (!prj_path.empty()) NoteGeographicCoordinates(prj_path, ReadFile(prj_path), &warnings);
    if (options.feature_properties != nullptr) {
      *options.feature_properties = ShapefileAttributes(path, features, &warnings);
    }
  }
  if (options.notes != nullptr) {
    options.notes->insert(options.notes->end(), warnings.begin(), warnings.end());
  }
  std::vector<Polygon2d> prepared;
  std::vector<double> radii;  // Per prepared polygon.
  std::vector<int> sources;   // Per prepared polygon: its polygon in the file.
  std::vector<int> groups;    // Per prepared polygon: its MULTIPOLYGON, or -1.
  for (size_t k = 0; k < polygons.size(); ++k) {
    const std::string where = path + ": polygon " + std::to_string(k);
    std::vector<Polygon2d> pieces;
    if (options.repair) {
      RepairedPolygon repaired = RepairPolygon(polygons[k], where);
      if (options.notes != nullptr) {
        options.notes->insert(options.notes->end(), repaired.changes.begin(),
                              repaired.changes.end());
      }
      pieces = std::move(repaired.polygons);
    } else {
      pieces = PreparePolygons(polygons[k], where);
    }
    // Every piece keeps the radius of the polygon it comes from, as written in the file.
    const double radius = ReferenceRadius(polygons[k]);
    for (Polygon2d& piece : pieces) {
      radii.push_back(radius);
      sources.push_back(static_cast<int>(k));
      groups.push_back(multipolygons[k]);
      prepared.push_back(std::move(piece));
    }
  }
  if (prepared.empty()) throw InputError(path + ": no polygon left after repair");
  const std::vector<std::pair<size_t, size_t>> overlapping =
      options.disjoint_members ? OverlappingPairs(prepared, groups, /*first_only=*/!options.repair)
                               : std::vector<std::pair<size_t, size_t>>{};
  if (!overlapping.empty() && !options.repair) {
    const auto [i, j] = overlapping.front();
    throw InputError(path + ": polygons " + std::to_string(sources[i]) + " and " +
                     std::to_string(sources[j]) +
                     " overlap (the members of a MULTIPOLYGON must have disjoint interiors; "
                     "--repair rebuilds them by the even-odd rule)");
  }
  if (!overlapping.empty()) {
    RebuildOverlapping(path, overlapping, &sources, &prepared, &radii, options.notes);
    if (prepared.empty()) throw InputError(path + ": no polygon left after repair");
  }
  if (reference_radii != nullptr) *reference_radii = std::move(radii);
  if (options.features != nullptr) {
    options.features->clear();
    for (const int source : sources) options.features->push_back(features[source]);
  }
  if (options.sources != nullptr) *options.sources = std::move(sources);
  return prepared;
}

}  // namespace acdplan::acd
