#include "acd/geojson_reader.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "acd/internal/skipped_geometries.h"
#include "acd/internal/text_parsing.h"
#include "base/input_error.h"

namespace acdplan::acd {
namespace {

// Ordered: a Feature's properties are handed on in the file's order (ReadGeoJson()).
using Json = nlohmann::ordered_json;

// Walks a parsed document; `path` names the element in messages: "features[2].geometry",
// "coordinates[0][3]", or "root" for the document itself.
class GeoJsonWalker {
 public:
  GeoJsonWalker(const std::string& source, bool skip_non_areal)
      : source_(source), skip_non_areal_(skip_non_areal) {}

  // The polygons, per polygon its MultiPolygon and its feature, and per feature its properties
  // (ReadGeoJson()); the note on skipped geometries to `warnings`.
  std::vector<Polygon2d> Walk(const Json& root, std::vector<int>* multipolygons,
                              std::vector<int>* features, std::vector<std::string>* properties,
                              std::vector<std::string>* warnings) {
    Object(root, "");
    if (!skipped_.empty() && warnings != nullptr) warnings->push_back(skipped_.Note(source_));
    if (multipolygons != nullptr) *multipolygons = std::move(multipolygons_);
    if (features != nullptr) *features = std::move(features_);
    if (properties != nullptr) *properties = std::move(properties_);
    return std::move(polygons_);
  }

 private:
  [[noreturn]] void Fail(const std::string& path, const std::string& message) const {
    throw InputError(source_ + ": " + (path.empty() ? std::string("root") : path) + ": " + message);
  }

  static std::string Member(const std::string& path, const std::string& name) {
    return path.empty() ? name : path + "." + name;
  }

  static std::string Index(const std::string& path, size_t i) {
    return path + "[" + std::to_string(i) + "]";
  }

  const Json& Require(const Json& object, const std::string& path, const std::string& name,
                      Json::value_t type, const char* type_name) const {
    const auto it = object.find(name);
    if (it == object.end()) Fail(path, "missing member '" + name + "'");
    if (it->type() != type) {
      Fail(Member(path, name), std::string("expected ") + type_name + ", found " + it->type_name());
    }
    return *it;
  }

  void Object(const Json& value, const std::string& path, bool geometry_only = false) {
    if (!value.is_object())
      Fail(path, std::string("expected an object, found ") + value.type_name());
    const std::string type =
        Require(value, path, "type", Json::value_t::string, "a string").get<std::string>();
    if (type == "Polygon") {
      const Json& coordinates =
          Require(value, path, "coordinates", Json::value_t::array, "an array");
      AddPolygon(coordinates, Member(path, "coordinates"));
    } else if (type == "MultiPolygon") {
      const Json& coordinates =
          Require(value, path, "coordinates", Json::value_t::array, "an array");
      const std::string member = Member(path, "coordinates");
      multipolygon_ = multipolygon_count_++;
      for (size_t i = 0; i < coordinates.size(); ++i) AddPolygon(coordinates[i], Index(member, i));
      multipolygon_ = -1;
    } else if (skip_non_areal_ && (type == "Point" || type == "MultiPoint" ||
                                   type == "LineString" || type == "MultiLineString")) {
      skipped_.Add(type, path.empty() ? std::string("root") : path);
    } else if (type == "GeometryCollection") {
      const Json& geometries = Require(value, path, "geometries", Json::value_t::array, "an array");
      const std::string member = Member(path, "geometries");
      for (size_t i = 0; i < geometries.size(); ++i) {
        if (path.empty()) feature_ = static_cast<int>(i);  // The root's members are features.
        Object(geometries[i], Index(member, i), true);
      }
    } else if (type == "Feature" && !geometry_only) {
      // RFC 7946 3.2: "properties" is an object or null (then, as when it is missing, none).
      const auto properties = value.find("properties");
      properties_.push_back(properties != value.end() && properties->is_object()
                                ? properties->dump()
                                : std::string("{}"));
      const auto it = value.find("geometry");
      if (it == value.end()) Fail(path, "missing member 'geometry'");
      // RFC 7946 3.2: an unlocated feature has a null geometry; it holds no polygon.
      if (!it->is_null()) Object(*it, Member(path, "geometry"), true);
    } else if (type == "FeatureCollection" && !geometry_only) {
      const Json& features = Require(value, path, "features", Json::value_t::array, "an array");
      const std::string member = Member(path, "features");
      for (size_t i = 0; i < features.size(); ++i) {
        const std::string feature_path = Index(member, i);
        const Json& feature = features[i];
        // Any JSON value may stand at "type"; only the string "Feature" makes a Feature (json's
        // value() would throw its own type_error on a non-string).
        if (!feature.is_object() || !feature.contains("type") || feature.at("type") != "Feature") {
          Fail(feature_path, "expected a Feature");
        }
        feature_ = static_cast<int>(i);
        Object(feature, feature_path);
      }
    } else {
      Fail(path, "unsupported type '" + type + "' (expected " +
                     (geometry_only ? "Polygon, MultiPolygon or GeometryCollection"
                                    : "Polygon, MultiPolygon, GeometryCollection, Feature or "
                                      "FeatureCollection") +
                     ")");
    }
  }

  // RFC 7946 3.1.6: an array of linear rings, the first the exterior, the others holes. An empty
  // array adds nothing (3.1: empty "coordinates" may stand for an empty geometry, as WKT's EMPTY).
  void AddPolygon(const Json& rings, const std::string& path) {
    if (!rings.is_array())
      Fail(path, std::string("expected an array of rings, found ") + rings.type_name());
    if (rings.empty()) return;
    Polygon2d polygon;
    polygon.outer = Ring(rings[0], Index(path, 0));
    for (size_t i = 1; i < rings.size(); ++i)
      polygon.holes.push_back(Ring(rings[i], Index(path, i)));
    polygons_.push_back(std::move(polygon));
    multipolygons_.push_back(multipolygon_);
    features_.push_back(feature_);
  }

  // A closed ring: the last position repeats the first and is dropped.
  Ring2d Ring(const Json& positions, const std::string& path) const {
    if (!positions.is_array()) {
      Fail(path, std::string("expected an array of positions, found ") + positions.type_name());
    }
    Ring2d ring;
    for (size_t i = 0; i < positions.size(); ++i) {
      const Json& position = positions[i];
      const std::string position_path = Index(path, i);
      if (!position.is_array() || position.size() < 2) {
        Fail(position_path, "expected a position [x, y]");
      }
      double xy[2];
      for (size_t k = 0; k < position.size(); ++k) {
        if (!position[k].is_number()) {
          Fail(Index(position_path, k),
               std::string("expected a number, found ") + position[k].type_name());
        }
        if (k >= 2) continue;  // Any z (or further value) is ignored.
        xy[k] = position[k].get<double>();
        // JSON has no NaN, but a literal like 1e400 overflows to infinity.
        if (!std::isfinite(xy[k])) Fail(Index(position_path, k), "non-finite number");
      }
      ring.emplace_back(xy[0], xy[1]);
    }
    if (ring.size() < 2 || ring.front() != ring.back()) {
      Fail(path,
           "ring is not closed (its last position must repeat its first" +
               (ring.empty() ? std::string(")") : " " + internal::FormatPoint(ring.front()) + ")"));
    }
    ring.pop_back();
    return ring;
  }

  const std::string& source_;
  const bool skip_non_areal_;
  internal::SkippedGeometries skipped_;
  std::vector<Polygon2d> polygons_;
  std::vector<int> multipolygons_;       // Per polygon.
  std::vector<int> features_;            // Per polygon.
  std::vector<std::string> properties_;  // Per Feature, in document order.
  int multipolygon_ = -1;                // The MultiPolygon being read, or -1.
  int feature_ = 0;                      // The feature being read.
  int multipolygon_count_ = 0;
};

}  // namespace

std::vector<Polygon2d> ReadGeoJson(std::istream& in, const std::string& source,
                                   std::vector<int>* multipolygons, std::vector<int>* features,
                                   std::vector<std::string>* properties,
                                   const GeoJsonSkipOptions& skip) {
  Json root;
  try {
    root = Json::parse(in);
  } catch (const Json::exception& error) {
    // what() is "[json.exception.parse_error.101] parse error at line 1, column 5: ..." (or
    // out_of_range.406 for a number that overflows a double).
    std::string message = error.what();
    const size_t bracket = message.find("] ");
    if (bracket != std::string::npos) message = message.substr(bracket + 2);
    throw InputError(source + ": invalid JSON: " + message);
  }
  return GeoJsonWalker(source, skip.non_areal)
      .Walk(root, multipolygons, features, properties, skip.warnings);
}

}  // namespace acdplan::acd
