#include "envs/moving_ai_map.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "envs/free_space2d.h"
#include "test_util.h"

namespace acdplan::envs {
namespace {

using testing::ErrorOf;
using ::testing::HasSubstr;
using testing::TempDir;

TEST(MovingAiMapTest, ReadsTerrainAndHeader) {
  TempDir dir;
  // Written on Windows: a UTF-8 byte order mark, CR LF line ends.
  const std::string path = dir.Write("small.map",
                                     "\xEF\xBB\xBFtype octile\r\nheight 2\r\nwidth 4\r\nmap\r\n"
                                     ".GS@\r\nOTW.\r\n");
  const OccupancyGrid grid = ReadMovingAiMap(path);
  EXPECT_EQ(grid.width, 4);
  EXPECT_EQ(grid.height, 2);
  EXPECT_EQ(grid.blocked, (std::vector<std::uint8_t>{0, 0, 0, 1, 1, 1, 1, 0}));
}

TEST(MovingAiMapTest, SmallMazeGivesOneFreeCorridor) {
  TempDir dir;
  // A maze whose corridors form one free region of 23 cells without holes (the inner walls
  // reach the border through column 4).
  const std::string path = dir.Write("maze.map",
                                     "type octile\nheight 7\nwidth 9\nmap\n"
                                     "@@@@@@@@@\n"
                                     "@.......@\n"
                                     "@.@@@@@.@\n"
                                     "@.@.T.@.@\n"
                                     "@.@.@.@.@\n"
                                     "@...@...@\n"
                                     "@@@@@@@@@\n");
  const Workspace2d world = LoadMovingAiMap(path);
  EXPECT_EQ(world.bounds.max(), Eigen::Vector2d(9, 7));
  const std::vector<acd::Polygon2d> free = FreeSpace2d(world);
  ASSERT_EQ(free.size(), 1u);
  EXPECT_TRUE(free[0].holes.empty());
  EXPECT_NEAR(acd::Area(free[0]), 23.0, 1e-9);
  // Straight corridors merge into long edges: far fewer vertices than cells.
  EXPECT_LE(free[0].outer.size(), 20u);
  testing::ExpectValidAndDecomposes(free);
}

TEST(MovingAiMapTest, DiagonalPinchesStayValid) {
  TempDir dir;
  const std::string path = dir.Write("diag.map",
                                     "type octile\nheight 5\nwidth 5\nmap\n"
                                     ".....\n"
                                     ".@...\n"
                                     "..@..\n"
                                     "...@.\n"
                                     ".....\n");
  const Workspace2d world = LoadMovingAiMap(path);
  EXPECT_EQ(world.obstacles.size(), 3u);
  const std::vector<acd::Polygon2d> free = FreeSpace2d(world);
  ASSERT_EQ(free.size(), 1u);
  EXPECT_NEAR(acd::Area(free[0]), 22.0, 1e-9);
  testing::ExpectValidAndDecomposes(free);
}

TEST(MovingAiMapTest, Errors) {
  TempDir dir;
  auto error = [&](const std::string& text) {
    const std::string path = dir.Write("bad.map", text);
    return ErrorOf([&] { ReadMovingAiMap(path); });
  };
  EXPECT_THAT(ErrorOf([&] { ReadMovingAiMap(dir.Path("none.map")); }),
              HasSubstr("none.map: cannot read the file: No such file or directory"));
  EXPECT_THAT(error("height 1\nwidth 1\nmap\n.\n"),
              HasSubstr("bad.map:3: missing 'type octile' before 'map'"));
  EXPECT_THAT(error("type tile\n"), HasSubstr("bad.map:1: unsupported map type 'tile'"));
  EXPECT_THAT(error("type octile\nheight x\n"),
              HasSubstr("bad.map:2: expected 'height N' with N an integer in [1, 100000]"));
  EXPECT_THAT(error("type octile\nheight 1\nmap\n.\n"),
              HasSubstr("bad.map:3: missing 'width N' before 'map'"));
  EXPECT_THAT(error("type octile\nheight 2\nwidth 3\nmap\n...\n..\n"),
              HasSubstr("bad.map:6: row 1 has 2 cells, expected 3"));
  EXPECT_THAT(error("type octile\nheight 2\nwidth 3\nmap\n...\n.x.\n"),
              HasSubstr("bad.map:6: unknown terrain 'x' in column 1"));
  EXPECT_THAT(error("type octile\nheight 3\nwidth 3\nmap\n...\n...\n"),
              HasSubstr("bad.map:7: unexpected end of file: expected 3 map rows, found 2"));
  EXPECT_THAT(error("type octile\nheight 1\nwidth 3\nmap\n...\n@@@\n"),
              HasSubstr("bad.map:6: unexpected text after the 1 map rows"));
  // The largest header without its rows: an error, not 10 GB of cells (a reproducer for
  // fuzz/fuzz_moving_ai_map, fuzz/corpus/moving_ai_map/regression-oom-huge-header.map).
  EXPECT_THAT(error("type octile\nheight 100000\nwidth 100000\nmap\n"),
              HasSubstr("bad.map:5: unexpected end of file: expected 100000 map rows, found 0"));
  EXPECT_THAT(error("type octile\nheight 1\nwidth 3\ncolour blue\n"),
              HasSubstr("bad.map:4: unknown header line 'colour blue'"));
  EXPECT_THAT(error("type octile\nheight 1\nwidth 3\n"),
              HasSubstr("bad.map:4: unexpected end of file: expected the 'map' line"));
}

}  // namespace
}  // namespace acdplan::envs
