#include "acd/poly_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "base/input_error.h"
#include "tests/data_paths.h"
#include "tests/input_error_of.h"

namespace acdplan::acd {
namespace {

using ::testing::HasSubstr;

std::vector<Polygon2d> PolyOf(const std::string& text) {
  std::istringstream in(text);
  return ReadPoly(in, "t.poly");
}

std::string PolyErrorOf(const std::string& text) {
  return acdplan::test::InputErrorOf([&] { PolyOf(text); });
}

TEST(PolyReaderTest, ReadsOuterWithHoleAndSecondOuterHonouringVertexOrder) {
  // The example of POLY_FORMAT.txt, with its comments.
  const std::string text =
      "3      # number of polygonal chains\n"
      "3 out  # first chain\n"
      "0 0\n0 10\n10 10\n"
      "3 2 1  # the order\n"
      "4 in\n1 1\n2 1\n2 2\n1 2\n1 2 3 4\n"
      "4 out\n-5 -5\n-3 0\n-4 3\n-6 0\n1 2 3 4\n";
  const std::vector<Polygon2d> polygons = PolyOf(text);
  ASSERT_EQ(polygons.size(), 2u);
  EXPECT_EQ(polygons[0].outer, Ring2d({{10, 10}, {0, 10}, {0, 0}}));
  ASSERT_EQ(polygons[0].holes.size(), 1u);
  EXPECT_EQ(polygons[0].holes[0], Ring2d({{1, 1}, {2, 1}, {2, 2}, {1, 2}}));
  EXPECT_TRUE(polygons[1].holes.empty());
  EXPECT_EQ(polygons[1].outer.size(), 4u);
}

TEST(PolyReaderTest, AcceptsCrLfTabsHeaderCommentsAndOrderOverSeveralLines) {
  const std::vector<Polygon2d> polygons =
      PolyOf("# header\r\n#\r\n1\r\n4\tout\r\n0\t0\r\n1 0\r\n1 1\r\n0 1\r\n4 3\r\n2 1\r\n");
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(polygons[0].outer, Ring2d({{0, 1}, {1, 1}, {1, 0}, {0, 0}}));
  // A UTF-8 byte order mark (Windows editors write one) is not part of the first number.
  const std::vector<Polygon2d> marked = PolyOf(
      "\xEF\xBB\xBF"
      "1\n3 out\n0 0\n1 0\n0 1\n1 2 3\n");
  ASSERT_EQ(marked.size(), 1u);
  EXPECT_EQ(marked[0].outer, Ring2d({{0, 0}, {1, 0}, {0, 1}}));
}

TEST(PolyReaderTest, MalformedNumberNamesFileLineAndToken) {
  EXPECT_EQ(PolyErrorOf("1\n3 out\n0 0\n1 0.5.5\n0 1\n1 2 3\n"),
            "t.poly:4: malformed number '0.5.5'");
  EXPECT_THAT(PolyErrorOf("1\n3 out\n0 0\n1 x\n0 1\n1 2 3\n"),
              HasSubstr("t.poly:4: malformed number 'x'"));
}

TEST(PolyReaderTest, BirdPolyLine47IsAMalformedNumber) {
  const std::string path = acdplan::test::DataDir() + "/polygons/acd2d/bird.poly";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  try {
    ReadPoly(in, "bird.poly");
    FAIL() << "bird.poly was accepted";
  } catch (const acdplan::InputError& error) {
    EXPECT_STREQ(error.what(), "bird.poly:47: malformed number '-6.64248.788605'");
  }
}

TEST(PolyReaderTest, NonFiniteNumberNamesLine) {
  EXPECT_THAT(PolyErrorOf("1\n3 out\n0 0\nnan 0\n0 1\n1 2 3\n"),
              HasSubstr("t.poly:4: non-finite number 'nan'"));
  EXPECT_THAT(PolyErrorOf("1\n3 out\n0 0\n1 0\n0 -inf\n1 2 3\n"),
              HasSubstr("t.poly:5: non-finite number '-inf'"));
  EXPECT_THAT(PolyErrorOf("1\n3 out\n0 0\n1 0\n0 1e999\n1 2 3\n"),
              HasSubstr("t.poly:5: number out of range '1e999'"));
}

TEST(PolyReaderTest, VertexOrderErrorsNameTheLine) {
  EXPECT_THAT(PolyErrorOf("1\n3 out\n0 0\n1 0\n0 1\n1 2 4\n"),
              HasSubstr("t.poly:6: vertex index 4 out of range 1..3"));
  EXPECT_THAT(PolyErrorOf("1\n3 out\n0 0\n1 0\n0 1\n1 0 2\n"),
              HasSubstr("t.poly:6: vertex index 0 out of range"));
  EXPECT_THAT(PolyErrorOf("1\n3 out\n0 0\n1 0\n0 1\n1 2 2\n"),
              HasSubstr("t.poly:6: vertex index 2 repeated"));
  EXPECT_THAT(PolyErrorOf("1\n3 out\n0 0\n1 0\n0 1\n1 2.5 3\n"),
              HasSubstr("t.poly:6: malformed vertex index '2.5'"));
  // Missing indices: the next chain's header is read in their place.
  EXPECT_THAT(PolyErrorOf("2\n3 out\n0 0\n1 0\n0 1\n1\n3 in\n0 0\n1 0\n0 1\n1 2 3\n"),
              HasSubstr("t.poly:7: the vertex order of chain 1 (line 2) ends early"));
  // Missing at the end of the file.
  EXPECT_THAT(PolyErrorOf("1\n3 out\n0 0\n1 0\n0 1\n1 2\n"),
              HasSubstr("t.poly:6: unexpected end of file: expected index 3 of 3"));
}

TEST(PolyReaderTest, CountAndStructureErrorsNameTheLine) {
  EXPECT_THAT(PolyErrorOf(""),
              HasSubstr("t.poly:0: unexpected end of file: expected the number of chains"));
  EXPECT_THAT(PolyErrorOf("two\n"), HasSubstr("t.poly:1: malformed number of chains 'two'"));
  EXPECT_THAT(PolyErrorOf("0\n"), HasSubstr("t.poly:1: number of chains must be positive"));
  EXPECT_THAT(PolyErrorOf("1\n-3 out\n"), HasSubstr("t.poly:2: vertex count must be positive"));
  EXPECT_THAT(PolyErrorOf("1\n3 around\n"), HasSubstr("t.poly:2: expected 'out' or 'in'"));
  EXPECT_THAT(PolyErrorOf("1\n3 in\n0 0\n1 0\n0 1\n1 2 3\n"),
              HasSubstr("t.poly:2: hole chain ('in') before any outer chain"));
  // Truncated: fewer vertices than declared.
  EXPECT_THAT(PolyErrorOf("1\n4 out\n0 0\n1 0\n0 1\n"),
              HasSubstr("t.poly:5: unexpected end of file: expected vertex 4 of 4 of chain 1"));
  // Truncated: fewer chains than declared.
  EXPECT_THAT(
      PolyErrorOf("2\n3 out\n0 0\n1 0\n0 1\n1 2 3\n"),
      HasSubstr("t.poly:6: unexpected end of file: expected the vertex count of chain 2 of 2"));
  // More chains than declared (simple5.poly does this) without a warnings list, or content
  // after the chains that is not a chain.
  EXPECT_THAT(PolyErrorOf("1\n3 out\n0 0\n1 0\n0 1\n1 2 3\n3 in\n"),
              HasSubstr("t.poly:7: unexpected '3' after the 1 chain(s) declared on line 1"));
}

TEST(PolyReaderTest, ReadsChainsBeyondTheDeclaredCountWithOneWarning) {
  std::istringstream in(
      "1\n4 out\n0 0\n4 0\n4 4\n0 4\n1 2 3 4\n3 in\n1 1\n2 1\n1 2\n1 2 3\n"
      "3 in\n3 3\n3.5 3\n3 3.5\n3 2 1\n");
  std::vector<std::string> warnings;
  const std::vector<Polygon2d> polygons = ReadPoly(in, "t.poly", &warnings);
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(polygons[0].holes.size(), 2u);
  EXPECT_THAT(warnings, ::testing::ElementsAre("t.poly:8: 2 chain(s) more than the 1 declared on "
                                               "line 1; read all 3 (wrong chain count in the "
                                               "file)"));
  // Content after the chains that is not a chain stays an error.
  std::istringstream bad("1\n3 out\n0 0\n1 0\n0 1\n1 2 3\nhello\n");
  EXPECT_THROW(ReadPoly(bad, "t.poly", &warnings), InputError);
}

}  // namespace
}  // namespace acdplan::acd
