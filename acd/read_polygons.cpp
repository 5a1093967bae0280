#include "acd/read_polygons.h"

#include <filesystem>
#include <sstream>

#include "acd/geojson_reader.h"
#include "acd/internal/text_parsing.h"
#include "acd/poly_reader.h"
#include "acd/prepare_polygon.h"
#include "acd/wkt_reader.h"
#include "base/file_io.h"
#include "base/input_error.h"

namespace acdplan::acd {

std::vector<Polygon2d> ReadPolygons(const std::string& path, std::vector<double>* reference_radii) {
  const std::string extension = internal::ToLower(std::filesystem::path(path).extension().string());
  using Reader = std::vector<Polygon2d> (*)(std::istream&, const std::string&);
  Reader reader = nullptr;
  if (extension == ".poly") {
    reader = &ReadPoly;
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
  if (reference_radii != nullptr) {
    reference_radii->clear();
    for (const Polygon2d& raw : polygons) reference_radii->push_back(ReferenceRadius(raw));
  }
  for (size_t k = 0; k < polygons.size(); ++k) {
    polygons[k] = PreparePolygon(polygons[k], path + ": polygon " + std::to_string(k));
  }
  return polygons;
}

}  // namespace acdplan::acd
