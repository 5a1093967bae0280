#include "acd/kml_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <zip.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "acd/check_decomposition.h"
#include "acd/decompose2d.h"
#include "acd/read_polygons.h"
#include "base/file_io.h"
#include "tests/data_paths.h"
#include "tests/input_error_of.h"
#include "tests/scratch_dir.h"

namespace acdplan::acd {
namespace {

using acdplan::test::InputErrorOf;
using ::testing::HasSubstr;

const std::string kKmlSamples =
    (std::filesystem::path(acdplan::test::DataDir()) / "polygons" / "kml" / "kmlsamples.kml")
        .string();

std::vector<Polygon2d> ParseKml(const std::string& text, KmlExtras* extras = nullptr,
                                bool skip_non_areal = true) {
  std::istringstream in(text);
  return ReadKml(in, "t.kml", skip_non_areal, extras);
}

// Google's KML samples (libkml's copy): 20 Placemarks, 9 of them with a Polygon, among
// points, paths, overlays and styles.
TEST(KmlReaderTest, ReadsThePolygonsOfGooglesSamples) {
  std::vector<std::string> notes, properties;
  std::vector<int> features;
  std::vector<double> radii;
  ReadPolygonsOptions options;
  options.notes = &notes;
  options.features = &features;
  options.feature_properties = &properties;
  options.skip_non_areal = true;
  const std::vector<Polygon2d> polygons = ReadPolygons(kKmlSamples, &radii, options);
  ASSERT_EQ(polygons.size(), 9u);
  ASSERT_EQ(properties.size(), 20u);
  int with_hole = -1;
  for (size_t k = 0; k < polygons.size(); ++k) {
    if (!polygons[k].holes.empty()) with_hole = static_cast<int>(k);
  }
  ASSERT_GE(with_hole, 0);
  const nlohmann::json pentagon = nlohmann::json::parse(properties[features[with_hole]]);
  EXPECT_EQ(pentagon.at("name"), "The Pentagon");
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_THAT(notes[0], HasSubstr("kmlsamples.kml: skipped 10 geometries without area (6 "
                                  "LineString, 4 Point; the first at line 126)"));
  EXPECT_THAT(notes[1], HasSubstr("kmlsamples.kml: geographic coordinates (GEOGCS \"WGS 84\")"));
  // Without skipping, the first point is an error naming its line.
  EXPECT_THAT(InputErrorOf([] { ReadPolygons(kKmlSamples); }),
              HasSubstr("kmlsamples.kml:126: a Point has no area"));

  Decompose2dOptions decompose;
  decompose.tau = 0.01 * radii[0];
  const Decomposition2d decomposition = Decompose2d(polygons, decompose);
  const DecompositionCheck check = CheckDecomposition(polygons, decomposition);
  EXPECT_TRUE(check.ok()) << check.problems.front();
}

TEST(KmlReaderTest, ReadsPrefixedMultiGeometriesAndTheirAttributes) {
  const std::string text = R"(<?xml version="1.0" encoding="UTF-8"?>
<kml:kml xmlns:kml="http://www.opengis.net/kml/2.2"><kml:Document><kml:Folder>
  <kml:Placemark>
    <kml:name>lots</kml:name>
    <kml:ExtendedData>
      <kml:Data name="owner"><kml:displayName>Owner</kml:displayName><kml:value>city</kml:value></kml:Data>
      <kml:SchemaData schemaUrl="#s"><kml:SimpleData name="zone">R2</kml:SimpleData></kml:SchemaData>
    </kml:ExtendedData>
    <kml:MultiGeometry>
      <kml:Polygon><kml:outerBoundaryIs><kml:LinearRing><kml:coordinates>
        0,0,5 10,0,5
        10,10,5   0,10,5 0,0,5
      </kml:coordinates></kml:LinearRing></kml:outerBoundaryIs>
      <kml:innerBoundaryIs><kml:LinearRing><kml:coordinates>1,1 1,2 2,2 1,1</kml:coordinates></kml:LinearRing>
        <kml:LinearRing><kml:coordinates>5, 5 5, 6 6, 6 5, 5</kml:coordinates></kml:LinearRing></kml:innerBoundaryIs>
      </kml:Polygon>
      <kml:Polygon><kml:outerBoundaryIs><kml:LinearRing><kml:coordinates>20,0 30,0 30,10</kml:coordinates></kml:LinearRing></kml:outerBoundaryIs></kml:Polygon>
    </kml:MultiGeometry>
  </kml:Placemark>
  <kml:Placemark><kml:Point><kml:coordinates>3,3</kml:coordinates></kml:Point></kml:Placemark>
</kml:Folder></kml:Document></kml:kml>
)";
  KmlExtras extras;
  const std::vector<Polygon2d> polygons = ParseKml(text, &extras);
  ASSERT_EQ(polygons.size(), 2u);
  EXPECT_EQ(polygons[0].outer, (Ring2d{{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
  ASSERT_EQ(polygons[0].holes.size(), 2u);
  EXPECT_EQ(polygons[0].holes[1], (Ring2d{{5, 5}, {5, 6}, {6, 6}}));
  EXPECT_EQ(polygons[1].outer, (Ring2d{{20, 0}, {30, 0}, {30, 10}}));  // Taken unclosed.
  EXPECT_EQ(extras.features, (std::vector<int>{0, 0}));
  ASSERT_EQ(extras.properties.size(), 2u);
  EXPECT_EQ(extras.properties[0], R"({"name":"lots","owner":"city","zone":"R2"})");
  EXPECT_EQ(extras.properties[1], "{}");
  ASSERT_EQ(extras.warnings.size(), 2u);
  EXPECT_EQ(extras.warnings[0],
            "t.kml: skipped 1 geometry without area (1 Point; the first at line 20)");
  EXPECT_EQ(extras.warnings[1],
            "t.kml:17: a ring without its closing point, taken as it is (1 in the file)");
}

TEST(KmlReaderTest, ReadsAFragmentAndAPolygonOutsideAPlacemark) {
  KmlExtras extras;
  const std::vector<Polygon2d> polygons = ParseKml(
      "<Document><Polygon><outerBoundaryIs><LinearRing><coordinates>0,0 1,0 1,1 0,0"
      "</coordinates></LinearRing></outerBoundaryIs></Polygon></Document>",
      &extras);
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(extras.features, std::vector<int>{0});
  EXPECT_EQ(extras.properties, std::vector<std::string>{"{}"});
}

TEST(KmlReaderTest, ErrorsNameTheLineAndTheRule) {
  const std::string head =
      "<kml>\n<Placemark><Polygon><outerBoundaryIs><LinearRing>\n<coordinates>";
  const std::string tail =
      "</coordinates></LinearRing></outerBoundaryIs></Polygon></Placemark></kml>";
  EXPECT_THAT(InputErrorOf([&] { ParseKml(head + "0,0 1,x 1,1 0,0" + tail); }),
              HasSubstr("t.kml:3: coordinates: malformed number 'x'"));
  EXPECT_THAT(InputErrorOf([&] { ParseKml(head + "0,0 1 1,1 0,0" + tail); }),
              HasSubstr("t.kml:3: coordinates: tuple '1' has fewer than 2 numbers"));
  EXPECT_THAT(InputErrorOf([&] { ParseKml(head + "0,0 1,1,1,1 1,1 0,0" + tail); }),
              HasSubstr("t.kml:3: coordinates: tuple '1,1,1,1' has more than 3 numbers"));
  EXPECT_THAT(InputErrorOf([&] { ParseKml(head + "0,0 1,nan 1,1 0,0" + tail); }),
              HasSubstr("t.kml:3: coordinates: non-finite number 'nan'"));
  EXPECT_THAT(InputErrorOf([&] { ParseKml(head + "0,0 1,0 1,1 0,0</coordinates></Polygon>"); }),
              HasSubstr("t.kml:3: malformed XML: mismatched tag"));
  EXPECT_THAT(InputErrorOf([&] { ParseKml(""); }), HasSubstr("t.kml:1: malformed XML"));
  EXPECT_THAT(InputErrorOf([&] { ParseKml("<svg><Polygon/></svg>"); }),
              HasSubstr("t.kml:1: not KML: the root element is <svg>, not <kml>"));
  EXPECT_THAT(InputErrorOf([&] {
                ParseKml(
                    "<kml><Polygon>\n<innerBoundaryIs><LinearRing><coordinates>0,0 1,0 1,1 "
                    "0,0</coordinates></LinearRing></innerBoundaryIs></Polygon></kml>");
              }),
              HasSubstr("t.kml:1: a Polygon with inner boundaries but no outer one"));
  EXPECT_THAT(InputErrorOf([&] {
                ParseKml(
                    "<kml>\n<Placemark><LineString><coordinates>0,0 1,1</coordinates>"
                    "</LineString></Placemark></kml>",
                    nullptr, /*skip_non_areal=*/false);
              }),
              HasSubstr("t.kml:2: a LineString has no area"));
}

// Writes a zip archive of `entries` (name, content), deflated, as Google Earth writes a KMZ.
std::string WriteZip(const std::string& path,
                     const std::vector<std::pair<std::string, std::string>>& entries) {
  zipFile zip = zipOpen64(path.c_str(), APPEND_STATUS_CREATE);
  EXPECT_NE(zip, nullptr);
  for (const auto& [name, content] : entries) {
    EXPECT_EQ(zipOpenNewFileInZip64(zip, name.c_str(), nullptr, nullptr, 0, nullptr, 0, nullptr,
                                    Z_DEFLATED, Z_DEFAULT_COMPRESSION, 0),
              ZIP_OK);
    EXPECT_EQ(zipWriteInFileInZip(zip, content.data(), static_cast<unsigned>(content.size())),
              ZIP_OK);
    EXPECT_EQ(zipCloseFileInZip(zip), ZIP_OK);
  }
  EXPECT_EQ(zipClose(zip, nullptr), ZIP_OK);
  return path;
}

// A KMZ (Google Earth's "Save Place As" default) reads as the first .kml inside it.
TEST(KmlReaderTest, ReadsTheRootKmlOfAKmz) {
  const acdplan::test::ScratchDir dir;
  const std::string kml = ReadFile(kKmlSamples);
  const std::string kmz =
      WriteZip(dir.Path("samples.KMZ"), {{"files/icon.png", "not a picture"}, {"doc.kml", kml}});
  std::vector<std::string> notes;
  ReadPolygonsOptions options;
  options.skip_non_areal = true;
  options.notes = &notes;
  const std::vector<Polygon2d> from_kmz = ReadPolygons(kmz, nullptr, options);
  EXPECT_EQ(from_kmz.size(), ReadPolygons(kKmlSamples, nullptr, options).size());
  ASSERT_FALSE(notes.empty());
  EXPECT_THAT(notes[0], HasSubstr("samples.KMZ/doc.kml: skipped 10 geometries"));
  EXPECT_THAT(InputErrorOf([&] { ReadPolygons(kmz); }),
              HasSubstr("samples.KMZ/doc.kml:126: a Point has no area"));

  const std::string no_kml = WriteZip(dir.Path("pictures.kmz"), {{"a.png", "x"}});
  EXPECT_THAT(InputErrorOf([&] { ReadPolygons(no_kml); }),
              HasSubstr("pictures.kmz: no .kml entry in the KMZ archive"));
  EXPECT_THAT(InputErrorOf([&] { ReadPolygons(dir.Write("text.kmz", kml)); }),
              HasSubstr("text.kmz: not a KMZ (not a readable zip archive)"));
  // A stored entry whose bytes were changed fails its CRC.
  const std::string stored = dir.Path("stored.kmz");
  {
    zipFile zip = zipOpen64(stored.c_str(), APPEND_STATUS_CREATE);
    ASSERT_EQ(
        zipOpenNewFileInZip64(zip, "doc.kml", nullptr, nullptr, 0, nullptr, 0, nullptr, 0, 0, 0),
        ZIP_OK);
    ASSERT_EQ(zipWriteInFileInZip(zip, kml.data(), static_cast<unsigned>(kml.size())), ZIP_OK);
    zipCloseFileInZip(zip);
    zipClose(zip, nullptr);
  }
  std::string bytes = ReadFile(stored);
  const size_t at = bytes.find("<kml");
  ASSERT_NE(at, std::string::npos);
  bytes[at + 1] = 'K';
  const std::string damaged = dir.Write("damaged.kmz", bytes);
  EXPECT_THAT(InputErrorOf([&] { ReadPolygons(damaged); }),
              HasSubstr("damaged.kmz/doc.kml: damaged entry"));
}

}  // namespace
}  // namespace acdplan::acd
