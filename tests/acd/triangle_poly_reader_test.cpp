// Triangle's .poly format: the region that Triangle meshes (closed loops of segments, less the
// regions of hole points), told apart from Lien's .poly by its header; messages name the line.
#include "acd/triangle_poly_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "acd/poly_reader.h"
#include "acd/read_polygons.h"
#include "tests/input_error_of.h"
#include "tests/scratch_dir.h"

namespace acdplan::acd {
namespace {

using ::testing::HasSubstr;

// The square [0, 3]^2 and, inside it, the square [1, 2]^2, numbered from 1, with a boundary
// marker per vertex and segment; `holes` is the hole section.
std::string Frame(const std::string& holes) {
  return "# a frame\n"
         "8 2 0 1\n"
         "1 0 0 1\n2 3 0 1\n3 3 3 1\n4 0 3 1\n"
         "5 1 1 2\n6 2 1 2\n7 2 2 2\n8 1 2 2\n"
         "\n"
         "8 1\n"
         "1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n"
         "5 5 6 2\n6 6 7 2\n7 7 8 2\n8 8 5 2\n" +
         holes;
}

std::vector<Polygon2d> Read(const std::string& text) { return ReadTrianglePoly(text, "t.poly"); }

std::string ErrorOf(const std::string& text) {
  return acdplan::test::InputErrorOf([&] { Read(text); });
}

const Ring2d kOuter = {{0, 0}, {3, 0}, {3, 3}, {0, 3}};
const Ring2d kInner = {{1, 1}, {1, 2}, {2, 2}, {2, 1}};  // A hole: clockwise.

TEST(TrianglePolyReaderTest, AHolePointEmptiesTheLoopAroundIt) {
  const std::vector<Polygon2d> polygons = Read(Frame("1\n1 1.5 1.5\n"));
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(polygons[0].outer, kOuter);
  ASSERT_EQ(polygons[0].holes.size(), 1u);
  EXPECT_EQ(polygons[0].holes[0], kInner);
}

TEST(TrianglePolyReaderTest, ALoopWithoutAHolePointIsMeshedAndItsSegmentsVanish) {
  // No hole point, or one outside every loop (it empties nothing, as in Triangle).
  for (const std::string holes : {"0\n", "1\n1 5 5\n"}) {
    const std::vector<Polygon2d> polygons = Read(Frame(holes));
    ASSERT_EQ(polygons.size(), 1u);
    EXPECT_EQ(polygons[0].outer, kOuter);
    EXPECT_TRUE(polygons[0].holes.empty());
  }
}

TEST(TrianglePolyReaderTest, NumberedFromZeroWithCrossingDanglingSegmentsAndRegions) {
  // A square numbered from 0, without markers; its two diagonals cross inside it, a segment
  // dangles outside it; then the regional attributes, which only meshing uses.
  const std::vector<Polygon2d> polygons = Read(
      "6 2 1\n0 0 0 7.5\n1 4 0 7.5\n2 4 4 7.5\n3 0 4 7.5\n4 5 5 0\n5 6 6 0\n"
      "7\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n4 0 2\n5 1 3\n6 4 5\n"
      "0\n"
      "1\n0 1 1 3.0 0.5\n");
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(polygons[0].outer, Ring2d({{0, 0}, {4, 0}, {4, 4}, {0, 4}}));
  EXPECT_TRUE(polygons[0].holes.empty());
}

TEST(TrianglePolyReaderTest, AHolePointBetweenTwoLoopsLeavesTheInnerRegion) {
  const std::vector<Polygon2d> polygons = Read(Frame("1\n1 0.5 0.5\n"));
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(polygons[0].outer, Ring2d({{1, 1}, {2, 1}, {2, 2}, {1, 2}}));
  EXPECT_TRUE(polygons[0].holes.empty());
}

TEST(TrianglePolyReaderTest, IslandsAndSeparateRegionsAreSeparatePolygons) {
  // The frame's hole holds an island [1.25, 1.75]^2 (no hole point: meshed), and a square
  // [5, 6]^2 lies apart.
  const std::vector<Polygon2d> polygons = Read(
      "16 2\n"
      "1 0 0\n2 3 0\n3 3 3\n4 0 3\n5 1 1\n6 2 1\n7 2 2\n8 1 2\n"
      "9 1.25 1.25\n10 1.75 1.25\n11 1.75 1.75\n12 1.25 1.75\n"
      "13 5 5\n14 6 5\n15 6 6\n16 5 6\n"
      "16\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n6 6 7\n7 7 8\n8 8 5\n"
      "9 9 10\n10 10 11\n11 11 12\n12 12 9\n13 13 14\n14 14 15\n15 15 16\n16 16 13\n"
      "1\n1 1.1 1.1\n");
  ASSERT_EQ(polygons.size(), 3u);
  EXPECT_EQ(polygons[0].outer, kOuter);
  EXPECT_EQ(polygons[0].holes, std::vector<Ring2d>{kInner});
  EXPECT_EQ(polygons[1].outer, Ring2d({{1.25, 1.25}, {1.75, 1.25}, {1.75, 1.75}, {1.25, 1.75}}));
  EXPECT_EQ(polygons[2].outer, Ring2d({{5, 5}, {6, 5}, {6, 6}, {5, 6}}));
}

TEST(TrianglePolyReaderTest, VerticesFromTheNodeFileBeside) {
  const acdplan::test::ScratchDir dir;
  const std::string poly = dir.Write("box.poly", "0 2 0 0\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n");
  EXPECT_THAT(acdplan::test::InputErrorOf([&] { ReadPolygons(poly); }),
              HasSubstr("box.poly:1: the vertex count is 0, so the vertices are in " +
                        dir.Path("box.node") + ", which cannot be read: No such file"));
  dir.Write("box.node", "4 2 0 0\n1 0 0\n2 3 0\n3 3 3\n4 0 3\n");
  const std::vector<Polygon2d> polygons = ReadPolygons(poly);
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(polygons[0].outer.size(), 4u);
  dir.Write("box.node", "4 2 0 0\n1 0 0\n2 3 0\n3 3 x\n4 0 3\n");
  EXPECT_THAT(acdplan::test::InputErrorOf([&] { ReadPolygons(poly); }),
              HasSubstr("box.node:4: malformed number 'x'"));
}

TEST(TrianglePolyReaderTest, ErrorsNameTheLineAndTheRule) {
  EXPECT_THAT(ErrorOf("4 3 0 0\n"),
              HasSubstr("t.poly:1: dimension must be 2, found 3 (a 3D .poly is TetGen's"));
  EXPECT_THAT(ErrorOf("2 2\n1 0 0\n"),
              HasSubstr("t.poly:2: unexpected end of file: expected vertex 2 of 2"));
  EXPECT_THAT(ErrorOf("1 2 0 2\n"),
              HasSubstr("t.poly:1: boundary marker count 2 out of range 0..1"));
  EXPECT_THAT(
      ErrorOf("1 2\n1 0\n"),
      HasSubstr("t.poly:2: expected vertex 1 of 1 ('<number> <x> <y> ...'), found 2 field(s)"));
  EXPECT_THAT(ErrorOf("1 2\n2 0 0\n"),
              HasSubstr("t.poly:2: first vertex number 2 out of range 0..1"));
  EXPECT_THAT(ErrorOf(Frame("1\n1 nan 1\n")), HasSubstr("t.poly:22: non-finite number 'nan'"));
  EXPECT_THAT(ErrorOf("3 2\n1 0 0\n2 1 0\n3 0 1\n1\n1 1 4\n0\n"),
              HasSubstr("t.poly:6: endpoint of segment 1 (a vertex number) 4 out of range 1..3"));
  EXPECT_THAT(ErrorOf(Frame("")), HasSubstr("t.poly:20: unexpected end of file: expected the "
                                            "hole count"));
  EXPECT_THAT(ErrorOf(Frame("1\n1 1 1.5\n")), HasSubstr("t.poly:22: hole 1 lies on a segment"));
  EXPECT_THAT(ErrorOf("3 2\n1 0 0\n2 1 0\n3 0 1\n2\n1 1 2\n2 2 3\n0\n"),
              HasSubstr("t.poly: the 2 segment(s) enclose no region"));
  EXPECT_THAT(ErrorOf(Frame("2\n1 0.5 0.5\n2 1.5 1.5\n")),
              HasSubstr("t.poly: the 8 segment(s) enclose no region"));
}

TEST(TrianglePolyReaderTest, ToldApartFromLiensFormat) {
  EXPECT_TRUE(IsTrianglePoly("# c\n\n8 2 0 1\n"));
  EXPECT_TRUE(IsTrianglePoly("0 2\n"));
  EXPECT_TRUE(IsTrianglePoly("4 3 0 0\n"));  // Read, to say that TetGen's 3D format is not.
  EXPECT_FALSE(IsTrianglePoly("1\n4 out\n0 0\n1 0\n1 1\n0 1\n1 2 3 4\n"));
  EXPECT_FALSE(IsTrianglePoly("1 4\nout\n0 0\n1 0\n1 1\n0 1\n1 2 3 4\n"));
  EXPECT_FALSE(IsTrianglePoly("1 4 IN\n"));
  EXPECT_FALSE(IsTrianglePoly("8\n"));
  EXPECT_FALSE(IsTrianglePoly("1 2 3 4 5\n"));
  EXPECT_FALSE(IsTrianglePoly(""));
  // ReadPoly() reads either.
  std::istringstream triangle(Frame("1\n1 1.5 1.5\n"));
  const std::vector<Polygon2d> polygons = ReadPoly(triangle, "t.poly");
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(polygons[0].holes.size(), 1u);
}

}  // namespace
}  // namespace acdplan::acd
