#include "acd/geopackage_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "acd/check_decomposition.h"
#include "acd/decompose2d.h"
#include "acd/read_polygons.h"
#include "base/file_io.h"
#include "tests/acd/wkb_fixtures.h"
#include "tests/data_paths.h"
#include "tests/input_error_of.h"
#include "tests/scratch_dir.h"

namespace acdplan::acd {
namespace {

using acdplan::test::GeoPackageBlob;
using acdplan::test::InputErrorOf;
using acdplan::test::WkbWriter;
using ::testing::HasSubstr;

using acdplan::test::kGeoPackages;

const Ring2d kSquare = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
const Ring2d kHole = {{1, 1}, {1, 2}, {2, 2}, {2, 1}};

std::string PolygonBlob(const std::vector<Ring2d>& rings) {
  return GeoPackageBlob(WkbWriter().Polygon(rings).bytes());
}

// A feature table: its name, declared geometry type and rows (a geometry blob or NULL, and a
// name attribute).
struct TestLayer {
  std::string name;
  std::string geometry_type = "POLYGON";
  std::vector<std::optional<std::string>> geometries;
};

void Exec(sqlite3* db, const std::string& sql) {
  char* error = nullptr;
  ASSERT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error), SQLITE_OK) << error;
}

// Writes a GeoPackage 1.2 with the required tables and `layers` (each with the columns fid,
// geom and name, "row <k>"), in SRS `srs_id` (4326 is defined as WGS 84 longitude/latitude).
std::string WriteGeoPackage(const acdplan::test::ScratchDir& dir, const std::string& file,
                            const std::vector<TestLayer>& layers, int srs_id = -1,
                            bool wal = false) {
  const std::string path = dir.Path(file);
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  if (wal) Exec(db, "PRAGMA journal_mode = WAL");
  Exec(db,
       "PRAGMA application_id = 1196444487;"
       "CREATE TABLE gpkg_spatial_ref_sys (srs_name TEXT NOT NULL, srs_id INTEGER PRIMARY KEY, "
       "organization TEXT NOT NULL, organization_coordsys_id INTEGER NOT NULL, "
       "definition TEXT NOT NULL, description TEXT);"
       "INSERT INTO gpkg_spatial_ref_sys VALUES "
       "('Undefined cartesian SRS', -1, 'NONE', -1, 'undefined', NULL),"
       "('WGS 84 geodetic', 4326, 'EPSG', 4326, 'GEOGCS[\"WGS 84\",DATUM[\"WGS_1984\"]]', NULL);"
       "CREATE TABLE gpkg_contents (table_name TEXT NOT NULL PRIMARY KEY, data_type TEXT NOT "
       "NULL, identifier TEXT, srs_id INTEGER);"
       "CREATE TABLE gpkg_geometry_columns (table_name TEXT NOT NULL, column_name TEXT NOT NULL, "
       "geometry_type_name TEXT NOT NULL, srs_id INTEGER NOT NULL, z TINYINT, m TINYINT);");
  for (const TestLayer& layer : layers) {
    const std::string srs = std::to_string(srs_id);
    Exec(db, "CREATE TABLE \"" + layer.name +
                 "\" (fid INTEGER PRIMARY KEY AUTOINCREMENT, geom BLOB, name TEXT);"
                 "INSERT INTO gpkg_contents VALUES ('" +
                 layer.name + "', 'features', '" + layer.name + "', " + srs +
                 ");"
                 "INSERT INTO gpkg_geometry_columns VALUES ('" +
                 layer.name + "', 'geom', '" + layer.geometry_type + "', " + srs + ", 0, 0);");
    for (size_t k = 0; k < layer.geometries.size(); ++k) {
      sqlite3_stmt* insert = nullptr;
      const std::string sql =
          "INSERT INTO \"" + layer.name + "\" (fid, geom, name) VALUES (?, ?, ?)";
      EXPECT_EQ(sqlite3_prepare_v2(db, sql.c_str(), -1, &insert, nullptr), SQLITE_OK);
      sqlite3_bind_int(insert, 1, static_cast<int>(10 + k));  // Ids from 10, not 0 or 1.
      const std::optional<std::string>& blob = layer.geometries[k];
      if (blob) {
        sqlite3_bind_blob(insert, 2, blob->data(), static_cast<int>(blob->size()),
                          SQLITE_TRANSIENT);
      }
      const std::string name = "row " + std::to_string(k);
      sqlite3_bind_text(insert, 3, name.c_str(), -1, SQLITE_TRANSIENT);
      EXPECT_EQ(sqlite3_step(insert), SQLITE_DONE);
      sqlite3_finalize(insert);
    }
  }
  EXPECT_EQ(sqlite3_close(db), SQLITE_OK);
  return path;
}

// The sf package's nc.gpkg (GDAL's writer, GeoPackage 1.0) holds what its nc.shp holds: the
// same 100 counties, 108 polygons, with the same attributes.
TEST(GeoPackageReaderTest, ReadsAGdalWrittenLayerAsTheSameDataAsAShapefile) {
  std::vector<std::string> notes, properties, shp_properties;
  std::vector<int> features, shp_features;
  ReadPolygonsOptions options;
  options.notes = &notes;
  options.features = &features;
  options.feature_properties = &properties;
  options.disjoint_members = true;
  const std::vector<Polygon2d> polygons =
      ReadPolygons((kGeoPackages / "nc.gpkg").string(), nullptr, options);
  options.features = &shp_features;
  options.feature_properties = &shp_properties;
  const std::vector<Polygon2d> shp =
      ReadPolygons((acdplan::test::kShapefiles / "nc.shp").string(), nullptr, options);
  ASSERT_EQ(polygons.size(), 108u);
  ASSERT_EQ(polygons.size(), shp.size());
  EXPECT_EQ(features, shp_features);
  for (size_t k = 0; k < polygons.size(); ++k) {
    EXPECT_NEAR(Area(polygons[k]), Area(shp[k]), 1e-12 * Area(shp[k])) << k;
  }
  ASSERT_EQ(properties.size(), 100u);
  const nlohmann::json first = nlohmann::json::parse(properties[0]);
  EXPECT_EQ(first.at("NAME"), "Ashe");
  EXPECT_EQ(first.at("FIPS"), nlohmann::json::parse(shp_properties[0]).at("FIPS"));
  EXPECT_FALSE(first.contains("geom"));
  // Its SRS is NAD27 longitude/latitude: the note of a shapefile's .prj, naming the layer.
  ASSERT_EQ(notes.size(), 2u);  // The shapefile's .prj gave the second.
  EXPECT_THAT(notes[0], HasSubstr("nc.gpkg: layer 'nc.gpkg': geographic coordinates (GEOGCS "
                                  "\"NAD27\")"));
}

// A GIS user's round on a projected layer: buildings.gpkg (GeoPackage 1.2) decomposes and the
// decomposition passes its check.
TEST(GeoPackageReaderTest, DecomposesTheBuildingsOfAGdalWrittenLayer) {
  std::vector<double> radii;
  std::vector<std::string> notes;
  ReadPolygonsOptions options;
  options.notes = &notes;
  const std::vector<Polygon2d> polygons =
      ReadPolygons((kGeoPackages / "buildings.gpkg").string(), &radii, options);
  ASSERT_EQ(polygons.size(), 158u);
  EXPECT_TRUE(notes.empty());  // Transverse Mercator: no geographic note.
  Decompose2dOptions decompose;
  decompose.tau = 0.01 * radii[0];
  const Decomposition2d decomposition = Decompose2d(polygons, decompose);
  EXPECT_GE(decomposition.components.size(), polygons.size());
  const DecompositionCheck check = CheckDecomposition(polygons, decomposition);
  EXPECT_TRUE(check.ok()) << check.problems.front();
}

TEST(GeoPackageReaderTest, ALayerOfPointsIsNoPolygonLayer) {
  EXPECT_THAT(InputErrorOf([] { ReadPolygons((kGeoPackages / "b_pump.gpkg").string()); }),
              HasSubstr("b_pump.gpkg: no layer of polygons (its layers: b_pump, of points or "
                        "lines)"));
}

TEST(GeoPackageReaderTest, ChoosesTheOnlyPolygonLayerOrTheOneNamed) {
  const acdplan::test::ScratchDir dir;
  const std::string path = WriteGeoPackage(
      dir, "city.gpkg",
      {{"parks", "POLYGON", {PolygonBlob({kSquare})}},
       {"lakes", "MULTIPOLYGON", {PolygonBlob({kSquare, kHole}), PolygonBlob({kHole})}},
       {"wells", "POINT", {GeoPackageBlob(WkbWriter().Header(1).Double(1).Double(2).bytes())}}});
  EXPECT_THAT(InputErrorOf([&] { ReadPolygons(path); }),
              HasSubstr("city.gpkg: holds 2 layers of polygons (parks, lakes): name one as " +
                        path + "|layername=NAME"));
  const std::vector<Polygon2d> lakes = ReadPolygons(path + "|layername=LAKES");
  ASSERT_EQ(lakes.size(), 2u);
  EXPECT_EQ(lakes[0].holes.size(), 1u);
  EXPECT_THAT(InputErrorOf([&] { ReadPolygons(path + "|layername=roads"); }),
              HasSubstr("city.gpkg: no feature layer 'roads' (its layers: parks, lakes, wells)"));
  // A layer of points named: its points have no area.
  EXPECT_THAT(InputErrorOf([&] { ReadPolygons(path + "|layername=wells"); }),
              HasSubstr("city.gpkg: layer 'wells': feature 0 (fid 10): a Point has no area"));
  EXPECT_TRUE(IsPolygonFile(path + "|layername=parks"));
  EXPECT_THAT(
      InputErrorOf([&] { ReadPolygons(dir.Write("a.wkt", "POLYGON EMPTY") + "|layername=x"); }),
      HasSubstr("'|layername=' names a layer of a GeoPackage (.gpkg) file only"));

  const acdplan::test::ScratchDir one;
  const std::string single = WriteGeoPackage(
      one, "one.gpkg",
      {{"parks", "POLYGON", {PolygonBlob({kSquare})}},
       {"wells", "POINT", {GeoPackageBlob(WkbWriter().Header(1).Double(1).Double(2).bytes())}}});
  EXPECT_EQ(ReadPolygons(single).size(), 1u);  // The only layer of polygons.
}

TEST(GeoPackageReaderTest, ReadsEveryHeaderFormAndSkipsEmptyGeometries) {
  const acdplan::test::ScratchDir dir;
  const std::string wkb = WkbWriter(false).Polygon({kSquare, kHole}).bytes();
  const std::string path = WriteGeoPackage(
      dir, "forms.gpkg",
      {{"shapes",
        "GEOMETRY",
        {GeoPackageBlob(wkb, 0), GeoPackageBlob(wkb, 1, false), GeoPackageBlob(wkb, 2),
         GeoPackageBlob(wkb, 3, false), GeoPackageBlob(wkb, 4), std::nullopt,
         GeoPackageBlob(WkbWriter().Header(3).Word(0).bytes(), 1, true, /*empty=*/true)}}},
      4326);
  std::vector<int> features;
  std::vector<std::string> properties, notes;
  ReadPolygonsOptions options;
  options.features = &features;
  options.feature_properties = &properties;
  options.notes = &notes;
  const std::vector<Polygon2d> polygons = ReadPolygons(path, nullptr, options);
  ASSERT_EQ(polygons.size(), 5u);
  for (const Polygon2d& polygon : polygons) EXPECT_DOUBLE_EQ(Area(polygon), 15.0);
  EXPECT_EQ(features, (std::vector<int>{0, 1, 2, 3, 4}));
  ASSERT_EQ(properties.size(), 7u);  // Features without a polygon keep their attributes.
  EXPECT_EQ(properties[6], R"({"name":"row 6"})");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(notes[0], HasSubstr("forms.gpkg: layer 'shapes': geographic coordinates (GEOGCS "
                                  "\"WGS 84\")"));
}

TEST(GeoPackageReaderTest, SkipsPointsAndLinesWithANoteWhenAsked) {
  const acdplan::test::ScratchDir dir;
  const std::string path =
      WriteGeoPackage(dir, "mixed.gpkg",
                      {{"things",
                        "GEOMETRY",
                        {PolygonBlob({kSquare}),
                         GeoPackageBlob(WkbWriter().Header(2).Points({{0, 0}, {1, 1}}).bytes()),
                         GeoPackageBlob(WkbWriter().Header(1).Double(1).Double(2).bytes()),
                         GeoPackageBlob(WkbWriter().Header(2).Points({{0, 0}, {2, 1}}).bytes())}}});
  EXPECT_THAT(InputErrorOf([&] { ReadPolygons(path); }),
              HasSubstr("mixed.gpkg: layer 'things': feature 1 (fid 11): a LineString has no "
                        "area"));
  std::vector<std::string> notes;
  ReadPolygonsOptions options;
  options.skip_non_areal = true;
  options.notes = &notes;
  EXPECT_EQ(ReadPolygons(path, nullptr, options).size(), 1u);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(notes[0], HasSubstr("mixed.gpkg: layer 'things': skipped 3 geometries without area "
                                  "(2 LineString, 1 Point; the first at feature 1 (fid 11))"));
}

TEST(GeoPackageReaderTest, ErrorsNameTheFileLayerAndFeature) {
  const acdplan::test::ScratchDir dir;
  std::string bad_envelope = PolygonBlob({kSquare});
  bad_envelope[3] = static_cast<char>(1 | (5 << 1));
  std::string extended = PolygonBlob({kSquare});
  extended[3] = static_cast<char>(extended[3] | 0x20);
  const std::string wkb = WkbWriter().Polygon({kSquare}).bytes();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"WKB" + wkb.substr(3), "feature 0 (fid 10): the geometry is no GeoPackageBinary"},
      {bad_envelope, "feature 0 (fid 10): GeoPackageBinary envelope kind 5 (expected 0 - 4)"},
      {extended, "feature 0 (fid 10): an extended geometry type"},
      {GeoPackageBlob(wkb.substr(0, 20)), "feature 0 (fid 10): WKB byte 9: truncated"},
      {GeoPackageBlob(wkb, 4).substr(0, 40),
       "feature 0 (fid 10): truncated GeoPackageBinary: its header and envelope need 72 bytes, "
       "the geometry has 40"}};
  for (size_t k = 0; k < cases.size(); ++k) {
    const std::string path = WriteGeoPackage(dir, "bad" + std::to_string(k) + ".gpkg",
                                             {{"layer", "POLYGON", {cases[k].first}}});
    EXPECT_THAT(InputErrorOf([&] { ReadPolygons(path); }),
                HasSubstr("bad" + std::to_string(k) + ".gpkg: layer 'layer': " + cases[k].second))
        << k;
  }
  // Files that are no GeoPackage.
  EXPECT_THAT(
      InputErrorOf([&] { ReadPolygons(dir.Write("text.gpkg", "POLYGON ((0 0, 1 0, 0 1, 0 0))")); }),
      HasSubstr("text.gpkg: not a readable GeoPackage: file is not a database"));
  const std::string plain = dir.Path("plain.gpkg");
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(plain.c_str(), &db), SQLITE_OK);
  Exec(db, "CREATE TABLE t (x INTEGER)");
  sqlite3_close(db);
  EXPECT_THAT(InputErrorOf([&] { ReadPolygons(plain); }),
              HasSubstr("plain.gpkg: not a GeoPackage (an SQLite database without the tables "
                        "gpkg_contents and gpkg_geometry_columns)"));
  EXPECT_THAT(InputErrorOf([&] { ReadPolygons(dir.Path("missing.gpkg")); }),
              HasSubstr("missing.gpkg"));
}

// A file left in write-ahead-log mode (as QGIS leaves one it edits) reads from its path and from
// its bytes alike (ReadGeoPackageBytes(), the fuzzers' entry), as does a GDAL-written one.
TEST(GeoPackageReaderTest, ReadsFromTheBytesAsFromTheFileAlsoInWalMode) {
  const acdplan::test::ScratchDir dir;
  const std::string path = WriteGeoPackage(
      dir, "wal.gpkg", {{"parks", "POLYGON", {PolygonBlob({kSquare, kHole})}}}, -1, /*wal=*/true);
  const std::string bytes = ReadFile(path);
  ASSERT_EQ(bytes[18], 2);  // The header says WAL.
  const GeoPackageLayer from_file = ReadGeoPackage(path, "", false, true);
  const GeoPackageLayer from_bytes = ReadGeoPackageBytes(bytes, "wal.gpkg", "", false, true);
  ASSERT_EQ(from_file.polygons.size(), 1u);
  ASSERT_EQ(from_bytes.polygons.size(), 1u);
  EXPECT_EQ(from_bytes.polygons[0].outer, from_file.polygons[0].outer);
  EXPECT_EQ(from_bytes.properties, from_file.properties);
  const std::string nc = (kGeoPackages / "nc.gpkg").string();
  const GeoPackageLayer nc_bytes = ReadGeoPackageBytes(ReadFile(nc), "nc.gpkg", "", false, false);
  EXPECT_EQ(nc_bytes.polygons.size(), ReadGeoPackage(nc, "", false, false).polygons.size());
  EXPECT_EQ(nc_bytes.name, "nc.gpkg");
}

}  // namespace
}  // namespace acdplan::acd
