#include "acd/read_polygons.h"

#include <filesystem>
#include <functional>
#include <sstream>

#include "acd/geojson_reader.h"
#include "acd/internal/text_parsing.h"
#include "acd/poly_reader.h"
#include "acd/prepare_polygon.h"
#include "acd/repair_polygon.h"
#include "acd/wkt_reader.h"
#include "base/file_io.h"
#include "base/input_error.h"

namespace acdplan::acd {

std::vector<Polygon2d> ReadPolygons(const std::string& path, std::vector<double>* reference_radii,
                                    const ReadPolygonsOptions& options) {
  const std::string extension = internal::ToLower(std::filesystem::path(path).extension().string());
  using Reader = std::function<std::vector<Polygon2d>(std::istream&, const std::string&)>;
  Reader reader = nullptr;
  std::vector<std::string> warnings;
  if (extension == ".poly") {
    reader = [&](std::istream& in, const std::string& source) {
      return ReadPoly(in, source, &warnings);
    };
  } else if (extension == ".wkt") {
    reader = &ReadWkt;
  } else if (extension == ".geojson" || extension == ".json") {
    reader = &ReadGeoJson;
  } else {
    throw InputError(path + ": unknown polygon file extension '" + extension +
                     "' (expected .poly, .wkt, .geojson or .json)");
  }
  std::istringstream in(ReadFile(path));
  std::vector<Polygon2d> polygons = reader(in, path);
  if (polygons.empty()) throw InputError(path + ": no polygon in file");
  if (options.notes != nullptr) {
    options.notes->insert(options.notes->end(), warnings.begin(), warnings.end());
  }
  if (reference_radii != nullptr) reference_radii->clear();
  std::vector<Polygon2d> prepared;
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
      if (reference_radii != nullptr) reference_radii->push_back(radius);
      prepared.push_back(std::move(piece));
    }
  }
  if (prepared.empty()) throw InputError(path + ": no polygon left after repair");
  return prepared;
}

}  // namespace acdplan::acd
