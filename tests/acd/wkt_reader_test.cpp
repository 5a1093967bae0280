#include "acd/wkt_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "base/input_error.h"
#include "tests/input_error_of.h"

namespace acdplan::acd {
namespace {

using ::testing::HasSubstr;

std::vector<Polygon2d> WktOf(const std::string& text) {
  std::istringstream in(text);
  return ReadWkt(in, "shape.wkt");
}

std::string WktErrorOf(const std::string& text) {
  return acdplan::test::InputErrorOf([&] { WktOf(text); });
}

TEST(WktReaderTest, ReadsPolygonWithHoleDroppingClosingPoints) {
  const std::vector<Polygon2d> polygons =
      WktOf("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1))");
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(polygons[0].outer, Ring2d({{0, 0}, {4, 0}, {4, 4}, {0, 4}}));
  ASSERT_EQ(polygons[0].holes.size(), 1u);
  EXPECT_EQ(polygons[0].holes[0], Ring2d({{1, 1}, {1, 2}, {2, 2}, {2, 1}}));
}

TEST(WktReaderTest, ReadsMultiPolygonCollectionCaseAndZ) {
  const std::vector<Polygon2d> polygons = WktOf(
      "multipolygon (((0 0, 1 0, 1 1, 0 0)), ((5 5, 6 5, 6 6, 5 5), (5.2 5.1, 5.8 5.1, 5.8 5.7, "
      "5.2 5.1)))\n"
      "GEOMETRYCOLLECTION (POLYGON Z ((0 0 1, 1e1 0 1, 10 +10 1, 0 0 1)), POLYGON EMPTY)\n"
      "POLYGON EMPTY");
  ASSERT_EQ(polygons.size(), 3u);
  EXPECT_EQ(polygons[0].outer.size(), 3u);
  EXPECT_EQ(polygons[1].holes.size(), 1u);
  EXPECT_EQ(polygons[2].outer, Ring2d({{0, 0}, {10, 0}, {10, 10}}));
}

TEST(WktReaderTest, SaysWhichMultipolygonEachPolygonBelongsTo) {
  std::istringstream in(
      "POLYGON ((0 0, 1 0, 1 1, 0 0)) MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)), EMPTY, ((5 5, 6 5, "
      "6 6, 5 5))) GEOMETRYCOLLECTION (MULTIPOLYGON EMPTY, MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0))), "
      "POLYGON ((0 0, 1 0, 1 1, 0 0)))");
  std::vector<int> multipolygons;
  EXPECT_EQ(ReadWkt(in, "test.wkt", &multipolygons).size(), 5u);
  EXPECT_EQ(multipolygons, std::vector<int>({-1, 0, 0, 1, -1}));
}

TEST(WktReaderTest, ReadsPostgisEwktAndEmptyMembers) {
  // ST_AsEWKT's SRID prefix, and EMPTY polygons inside a MULTIPOLYGON (OGC 06-103r4, 7.2.4).
  const std::vector<Polygon2d> polygons = WktOf(
      "SRID=4326;MULTIPOLYGON (EMPTY, ((0 0, 1 0, 1 1, 0 0)), EMPTY)\n"
      "srid=3857 ; POLYGON ((5 5, 6 5, 6 6, 5 5))");
  ASSERT_EQ(polygons.size(), 2u);
  EXPECT_EQ(polygons[0].outer, Ring2d({{0, 0}, {1, 0}, {1, 1}}));
  EXPECT_EQ(polygons[1].outer, Ring2d({{5, 5}, {6, 5}, {6, 6}}));
  // A UTF-8 byte order mark before the text.
  EXPECT_EQ(WktOf("\xEF\xBB\xBFPOLYGON ((0 0, 1 0, 1 1, 0 0))").size(), 1u);
  EXPECT_THAT(WktErrorOf("SRID=x;POLYGON EMPTY"),
              HasSubstr("malformed SRID (expected SRID=<integer>;) at line 1, column 1, found "
                        "'SRID=x'"));
  EXPECT_THAT(WktErrorOf("SRID=4326 POLYGON EMPTY"),
              HasSubstr("expected ';' at line 1, column 11, found 'POLYGON'"));
}

// OGC 06-103r4 lets a ring be EMPTY: an empty hole is skipped, an empty exterior ring leaves no
// polygon; holes in an empty polygon are an error (GEOS: "shell is empty but holes are not").
TEST(WktReaderTest, EmptyRingsAreSkipped) {
  const std::vector<Polygon2d> polygons = WktOf(
      "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), EMPTY, (1 1, 1 2, 2 2, 1 1), empty)\n"
      "POLYGON (EMPTY)\nMULTIPOLYGON ((EMPTY), ((5 5, 6 5, 6 6, 5 5)))");
  ASSERT_EQ(polygons.size(), 2u);
  ASSERT_EQ(polygons[0].holes.size(), 1u);
  EXPECT_EQ(polygons[0].holes[0], Ring2d({{1, 1}, {1, 2}, {2, 2}}));
  EXPECT_EQ(polygons[1].outer, Ring2d({{5, 5}, {6, 5}, {6, 6}}));
  EXPECT_THAT(WktErrorOf("POLYGON ( EMPTY, (1 1, 1 2, 2 2, 1 1))"),
              HasSubstr("shape.wkt: a polygon with an EMPTY exterior ring has a hole at line 1, "
                        "column 11, found 'EMPTY'"));
}

TEST(WktReaderTest, SyntaxErrorsNameLineColumnAndRule) {
  EXPECT_THAT(WktErrorOf("POLYGON 0 0, 1 0"),
              HasSubstr("shape.wkt: expected '(' at line 1, column 9, found '0'"));
  EXPECT_THAT(WktErrorOf("POLYGON ((0 0, 1 0, 1 1, 0 0)\n"),
              HasSubstr("shape.wkt: expected ',' or ')' after a ring at line 2, column 1, "
                        "found end of input"));
  EXPECT_THAT(WktErrorOf("\nLINESTRING (0 0, 1 1)"),
              HasSubstr("expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION (other geometry "
                        "types are not supported) at line 2, column 1, found 'LINESTRING'"));
  EXPECT_THAT(WktErrorOf(""), HasSubstr("shape.wkt: expected POLYGON"));
  EXPECT_THAT(WktErrorOf("POLYGON ((0 0 1 2 3, 1 0, 1 1, 0 0))"),
              HasSubstr("more than 4 coordinates in a point at line 1, column 19"));
  EXPECT_THAT(WktErrorOf("POLYGON ((0 0, 1, 1 1, 0 0))"),
              HasSubstr("expected a point: two numbers 'x y' at line 1, column 17"));
}

TEST(WktReaderTest, NumberErrorsNamePosition) {
  EXPECT_THAT(WktErrorOf("POLYGON ((0 0, 1 0.5.5, 1 1, 0 0))"),
              HasSubstr("shape.wkt: malformed number '0.5.5' at line 1, column 18"));
  EXPECT_THAT(WktErrorOf("POLYGON ((0 0, 1 nan, 1 1, 0 0))"),
              HasSubstr("non-finite number 'nan' at line 1, column 18"));
}

TEST(WktReaderTest, UnclosedRingIsAnError) {
  EXPECT_THAT(WktErrorOf("POLYGON ((0 0, 1 0, 1 1))"),
              HasSubstr("ring is not closed (its last point must repeat its first point (0, 0)) "
                        "at line 1, column 11"));
}

}  // namespace
}  // namespace acdplan::acd
