#include "acd/geojson_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "base/input_error.h"
#include "tests/input_error_of.h"

namespace acdplan::acd {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

std::vector<Polygon2d> GeoJsonOf(const std::string& text) {
  std::istringstream in(text);
  return ReadGeoJson(in, "shape.geojson");
}

std::string GeoJsonErrorOf(const std::string& text) {
  return acdplan::test::InputErrorOf([&] { GeoJsonOf(text); });
}

const char* const kSquareWithHole =
    R"({"type": "Polygon", "coordinates": [[[0,0],[4,0],[4,4],[0,4],[0,0]],
                                           [[1,1],[1,2],[2,2],[2,1],[1,1]]]})";

TEST(GeoJsonReaderTest, ReadsPolygonWithHoleDroppingClosingPositions) {
  const std::vector<Polygon2d> polygons = GeoJsonOf(kSquareWithHole);
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(polygons[0].outer, Ring2d({{0, 0}, {4, 0}, {4, 4}, {0, 4}}));
  ASSERT_EQ(polygons[0].holes.size(), 1u);
  EXPECT_EQ(polygons[0].holes[0], Ring2d({{1, 1}, {1, 2}, {2, 2}, {2, 1}}));
}

TEST(GeoJsonReaderTest, ReadsFeatureCollectionMultiPolygonAndGeometryCollection) {
  const std::string text = std::string(R"({"type": "FeatureCollection", "features": [
      {"type": "Feature", "properties": {}, "geometry": )") +
                           kSquareWithHole + R"(},
      {"type": "Feature", "properties": null, "geometry": {"type": "MultiPolygon",
       "coordinates": [[[[0,0,7],[1,0,7],[1,1,7],[0,0,7]]], [[[5,5],[6,5],[6,6],[5,5]]]]}},
      {"type": "Feature", "geometry": null},
      {"type": "Feature", "geometry": {"type": "GeometryCollection", "geometries": [
        {"type": "Polygon", "coordinates": [[[0,0],[2,0],[2,2],[0,0]]]}]}}]})";
  const std::vector<Polygon2d> polygons = GeoJsonOf(text);
  ASSERT_EQ(polygons.size(), 4u);
  EXPECT_EQ(polygons[0].holes.size(), 1u);
  EXPECT_EQ(polygons[1].outer, Ring2d({{0, 0}, {1, 0}, {1, 1}}));  // z ignored
  EXPECT_EQ(polygons[2].outer.size(), 3u);
  EXPECT_EQ(polygons[3].outer, Ring2d({{0, 0}, {2, 0}, {2, 2}}));
}

TEST(GeoJsonReaderTest, SaysWhichMultiPolygonEachPolygonBelongsTo) {
  std::istringstream in(R"({"type": "GeometryCollection", "geometries": [
      {"type": "MultiPolygon", "coordinates": [[[[0,0],[1,0],[1,1],[0,0]]], []]},
      {"type": "Polygon", "coordinates": [[[0,0],[1,0],[1,1],[0,0]]]},
      {"type": "MultiPolygon", "coordinates": [[[[0,0],[1,0],[1,1],[0,0]]],
                                               [[[5,5],[6,5],[6,6],[5,5]]]]}]})");
  std::vector<int> multipolygons;
  EXPECT_EQ(ReadGeoJson(in, "test.geojson", &multipolygons).size(), 4u);
  EXPECT_EQ(multipolygons, std::vector<int>({0, -1, 1, 1}));
}

// RFC 7946 3.1: empty "coordinates" may be read as an empty geometry (shapely reads an empty
// Polygon so); an empty member of a MultiPolygon is skipped as WKT's EMPTY member is.
TEST(GeoJsonReaderTest, EmptyCoordinatesHoldNoPolygon) {
  const std::vector<Polygon2d> polygons =
      GeoJsonOf(R"({"type": "GeometryCollection", "geometries": [
      {"type": "Polygon", "coordinates": []},
      {"type": "MultiPolygon", "coordinates": [[], [[[0,0],[1,0],[1,1],[0,0]]]]},
      {"type": "MultiPolygon", "coordinates": []}]})");
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(polygons[0].outer, Ring2d({{0, 0}, {1, 0}, {1, 1}}));
}

TEST(GeoJsonReaderTest, UnsupportedTypeNamesElementPath) {
  EXPECT_EQ(GeoJsonErrorOf(R"({"type": "FeatureCollection", "features": [
      {"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [[[0,0],[1,0],[1,1],[0,0]]]}},
      {"type": "Feature", "geometry": null},
      {"type": "Feature", "geometry": {"type": "LineString", "coordinates": [[0,0],[1,1]]}}]})"),
            "shape.geojson: features[2].geometry: unsupported type 'LineString' (expected "
            "Polygon, MultiPolygon or GeometryCollection)");
  EXPECT_THAT(GeoJsonErrorOf(R"({"type": "Point", "coordinates": [0, 0]})"),
              HasSubstr("shape.geojson: root: unsupported type 'Point'"));
}

TEST(GeoJsonReaderTest, SkipsPointsAndLinesWhenAskedWithOneNote) {
  // A layer of buildings with an entrance (a point), a path (a line) and, inside a
  // GeometryCollection, a fence (lines) beside a shed: the areas are read, the rest is counted.
  const std::string layer = R"({"type": "FeatureCollection", "features": [
      {"type": "Feature", "properties": {"kind": "entrance"},
       "geometry": {"type": "Point", "coordinates": [5, 5]}},
      {"type": "Feature", "properties": {"kind": "hall"},
       "geometry": {"type": "Polygon", "coordinates": [[[0,0],[4,0],[4,4],[0,0]]]}},
      {"type": "Feature", "properties": {"kind": "path"},
       "geometry": {"type": "LineString", "coordinates": [[0,0],[9,9]]}},
      {"type": "Feature", "properties": {"kind": "yard"},
       "geometry": {"type": "GeometryCollection", "geometries": [
         {"type": "MultiLineString", "coordinates": [[[6,0],[6,3]], [[7,0],[7,3]]]},
         {"type": "Polygon", "coordinates": [[[8,0],[9,0],[9,1],[8,0]]]},
         {"type": "MultiPoint", "coordinates": [[8,8]]}]}}]})";
  std::istringstream in(layer);
  std::vector<int> features;
  std::vector<std::string> properties, warnings;
  const std::vector<Polygon2d> polygons =
      ReadGeoJson(in, "site.geojson", nullptr, &features, &properties, {true, &warnings});
  ASSERT_EQ(polygons.size(), 2u);
  EXPECT_EQ(polygons[0].outer, Ring2d({{0, 0}, {4, 0}, {4, 4}}));
  EXPECT_EQ(polygons[1].outer, Ring2d({{8, 0}, {9, 0}, {9, 1}}));
  EXPECT_EQ(features, (std::vector<int>{1, 3}));  // Feature indices as in the file.
  ASSERT_EQ(properties.size(), 4u);               // Every feature's, so that they stay aligned.
  EXPECT_EQ(properties[3], R"({"kind":"yard"})");
  EXPECT_EQ(warnings, (std::vector<std::string>{
                          "site.geojson: skipped 4 geometries without area (1 LineString, 1 "
                          "MultiLineString, 1 MultiPoint, 1 Point; the first at "
                          "features[0].geometry)"}));
  // Nothing skipped, no note; without the option, the first is refused as before.
  std::istringstream plain(kSquareWithHole);
  warnings.clear();
  EXPECT_EQ(ReadGeoJson(plain, "site.geojson", nullptr, nullptr, nullptr, {true, &warnings}).size(),
            1u);
  EXPECT_TRUE(warnings.empty());
  EXPECT_THAT(GeoJsonErrorOf(layer), HasSubstr("features[0].geometry: unsupported type 'Point'"));
}

TEST(GeoJsonReaderTest, StructureErrorsNameElementPath) {
  EXPECT_THAT(GeoJsonErrorOf(R"({"coordinates": []})"),
              HasSubstr("shape.geojson: root: missing member 'type'"));
  EXPECT_THAT(
      GeoJsonErrorOf(R"({"type": "Polygon", "coordinates": [[[0,0],[1,0],["a",1],[0,0]]]})"),
      HasSubstr("shape.geojson: coordinates[0][2][0]: expected a number, found string"));
  EXPECT_THAT(GeoJsonErrorOf(R"({"type": "Polygon", "coordinates": [[[0,0],[1],[1,1],[0,0]]]})"),
              HasSubstr("shape.geojson: coordinates[0][1]: expected a position [x, y]"));
  EXPECT_THAT(
      GeoJsonErrorOf(R"({"type": "MultiPolygon", "coordinates": [[[[0,0],[1,0],[1,1],[0,0]]],
                                                                [[[0,0],[1,0],[1,1]]]]})"),
      HasSubstr("shape.geojson: coordinates[1][0]: ring is not closed"));
  // nlohmann::json rejects numbers that overflow a double while parsing.
  EXPECT_THAT(
      GeoJsonErrorOf(R"({"type": "Polygon", "coordinates": [[[0,0],[1,0],[1,1e999],[0,0]]]})"),
      AllOf(HasSubstr("shape.geojson: invalid JSON"), HasSubstr("1e999")));
  EXPECT_THAT(GeoJsonErrorOf(R"({"type": "FeatureCollection", "features": [{"type": "Polygon"}]})"),
              HasSubstr("shape.geojson: features[0]: expected a Feature"));
  // A feature whose "type" is not a string (found by fuzz/fuzz_geojson_reader, which stopped on
  // nlohmann::json's own type_error; fuzz/corpus/geojson_reader/regression-feature-type-object).
  for (const char* type : {R"({"name": "a"})", "[]", "1", "null", "true"}) {
    EXPECT_EQ(
        GeoJsonErrorOf(std::string(R"({"type": "FeatureCollection", "features": [{"type": )") +
                       type + R"(, "geometry": null}]})"),
        "shape.geojson: features[0]: expected a Feature")
        << type;
  }
}

TEST(GeoJsonReaderTest, InvalidJsonNamesPosition) {
  EXPECT_THAT(GeoJsonErrorOf("{\"type\": \"Polygon\",\n \"coordinates\": [[[0,0],]]}"),
              HasSubstr("shape.geojson: invalid JSON: parse error at line 2"));
}

}  // namespace
}  // namespace acdplan::acd
