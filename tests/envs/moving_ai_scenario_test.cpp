// Moving AI .scen files: problems with their cells and map, the map found as benchmark sets
// are unpacked; errors name the line.
#include "envs/moving_ai_scenario.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "test_util.h"

namespace acdplan::envs {
namespace {

using testing::ErrorOf;
using ::testing::HasSubstr;
using testing::TempDir;

TEST(MovingAiScenarioTest, ReadsProblemsWithTabsOrSpacesAndCrLf) {
  TempDir dir;
  const std::string path = dir.Write("a.map.scen",
                                     "version 1\r\n"
                                     "0\tmaps/dao/a.map\t9\t7\t1\t1\t7\t1\t12.48528137\r\n"
                                     "\r\n"
                                     "3 a.map 9 7 2 5 3 1 4.41421356\r\n");
  const std::vector<MovingAiProblem> problems = ReadMovingAiScenario(path);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].bucket, 0);
  EXPECT_EQ(problems[0].map, "maps/dao/a.map");
  EXPECT_EQ(problems[0].map_width, 9);
  EXPECT_EQ(problems[0].map_height, 7);
  EXPECT_EQ(problems[0].start, Eigen::Vector2i(1, 1));
  EXPECT_EQ(problems[0].goal, Eigen::Vector2i(7, 1));
  EXPECT_DOUBLE_EQ(problems[0].optimal_length, 12.48528137);
  EXPECT_EQ(problems[0].line, 2);
  EXPECT_EQ(problems[1].bucket, 3);
  EXPECT_EQ(problems[1].line, 4);
  // Without a version line too.
  EXPECT_EQ(ReadMovingAiScenario(dir.Write("b.scen", "0 a.map 9 7 1 1 7 1 1\n")).size(), 1u);
}

TEST(MovingAiScenarioTest, FindsTheMapAsNamedOrBesideTheFile) {
  TempDir dir;
  const std::string scen = dir.Path("a.map.scen");
  // Not there: beside the scenario file, by its name.
  EXPECT_EQ(ResolveMovingAiMap(scen, "maps/dao/a.map"), dir.Path("a.map"));
  std::filesystem::create_directories(dir.Path("maps/dao"));
  dir.Write("maps/dao/a.map", "");
  EXPECT_EQ(ResolveMovingAiMap(scen, "maps/dao/a.map"), dir.Path("maps/dao/a.map"));
  EXPECT_EQ(ResolveMovingAiMap(scen, dir.Path("maps/dao/a.map")), dir.Path("maps/dao/a.map"));
}

TEST(MovingAiScenarioTest, CellCentresInTheMapsWorld) {
  // Row 0 is the top row of a 7-row map: y in [6, 7].
  EXPECT_EQ(MovingAiCellCentre({0, 0}, 7), Eigen::Vector2d(0.5, 6.5));
  EXPECT_EQ(MovingAiCellCentre({8, 6}, 7), Eigen::Vector2d(8.5, 0.5));
}

TEST(MovingAiScenarioTest, ErrorsNameTheLine) {
  TempDir dir;
  auto error = [&](const std::string& text) {
    const std::string path = dir.Write("e.scen", text);
    return ErrorOf([&] { ReadMovingAiScenario(path); });
  };
  EXPECT_THAT(error("version 2\n"), HasSubstr("e.scen:1: expected 'version 1' as the first line"));
  EXPECT_THAT(error("version 1\n0 a.map 9 7 1 1 7 1\n"),
              HasSubstr("e.scen:2: expected 9 fields (bucket, map, map width, map height, start "
                        "x, start y, goal x, goal y, optimal length), found 8"));
  EXPECT_THAT(error("0 a.map 9 7 1 x 7 1 2\n"),
              HasSubstr("e.scen:1: start y: expected an integer in [0, 100000], found 'x'"));
  EXPECT_THAT(error("0 a.map 9 7 1 1 9 1 2\n"),
              HasSubstr("e.scen:1: goal cell (9, 1) outside the map's 9 x 7 cells"));
  EXPECT_THAT(error("0 a.map 9 7 1 1 7 1 nan\n"),
              HasSubstr("e.scen:1: optimal length: non-finite number 'nan'"));
  EXPECT_THAT(error("0 a.map 9 7 1 1 7 1 -1\n"),
              HasSubstr("e.scen:1: optimal length: expected a number >= 0"));
  EXPECT_THAT(error("version 1\n\n"), HasSubstr("e.scen: no problem in file"));
  EXPECT_THAT(error("0 a.map 9 7 1 1 7 1 2\nversion 1\n"),
              HasSubstr("e.scen:2: expected 'version 1' as the first line"));
}

}  // namespace
}  // namespace acdplan::envs
