#include "acd/shapefile_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "acd/check_decomposition.h"
#include "acd/decompose2d.h"
#include "acd/read_polygons.h"
#include "base/input_error.h"
#include "tests/data_paths.h"
#include "tests/input_error_of.h"
#include "tests/polygon_fixtures.h"

namespace acdplan::acd {
namespace {

using ::testing::HasSubstr;

using acdplan::test::kShapefiles;

// A polygon record as a writer lays it out: its parts as written (closing points included).
struct Record {
  std::vector<Ring2d> parts;
  int type = 5;  // Polygon; 15 PolygonZ (a z per point follows), 0 null.
};

void AppendBigEndian(std::int32_t value, std::string* out) {
  for (int shift = 24; shift >= 0; shift -= 8) out->push_back(static_cast<char>(value >> shift));
}
void AppendLittleEndian(std::int32_t value, std::string* out) {
  for (int shift = 0; shift <= 24; shift += 8) out->push_back(static_cast<char>(value >> shift));
}
void AppendDouble(double value, std::string* out) {
  char bytes[8];
  std::memcpy(bytes, &value, 8);  // Little-endian hosts only, as the tests run on.
  out->append(bytes, 8);
}

// The .shp bytes of `records` in a file of shape type `file_type`.
std::string Shapefile(const std::vector<Record>& records, std::int32_t file_type = 5) {
  std::string body;
  int number = 0;
  for (const Record& record : records) {
    std::string content;
    AppendLittleEndian(record.type, &content);
    if (record.type != 0) {
      for (int k = 0; k < 4; ++k) AppendDouble(0.0, &content);  // The box: not read.
      std::int32_t points = 0;
      for (const Ring2d& part : record.parts) points += static_cast<std::int32_t>(part.size());
      AppendLittleEndian(static_cast<std::int32_t>(record.parts.size()), &content);
      AppendLittleEndian(points, &content);
      std::int32_t start = 0;
      for (const Ring2d& part : record.parts) {
        AppendLittleEndian(start, &content);
        start += static_cast<std::int32_t>(part.size());
      }
      for (const Ring2d& part : record.parts) {
        for (const Point2d& p : part) AppendDouble(p.x(), &content), AppendDouble(p.y(), &content);
      }
      if (record.type == 15) {
        for (int k = 0; k < 2 + points; ++k) AppendDouble(7.0, &content);  // z range, z values
      }
    }
    AppendBigEndian(++number, &body);
    AppendBigEndian(static_cast<std::int32_t>(content.size() / 2), &body);
    body += content;
  }
  std::string file;
  AppendBigEndian(9994, &file);
  for (int k = 0; k < 5; ++k) AppendBigEndian(0, &file);
  AppendBigEndian(static_cast<std::int32_t>((100 + body.size()) / 2), &file);
  AppendLittleEndian(1000, &file);
  AppendLittleEndian(file_type, &file);
  for (int k = 0; k < 8; ++k) AppendDouble(0.0, &file);  // Bounding box and z, m ranges.
  return file + body;
}

// A square ring from (x, y) with side `side`, closed, clockwise (the format's outer rings) or
// counter-clockwise (its holes).
Ring2d Square(double x, double y, double side, bool clockwise) {
  Ring2d ring = acdplan::test::SquareRing(x, y, side);  // Counter-clockwise.
  ring.push_back(ring.front());
  return clockwise ? Reversed(ring) : ring;
}

std::vector<Polygon2d> Read(const std::string& bytes, std::vector<int>* multipolygons = nullptr,
                            std::vector<std::string>* warnings = nullptr) {
  std::istringstream in(bytes);
  return ReadShapefile(in, "parcels.shp", multipolygons, warnings);
}

std::string ErrorOf(const std::string& bytes) {
  return acdplan::test::InputErrorOf([&] { Read(bytes); });
}

TEST(ShapefileReaderTest, GroupsARecordsRingsByNestingIntoAMultiPolygon) {
  // A field (outer), a pond in it (hole), an island in the pond (outer again), and a second
  // field beside: two polygons of one record, the pond the first one's hole.
  const Record record{{Square(0, 0, 10, true), Square(2, 2, 6, false), Square(4, 4, 2, true),
                       Square(20, 0, 3, true)}};
  std::vector<int> multipolygons, features;
  std::istringstream in(Shapefile({{}, record}));
  const std::vector<Polygon2d> polygons =
      ReadShapefile(in, "parcels.shp", &multipolygons, nullptr, &features);
  ASSERT_EQ(polygons.size(), 3u);
  EXPECT_EQ(polygons[0].outer.size(), 4u);  // The closing point is dropped.
  ASSERT_EQ(polygons[0].holes.size(), 1u);
  EXPECT_EQ(polygons[0].holes[0].front(), Point2d(2, 2));
  EXPECT_EQ(polygons[1].outer.front(), Point2d(4, 4));
  EXPECT_TRUE(polygons[1].holes.empty());
  EXPECT_EQ(polygons[2].outer.front(), Point2d(20, 0));
  EXPECT_EQ(multipolygons, (std::vector<int>{2, 2, 2}));  // Record 2 (record 1 has no parts).
  EXPECT_EQ(features, (std::vector<int>{1, 1, 1}));       // Its FID.
}

TEST(ShapefileReaderTest, GroupsARecordOfThousandsOfRings) {
  // A record as a map of many islands stores it: 20 x 20 fields, each with a pond holding an
  // island, 1,200 rings in an order that is not the nesting's (ponds first, then islands, then
  // fields, each by columns from the right).
  Record record;
  for (int kind = 0; kind < 3; ++kind) {
    for (int i = 19; i >= 0; --i) {
      for (int j = 0; j < 20; ++j) {
        const double x = 20.0 * i, y = 20.0 * j;
        if (kind == 0) record.parts.push_back(Square(x + 2, y + 2, 6, false));
        if (kind == 1) record.parts.push_back(Square(x + 4, y + 4, 2, true));
        if (kind == 2) record.parts.push_back(Square(x, y, 10, true));
      }
    }
  }
  const std::vector<Polygon2d> polygons = Read(Shapefile({record}));
  ASSERT_EQ(polygons.size(), 800u);  // 400 fields with their pond, 400 islands.
  // In the order of their outer rings: the islands, then the fields.
  for (size_t k = 0; k < 400; ++k) {
    EXPECT_TRUE(polygons[k].holes.empty());
    ASSERT_EQ(polygons[400 + k].holes.size(), 1u);
    // Field k's pond is ring k of the record, from the same corner.
    EXPECT_EQ(polygons[400 + k].holes[0].front() - polygons[400 + k].outer.front(), Point2d(2, 2));
    EXPECT_EQ(polygons[400 + k].holes[0].front(), record.parts[k].front());
  }
}

TEST(ShapefileReaderTest, NestingDecidesWhereOrientationIsWrongOrRingsTouch) {
  // Outer ring counter-clockwise and hole clockwise, against the format's rule; a second hole
  // touching the outer ring at its corner (10, 10), valid in OGC's rules.
  const Ring2d touching = {{10, 10}, {7, 9}, {9, 7}, {10, 10}};
  const Record record{{Square(0, 0, 10, false), Square(2, 2, 3, true), touching}};
  std::vector<int> multipolygons;
  const std::vector<Polygon2d> polygons = Read(Shapefile({record}), &multipolygons);
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(polygons[0].holes.size(), 2u);
  EXPECT_EQ(multipolygons, (std::vector<int>{-1}));
}

TEST(ShapefileReaderTest, SkipsNullShapesReadsPolygonZAndWarnsOfUnclosedRings) {
  Ring2d open = Square(0, 0, 1, true);
  open.pop_back();
  Record null_record;
  null_record.type = 0;
  Record z_record{{Square(5, 5, 1, true)}};
  z_record.type = 15;
  std::vector<std::string> warnings;
  const std::vector<Polygon2d> polygons =
      Read(Shapefile({null_record, Record{{open}}, Record{{open, open}}}, 5), nullptr, &warnings);
  ASSERT_EQ(polygons.size(), 3u);
  EXPECT_EQ(polygons[0].outer.size(), 4u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_THAT(warnings[0], HasSubstr("parcels.shp: record 2, part 0: ring not closed"));
  EXPECT_THAT(warnings[0], HasSubstr("read as closed (and 2 more rings like it)"));
  const std::vector<Polygon2d> z = Read(Shapefile({null_record, z_record}, 15));
  ASSERT_EQ(z.size(), 1u);
  EXPECT_EQ(z[0].outer.front(), Point2d(5, 5));
}

TEST(ShapefileReaderTest, BadFilesNameTheRuleAndWhere) {
  const std::string good = Shapefile({Record{{Square(0, 0, 1, true)}}});
  EXPECT_THAT(ErrorOf(good.substr(0, 60)), HasSubstr("parcels.shp: not a shapefile: 60 bytes"));
  std::string wrong_code = good;
  wrong_code[3] = 0;
  EXPECT_THAT(ErrorOf(wrong_code), HasSubstr("not a shapefile: file code"));
  EXPECT_THAT(ErrorOf(Shapefile({}, 3)),
              HasSubstr("parcels.shp: holds PolyLine shapes (type 3), not polygons"));
  EXPECT_THAT(ErrorOf(good.substr(0, good.size() - 16)),
              HasSubstr("the header declares 236 bytes, the file holds 220: truncated"));
  Record z_in_polygon_file{{Square(0, 0, 1, true)}};
  z_in_polygon_file.type = 15;
  EXPECT_THAT(ErrorOf(Shapefile({Record{{Square(0, 0, 1, true)}}, z_in_polygon_file})),
              HasSubstr("record 2: shape type PolygonZ (15) differs from the file's, Polygon (5)"));
  // The first part's offset (byte 100 + 8 + 44) made 1: parts must start at point 0.
  std::string offset = good;
  offset[152] = 1;
  EXPECT_THAT(ErrorOf(offset), HasSubstr("record 1, part 0: the first part starts at point 1"));
  // NumPoints (byte 100 + 8 + 40) made 200: more points than the record holds.
  std::string points = good;
  points[148] = static_cast<char>(200);
  EXPECT_THAT(ErrorOf(points), HasSubstr("record 1: NumParts 1 and NumPoints 200 need"));
  // The record's content length made longer than the file: a truncated record.
  std::string length = good;
  length[107] = static_cast<char>(200);
  EXPECT_THAT(ErrorOf(length), HasSubstr("record 1 (byte 100): content length 400 bytes runs "
                                         "past the end of the file (128 bytes left)"));
  const Record nan_record{{{{0, 0}, {0, std::numeric_limits<double>::quiet_NaN()}, {1, 1}}}};
  EXPECT_THAT(ErrorOf(Shapefile({nan_record})),
              HasSubstr("record 1, part 0, point 1: non-finite coordinate"));
}

// Files written by other software: go-shp's test files (a 5 x 5 square as Polygon, PolygonM
// and PolygonZ), and two of R's sf package (the 100 counties of North Carolina, six of them
// with islands; the 470 census tracts of Olinda, Brazil). Their counts were taken with another
// reader (pyshp 2.3.1): parts, and points less the closing ones.
TEST(ShapefileReaderTest, ReadsFilesOfOtherWriters) {
  for (const char* name : {"polygon.shp", "polygonm.shp", "polygonz.shp"}) {
    std::ifstream in(kShapefiles / "go-shp" / name, std::ios::binary);
    const std::vector<Polygon2d> polygons = ReadShapefile(in, name);
    ASSERT_EQ(polygons.size(), 1u) << name;
    EXPECT_EQ(polygons[0].outer, Ring2d({{0, 0}, {0, 5}, {5, 5}, {5, 0}})) << name;
  }
  struct Expected {
    const char* name;
    size_t polygons, vertices, multipolygon_members;
  };
  for (const Expected& e :
       {Expected{"nc.shp", 108, 2421, 14}, Expected{"olinda1.shp", 470, 12235, 0}}) {
    std::ifstream in(kShapefiles / e.name, std::ios::binary);
    std::vector<int> multipolygons;
    const std::vector<Polygon2d> polygons = ReadShapefile(in, e.name, &multipolygons);
    EXPECT_EQ(polygons.size(), e.polygons) << e.name;
    size_t vertices = 0, members = 0;
    for (const Polygon2d& p : polygons) {
      vertices += p.outer.size();
      EXPECT_TRUE(p.holes.empty()) << e.name;
    }
    for (const int m : multipolygons) members += m >= 0;
    EXPECT_EQ(vertices, e.vertices) << e.name;
    EXPECT_EQ(members, e.multipolygon_members) << e.name;
  }
}

// ReadPolygons() takes them by extension, the members of each record held to OGC's rule (as
// `acdplan decompose` does), and every polygon decomposes and passes CheckDecomposition().
TEST(ShapefileReaderTest, RealShapefilesDecompose) {
  for (const char* name : {"nc.shp", "olinda1.shp"}) {
    std::vector<double> radii;
    ReadPolygonsOptions options;
    options.disjoint_members = true;
    const std::vector<Polygon2d> polygons =
        ReadPolygons((kShapefiles / name).string(), &radii, options);
    Decompose2dOptions decompose;
    decompose.measure = ConcavityMeasure::kShortestPath;
    decompose.tau = 0.01 * *std::max_element(radii.begin(), radii.end());
    const Decomposition2d decomposition = Decompose2d(polygons, decompose);
    const DecompositionCheck check = CheckDecomposition(polygons, decomposition);
    EXPECT_TRUE(check.ok()) << name << ": " << check.problems.front();
    EXPECT_GE(decomposition.components.size(), polygons.size()) << name;
  }
}

}  // namespace
}  // namespace acdplan::acd
