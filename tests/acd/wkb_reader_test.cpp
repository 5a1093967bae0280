#include "acd/wkb_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "tests/acd/wkb_fixtures.h"
#include "tests/input_error_of.h"

namespace acdplan::acd {
namespace {

using acdplan::test::InputErrorOf;
using acdplan::test::WkbWriter;
using ::testing::HasSubstr;

const Ring2d kSquare = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
const Ring2d kHole = {{1, 1}, {1, 2}, {2, 2}, {2, 1}};
const Ring2d kFar = {{10, 0}, {12, 0}, {12, 2}};

WkbPolygons ReadBytes(const std::string& bytes) {
  return ReadWkb(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), "t");
}

TEST(WkbReaderTest, ReadsAPolygonWithAHoleInEitherByteOrder) {
  for (const bool little : {true, false}) {
    const WkbPolygons read = ReadBytes(WkbWriter(little).Polygon({kSquare, kHole}).bytes());
    ASSERT_EQ(read.polygons.size(), 1u) << little;
    EXPECT_EQ(read.polygons[0].outer, kSquare);  // The closing point dropped.
    ASSERT_EQ(read.polygons[0].holes.size(), 1u);
    EXPECT_EQ(read.polygons[0].holes[0], kHole);
    EXPECT_EQ(read.multipolygons, std::vector<int>{-1});
    EXPECT_EQ(read.unclosed_rings, 0);
    EXPECT_TRUE(read.non_areal.empty());
  }
}

TEST(WkbReaderTest, IgnoresZAndMInIsoAndExtendedForms) {
  // ISO: 1003 (z), 2003 (m), 3003 (z and m); PostGIS: the z flag, and the SRID flag with its
  // SRID before the rings.
  for (const auto& [type, extra] :
       std::vector<std::pair<std::uint32_t, int>>{{1003, 1}, {2003, 1}, {3003, 2}}) {
    const WkbPolygons read = ReadBytes(WkbWriter().Polygon({kSquare}, type, extra).bytes());
    ASSERT_EQ(read.polygons.size(), 1u) << type;
    EXPECT_EQ(read.polygons[0].outer, kSquare) << type;
  }
  WkbWriter ewkb(false);
  ewkb.Header(0x80000000u | 0x20000000u | 3).Word(4326).Word(1).Ring(kSquare, 1);
  const WkbPolygons read = ReadBytes(ewkb.bytes());
  ASSERT_EQ(read.polygons.size(), 1u);
  EXPECT_EQ(read.polygons[0].outer, kSquare);
}

TEST(WkbReaderTest, GroupsMultiPolygonMembersAndListsWhatHasNoArea) {
  // A collection: a Polygon, a MultiPolygon of two (one big-endian inside a little-endian
  // whole), a LineString and a Point; then an empty Polygon.
  WkbWriter wkb;
  wkb.Header(7).Word(5);
  wkb.Polygon({kSquare});
  wkb.Header(6).Word(2).Polygon({kFar}).Raw(WkbWriter(false).Polygon({kSquare, kHole}).bytes());
  wkb.Header(2).Points({{0, 0}, {1, 1}});
  wkb.Header(1).Double(3).Double(4);
  wkb.Header(3).Word(0);
  const WkbPolygons read = ReadBytes(wkb.bytes());
  ASSERT_EQ(read.polygons.size(), 3u);
  EXPECT_EQ(read.multipolygons, (std::vector<int>{-1, 0, 0}));
  EXPECT_EQ(read.polygons[1].outer, kFar);
  EXPECT_EQ(read.polygons[2].holes.size(), 1u);
  EXPECT_EQ(read.non_areal,
            (std::vector<std::pair<std::string, int>>{{"LineString", 1}, {"Point", 1}}));
}

TEST(WkbReaderTest, ReadsStraightCurvePolygonsAndRefusesCurvedRings) {
  // A MultiSurface of a CurvePolygon whose rings are LineStrings, and of a Polygon.
  WkbWriter surface;
  surface.Header(12).Word(2);
  surface.Header(10).Word(2);
  surface.Header(2).Ring(kSquare);
  surface.Header(2).Ring(kHole);
  surface.Polygon({kFar});
  const WkbPolygons read = ReadBytes(surface.bytes());
  ASSERT_EQ(read.polygons.size(), 2u);
  EXPECT_EQ(read.polygons[0].holes.size(), 1u);
  EXPECT_EQ(read.multipolygons, (std::vector<int>{0, 0}));

  WkbWriter arc;
  arc.Header(10).Word(1).Header(8).Points({{0, 0}, {1, 1}, {2, 0}, {1, -1}, {0, 0}});
  EXPECT_THAT(InputErrorOf([&] { ReadBytes(arc.bytes()); }),
              HasSubstr("t: WKB byte 9: curved ring (CircularString): linearize it first"));
}

TEST(WkbReaderTest, TakesAnUnclosedRingAsItIsAndCountsIt) {
  WkbWriter wkb;
  wkb.Header(3).Word(1).Points(kSquare);  // Four points, no closing one.
  const WkbPolygons read = ReadBytes(wkb.bytes());
  ASSERT_EQ(read.polygons.size(), 1u);
  EXPECT_EQ(read.polygons[0].outer, kSquare);
  EXPECT_EQ(read.unclosed_rings, 1);
}

TEST(WkbReaderTest, EveryTruncationIsAnErrorNamingTheByte) {
  WkbWriter wkb;
  wkb.Header(6).Word(2).Polygon({kSquare, kHole}).Polygon({kFar}, 1003, 1);
  const std::string bytes = wkb.bytes();
  for (size_t size = 0; size < bytes.size(); ++size) {
    EXPECT_THAT(InputErrorOf([&] { ReadBytes(bytes.substr(0, size)); }), HasSubstr("truncated"))
        << size;
  }
  EXPECT_THAT(InputErrorOf([&] { ReadBytes(bytes + "x"); }),
              HasSubstr("WKB byte " + std::to_string(bytes.size()) + ": 1 bytes after"));
}

TEST(WkbReaderTest, RefusesWhatBreaksTheFormat) {
  // A count far beyond the bytes left fails before anything that large is allocated.
  WkbWriter huge;
  huge.Header(3).Word(1).Word(0xFFFFFFFFu);
  EXPECT_THAT(InputErrorOf([&] { ReadBytes(huge.bytes()); }),
              HasSubstr("WKB byte 9: truncated: 4294967295 points need at least 16 bytes each"));
  WkbWriter infinite;
  infinite.Header(3).Word(1).Word(1).Double(0).Double(std::numeric_limits<double>::infinity());
  EXPECT_THAT(InputErrorOf([&] { ReadBytes(infinite.bytes()); }),
              HasSubstr("WKB byte 21: non-finite coordinate"));
  EXPECT_THAT(InputErrorOf([&] { ReadBytes(std::string("\x07\x03\0\0\0", 5)); }),
              HasSubstr("WKB byte 0: byte order 7 (expected 0 or 1)"));
  EXPECT_THAT(InputErrorOf([&] { ReadBytes(WkbWriter().Header(99).bytes()); }),
              HasSubstr("unknown geometry type 99"));
  EXPECT_THAT(InputErrorOf([&] { ReadBytes(WkbWriter().Header(16).Word(0).bytes()); }),
              HasSubstr("TIN is a 3D surface"));
  WkbWriter line_in_multipolygon;
  line_in_multipolygon.Header(6).Word(1).Header(2).Points({{0, 0}, {1, 1}});
  EXPECT_THAT(InputErrorOf([&] { ReadBytes(line_in_multipolygon.bytes()); }),
              HasSubstr("WKB byte 9: a MultiPolygon cannot hold a LineString"));
  WkbWriter deep;
  for (int k = 0; k < 40; ++k) deep.Header(7).Word(1);
  deep.Polygon({kSquare});
  EXPECT_THAT(InputErrorOf([&] { ReadBytes(deep.bytes()); }), HasSubstr("nested deeper than 32"));
  WkbWriter holes_only;
  holes_only.Header(3).Word(2).Word(0).Ring(kHole);
  EXPECT_THAT(InputErrorOf([&] { ReadBytes(holes_only.bytes()); }),
              HasSubstr("a polygon with holes but no exterior ring"));
}

}  // namespace
}  // namespace acdplan::acd
