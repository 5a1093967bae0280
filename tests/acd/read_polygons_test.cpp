#include "acd/read_polygons.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "base/file_io.h"
#include "base/input_error.h"
#include "tests/data_paths.h"
#include "tests/input_error_of.h"
#include "tests/scratch_dir.h"

namespace acdplan::acd {
namespace {

namespace fs = std::filesystem;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

using acdplan::test::kAcd2d;
using acdplan::test::kShapefiles;

std::string ReadErrorOf(const std::string& path) {
  return acdplan::test::InputErrorOf([&] { ReadPolygons(path); });
}

// A file in the process's scratch folder.
std::string WriteTemp(const std::string& name, const std::string& text) {
  static const acdplan::test::ScratchDir dir("acdplan_read_polygons_test");  // Removed at exit.
  return dir.Write(name, text);
}

TEST(ReadPolygonsTest, DispatchesByExtensionCaseInsensitiveAndPrepares) {
  // Clockwise outer rings everywhere: ReadPolygons re-orients them.
  const std::string wkt = WriteTemp("a.WKT", "POLYGON ((0 0, 0 4, 4 4, 4 0, 0 0))");
  const std::string json = WriteTemp(
      "a.GeoJSON", R"({"type": "Polygon", "coordinates": [[[0,0],[0,4],[4,4],[4,0],[0,0]]]})");
  const std::string json2 = WriteTemp(
      "a.json", R"({"type": "Polygon", "coordinates": [[[0,0],[0,4],[4,4],[4,0],[0,0]]]})");
  const std::string poly = WriteTemp("a.Poly", "1\n4 out\n0 0\n0 4\n4 4\n4 0\n1 2 3 4\n");
  for (const std::string& path : {wkt, json, json2, poly}) {
    const std::vector<Polygon2d> polygons = ReadPolygons(path);
    ASSERT_EQ(polygons.size(), 1u) << path;
    EXPECT_DOUBLE_EQ(SignedArea(polygons[0].outer), 16.0) << path;
    fs::remove(path);
  }
}

TEST(ReadPolygonsTest, FileErrors) {
  EXPECT_THAT(
      ReadErrorOf("/nonexistent/shape.poly"),
      HasSubstr("/nonexistent/shape.poly: cannot read the file: No such file or directory"));
  EXPECT_THAT(ReadErrorOf("shape.svg"),
              HasSubstr("shape.svg: unknown polygon file extension '.svg'"));
  const std::string empty = WriteTemp("empty.wkt", "POLYGON EMPTY");
  EXPECT_THAT(ReadErrorOf(empty), HasSubstr("empty.wkt: no polygon in file"));
  fs::remove(empty);
}

TEST(ReadPolygonsTest, GeometryErrorsNameFileAndPolygon) {
  // The second polygon is a bow tie.
  const std::string path =
      WriteTemp("bowtie.wkt", "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)), ((0 0, 2 2, 3 0, 0 3, 0 0)))");
  EXPECT_THAT(ReadErrorOf(path), HasSubstr("bowtie.wkt: polygon 1: outer ring is not simple: edges "
                                           "(0,1) and (2,3) intersect at (1.5, 1.5)"));
  fs::remove(path);
}

TEST(ReadPolygonsTest, EveryAcd2dPolyFileValidatesExceptKnownDefects) {
  int files = 0;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kAcd2d)) {
    if (entry.path().extension() != ".poly") continue;
    ++files;
    const std::string name = entry.path().filename().string();
    const std::string path = entry.path().string();
    if (name == "bird.poly") {
      EXPECT_THAT(ReadErrorOf(path), HasSubstr("bird.poly:47: malformed number '-6.64248.788605'"));
    } else {
      EXPECT_EQ(ReadErrorOf(path), "") << name;
    }
  }
  EXPECT_EQ(files, 54);
}

TEST(ReadPolygonsTest, Simple5ReadsAllItsChainsWithOneWarning) {
  // Declares 1 chain but holds more (an outer ring, then a hole from line 380 on); Lien's
  // reader read the first chain only. We read all and warn once.
  std::vector<std::string> notes;
  ReadPolygonsOptions options;
  options.notes = &notes;
  const std::vector<Polygon2d> polygons =
      ReadPolygons((kAcd2d / "simple5.poly").string(), nullptr, options);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(notes[0], HasSubstr("simple5.poly:380: "));
  EXPECT_THAT(notes[0], HasSubstr("more than the 1 declared on line 1"));
  ASSERT_FALSE(polygons.empty());
  EXPECT_FALSE(polygons[0].holes.empty());
}

TEST(ReadPolygonsTest, RepairOptionRepairsAndReportsChanges) {
  const std::string path = WriteTemp("tile.wkt", "POLYGON ((0 0, 2 2, 3 0, 0 3, 0 0))");
  EXPECT_THAT(ReadErrorOf(path), HasSubstr("tile.wkt: polygon 0: outer ring is not simple"));
  std::vector<std::string> notes;
  ReadPolygonsOptions options;
  options.repair = true;
  options.notes = &notes;
  std::vector<double> radii;
  const std::vector<Polygon2d> polygons = ReadPolygons(path, &radii, options);
  EXPECT_EQ(polygons.size(), 2u);
  EXPECT_EQ(radii.size(), 2u);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(notes[0], HasSubstr("tile.wkt: polygon 0: repaired: outer ring is not simple"));
  fs::remove(path);
}

TEST(ReadPolygonsTest, OverlappingMultipolygonMembersAreAnErrorOrRepaired) {
  // Members 0 and 2 overlap in [1, 2]^2; member 1 touches member 0 along an edge, member 3
  // touches member 2 at a point (both allowed).
  const std::string path =
      WriteTemp("overlap.wkt",
                "MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0)), ((2 0, 4 0, 4 1, 2 1, 2 0)),"
                " ((1 1, 3 1.5, 3 3, 1 3, 1 1)), ((3 3, 4 3, 4 4, 3 4, 3 3)))");
  EXPECT_EQ(ReadPolygons(path).size(), 4u);  // As obstacles: overlaps are allowed.
  ReadPolygonsOptions options;
  options.disjoint_members = true;
  EXPECT_THAT(acdplan::test::InputErrorOf([&] { ReadPolygons(path, nullptr, options); }),
              HasSubstr("overlap.wkt: polygons 0 and 2 overlap (the members of a MULTIPOLYGON "
                        "must have disjoint interiors"));

  std::vector<std::string> notes;
  options.repair = true;
  options.notes = &notes;
  std::vector<int> sources;
  options.sources = &sources;
  std::vector<double> radii;
  const std::vector<Polygon2d> polygons = ReadPolygons(path, &radii, options);
  // The rebuilt pieces of members 0 and 2 where member 0 was, then members 1 and 3.
  EXPECT_EQ(sources, (std::vector<int>{0, 0, 1, 3}));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(notes[0], HasSubstr("overlap.wkt: polygons 0 and 2: repaired: they overlap: rebuilt "
                                  "together by the even-odd rule into 2 polygon(s)"));
  ASSERT_EQ(polygons.size(), 4u);  // The even-odd rule splits 0 and 2 where they cross.
  EXPECT_EQ(radii.size(), polygons.size());
  double area = 0.0;
  for (const Polygon2d& polygon : polygons) area += Area(polygon);
  // 4 + 2 + 3.5 + 1, less twice the common area: the quadrilateral (1,1) (2,1.25) (2,2) (1,2).
  EXPECT_NEAR(area, 10.5 - 2.0 * 0.875, 1e-12);
  fs::remove(path);
}

// Each polygon returned says which of the file's polygons it comes from: the pieces a pinch
// splits one into share its index.
TEST(ReadPolygonsTest, SourcesMapPiecesBackToTheFilesPolygons) {
  const std::string path =
      WriteTemp("pinch.wkt",
                "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0), (0 5, 3 6, 3 4, 0 5)),"
                " ((20 0, 22 0, 22 2, 20 2, 20 0)))\nPOLYGON ((30 0, 32 0, 32 2, 30 2, 30 0))\n");
  ReadPolygonsOptions options;
  std::vector<int> sources;
  options.sources = &sources;
  const std::vector<Polygon2d> polygons = ReadPolygons(path, nullptr, options);
  ASSERT_EQ(polygons.size(), 4u);  // The hole touching the outer ring: two pieces.
  EXPECT_EQ(sources, (std::vector<int>{0, 0, 1, 2}));
  fs::remove(path);
}

// A feature is what a GIS tool keeps attributes for: a MultiPolygon's members share theirs, a
// feature without geometry holds no polygon but keeps its number.
TEST(ReadPolygonsTest, FeaturesMapPolygonsBackToTheFilesFeatures) {
  const std::string geojson = WriteTemp("features.geojson", R"({"type": "FeatureCollection",
    "features": [
      {"type": "Feature", "properties": {},
       "geometry": {"type": "Polygon", "coordinates": [[[0,0],[2,0],[2,2],[0,2],[0,0]]]}},
      {"type": "Feature", "properties": {},
       "geometry": {"type": "MultiPolygon", "coordinates": [[[[10,0],[12,0],[12,2],[10,2],[10,0]]],
                                                            [[[20,0],[22,0],[22,2],[20,2],[20,0]]]]}},
      {"type": "Feature", "properties": {}, "geometry": null},
      {"type": "Feature", "properties": {},
       "geometry": {"type": "Polygon", "coordinates": [[[30,0],[32,0],[32,2],[30,2],[30,0]]]}}]})");
  const std::string wkt = WriteTemp(
      "features.wkt",
      "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))\n"
      "MULTIPOLYGON (((10 0, 12 0, 12 2, 10 2, 10 0)), ((20 0, 22 0, 22 2, 20 2, 20 0)))\n"
      "POLYGON ((30 0, 32 0, 32 2, 30 2, 30 0))\n");
  const std::string poly = WriteTemp("features.poly",
                                     "2\n4 out\n0 0\n2 0\n2 2\n0 2\n1 2 3 4\n"
                                     "4 out\n10 0\n12 0\n12 2\n10 2\n1 2 3 4\n");
  const std::vector<std::pair<std::string, std::vector<int>>> cases = {
      {geojson, {0, 1, 1, 3}}, {wkt, {0, 1, 1, 2}}, {poly, {0, 1}}};
  for (const auto& [path, expected] : cases) {
    ReadPolygonsOptions options;
    options.disjoint_members = true;
    std::vector<int> features;
    options.features = &features;
    ReadPolygons(path, nullptr, options);
    EXPECT_EQ(features, expected) << path;
  }
}

// The attributes of each feature, to carry into output: a GeoJSON Feature's properties, in the
// file's order; none for formats without attributes.
TEST(ReadPolygonsTest, FeaturePropertiesOfGeoJsonFeatures) {
  const std::string geojson = WriteTemp("properties.geojson", R"({"type": "FeatureCollection",
    "features": [
      {"type": "Feature", "properties": {"name": "field", "area_ha": 4.5},
       "geometry": {"type": "Polygon", "coordinates": [[[0,0],[2,0],[2,2],[0,2],[0,0]]]}},
      {"type": "Feature", "properties": null, "geometry": null},
      {"type": "Feature", "properties": {"name": "barn", "tags": ["a", "b"]},
       "geometry": {"type": "Polygon", "coordinates": [[[30,0],[32,0],[32,2],[30,2],[30,0]]]}}]})");
  ReadPolygonsOptions options;
  std::vector<std::string> properties = {"stale"};
  options.feature_properties = &properties;
  ReadPolygons(geojson, nullptr, options);
  EXPECT_EQ(properties, (std::vector<std::string>{R"({"name":"field","area_ha":4.5})", "{}",
                                                  R"({"name":"barn","tags":["a","b"]})"}));
  properties = {"stale"};
  ReadPolygons(WriteTemp("none.wkt", "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))\n"), nullptr, options);
  EXPECT_TRUE(properties.empty());
}

// A shapefile's attributes are the rows of the .dbf beside it, one per record (FID); a record
// without a row is an error, a missing .dbf a note.
TEST(ReadPolygonsTest, FeaturePropertiesOfShapefileRecordsFromTheDbf) {
  ReadPolygonsOptions options;
  std::vector<std::string> properties;
  std::vector<int> features;
  options.feature_properties = &properties;
  options.features = &features;
  const std::vector<Polygon2d> counties =
      ReadPolygons((kShapefiles / "nc.shp").string(), nullptr, options);
  ASSERT_EQ(properties.size(), 100u);
  EXPECT_THAT(properties[0], HasSubstr(R"("NAME":"Ashe")"));
  EXPECT_THAT(properties[99], HasSubstr(R"("NAME":"Brunswick")"));
  ASSERT_EQ(features.size(), counties.size());
  EXPECT_EQ(features.front(), 0);
  EXPECT_EQ(features.back(), 99);

  // Copies: without the .dbf (nor a .prj); with a .dbf of fewer rows than records.
  const std::string shp = WriteTemp("counties.shp", ReadFile((kShapefiles / "nc.shp").string()));
  std::vector<std::string> notes;
  options.notes = &notes;
  ReadPolygons(shp, nullptr, options);
  EXPECT_TRUE(properties.empty());
  EXPECT_THAT(notes, ElementsAre(HasSubstr("no .dbf beside it")));
  // nc.dbf cut to its first 99 rows: the header's count says 99 too.
  std::string short_dbf = ReadFile((kShapefiles / "nc.dbf").string());
  auto uint16_at = [&](size_t at) {
    return static_cast<unsigned char>(short_dbf[at]) | static_cast<unsigned char>(short_dbf[at + 1])
                                                           << 8;
  };
  const int header = uint16_at(8), row = uint16_at(10);
  short_dbf[4] = 99;  // The record count's low byte: 100 -> 99.
  short_dbf.resize(static_cast<size_t>(header + 99 * row));
  WriteTemp("counties.dbf", short_dbf);
  EXPECT_THAT(
      acdplan::test::InputErrorOf([&] { ReadPolygons(shp, nullptr, options); }),
      HasSubstr("counties.dbf: holds 99 records, but " + shp + "'s record 100 has a shape"));
}

// Longitude/latitude decomposed as planar distorts shapes: a .prj that says so gets a note, a
// projected one none.
TEST(ReadPolygonsTest, GeographicCoordinatesOfAShapefileGetANote) {
  ReadPolygonsOptions options;
  std::vector<std::string> notes;
  options.notes = &notes;
  ReadPolygons((kShapefiles / "nc.shp").string(), nullptr, options);
  EXPECT_THAT(notes, ElementsAre(HasSubstr(
                         "nc.prj: geographic coordinates (GEOGCS \"GCS_North_American_1927\"): "
                         "decomposed as planar x = longitude, y = latitude")));
  const std::string shp = WriteTemp("tracts.shp", ReadFile((kShapefiles / "olinda1.shp").string()));
  WriteTemp("tracts.prj", "PROJCS[\"SIRGAS 2000 / UTM zone 25S\",GEOGCS[\"SIRGAS 2000\"]]");
  notes.clear();
  ReadPolygons(shp, nullptr, options);
  EXPECT_THAT(notes, ElementsAre());
  WriteTemp("tracts.prj",
            "\n  geogcrs[\"WGS 84\",DATUM[\"World Geodetic System 1984\"]]");  // WKT 2.
  ReadPolygons(shp, nullptr, options);
  EXPECT_THAT(notes, ElementsAre(HasSubstr("(geogcrs \"WGS 84\")")));
}

TEST(ReadPolygonsTest, NazcaMonkeyAndNeuronCounts) {
  const std::vector<Polygon2d> monkey =
      ReadPolygons((kAcd2d / "nazca" / "nazca_monkey.poly").string());
  ASSERT_EQ(monkey.size(), 1u);
  EXPECT_EQ(VertexCount(monkey[0]), 1204);  // The dissertation's count (Table 2).
  EXPECT_TRUE(monkey[0].holes.empty());

  const std::vector<Polygon2d> neuron = ReadPolygons((kAcd2d / "neuron" / "neuron.poly").string());
  ASSERT_EQ(neuron.size(), 1u);
  EXPECT_EQ(neuron[0].holes.size(), 18u);
  EXPECT_EQ(VertexCount(neuron[0]), 1786);  // 1,815 in the file; 29 collinear ones dropped.

  // egg.poly's outer chain is clockwise in the file: re-oriented, not rejected.
  const std::vector<Polygon2d> egg = ReadPolygons((kAcd2d / "egg.poly").string());
  ASSERT_EQ(egg.size(), 1u);
  EXPECT_GT(SignedArea(egg[0].outer), 0.0);
  EXPECT_EQ(egg[0].outer.size(), 64u);

  const std::vector<Polygon2d> nacd = ReadPolygons((kAcd2d / "neuron" / "nacd.poly").string());
  EXPECT_EQ(nacd.size(), 234u);  // 234 "out" chains: 234 polygons.
}

}  // namespace
}  // namespace acdplan::acd
