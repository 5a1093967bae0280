#include "envs/generators.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "envs/free_space2d.h"
#include "envs/workspace_yaml.h"
#include "test_util.h"
#include "tests/data_paths.h"

namespace acdplan::envs {
namespace {

using testing::ErrorOf;
using ::testing::HasSubstr;

bool SameWorld(const Workspace2d& a, const Workspace2d& b) {
  if (a.bounds.min() != b.bounds.min() || a.bounds.max() != b.bounds.max()) return false;
  if (a.obstacles.size() != b.obstacles.size()) return false;
  for (size_t k = 0; k < a.obstacles.size(); ++k) {
    if (a.obstacles[k].outer != b.obstacles[k].outer) return false;
    if (a.obstacles[k].holes != b.obstacles[k].holes) return false;
  }
  return true;
}

class GeneratorTest : public ::testing::TestWithParam<std::string> {};

TEST_P(GeneratorTest, FreeSpaceIsValidAndDecomposes) {
  for (double width : {0.0, 0.25}) {
    for (std::uint64_t seed : {1, 2, 3}) {
      SCOPED_TRACE("width " + std::to_string(width) + " seed " + std::to_string(seed));
      const Workspace2d world = GenerateWorkspace2d(GetParam(), seed, {width});
      const std::vector<acd::Polygon2d> free = FreeSpace2d(world);
      ASSERT_FALSE(free.empty());
      // Every narrow-passage world is one connected region (its passage connects it), except
      // that furniture may wall off a pocket in two_rooms.
      if (GetParam() != "two_rooms") {
        EXPECT_EQ(free.size(), 1u);
      }
      testing::ExpectValidAndDecomposes(free);
    }
  }
}

TEST_P(GeneratorTest, SameSeedSameWorldOtherSeedOtherWorld) {
  const Workspace2d a = GenerateWorkspace2d(GetParam(), 7);
  EXPECT_TRUE(SameWorld(a, GenerateWorkspace2d(GetParam(), 7)));
  bool differs = false;
  for (std::uint64_t seed = 8; seed < 16 && !differs; ++seed) {
    differs = !SameWorld(a, GenerateWorkspace2d(GetParam(), seed));
  }
  EXPECT_TRUE(differs);
}

TEST_P(GeneratorTest, CommittedFileMatchesTheGenerator) {
  // envs/2d/<name>.yaml is the default instance with seed 1 (envs/tools/generate_envs.cpp).
  const Workspace2d file =
      LoadWorkspace2dYaml(acdplan::test::SourceDir() + "/envs/2d/" + GetParam() + ".yaml");
  const Workspace2d generated = GenerateWorkspace2d(GetParam(), 1);
  EXPECT_TRUE(SameWorld(file, generated)) << "regenerate with acdplan_generate_envs envs/2d";
  EXPECT_EQ(file.description, generated.description);
}

INSTANTIATE_TEST_SUITE_P(AllGenerators, GeneratorTest, ::testing::ValuesIn(GeneratorNames()),
                         [](const auto& info) { return info.param; });

TEST(GeneratorsTest, WallGapHasThePassageWidth) {
  WallGapOptions options;
  options.passage_width = 0.37;
  const Workspace2d w = MakeWallWithGap(3, options);
  ASSERT_EQ(w.obstacles.size(), 2u);
  double top_of_lower = -1e9, bottom_of_upper = 1e9;
  for (const acd::Point2d& p : w.obstacles[0].outer) top_of_lower = std::max(top_of_lower, p.y());
  for (const acd::Point2d& p : w.obstacles[1].outer)
    bottom_of_upper = std::min(bottom_of_upper, p.y());
  EXPECT_NEAR(bottom_of_upper - top_of_lower, 0.37, 1e-12);
}

TEST(GeneratorsTest, MazeFreeSpaceIsATreeOfPassages) {
  MazeOptions options;
  options.columns = 5;
  options.rows = 4;
  options.passage_width = 1.0;
  options.wall_thickness = 0.5;
  const std::vector<acd::Polygon2d> free = FreeSpace2d(MakeMaze(11, options));
  ASSERT_EQ(free.size(), 1u);
  EXPECT_TRUE(free[0].holes.empty());  // A perfect maze has no loops.
  // 20 cells plus 19 carved walls of 1 x 0.5.
  EXPECT_NEAR(acd::Area(free[0]), 20 * 1.0 + 19 * 0.5, 1e-9);
}

TEST(GeneratorsTest, SpiralCorridorWidth) {
  SpiralOptions options;
  options.turns = 2;
  options.margin = 0.0;
  const Workspace2d w = MakeSpiral(5, options);
  ASSERT_EQ(w.obstacles.size(), 1u);
  // Wall area: total centre-line length times thickness (square corners add and lose the same).
  const double pitch = options.passage_width + options.wall_thickness;
  double length = 0;
  for (int k = 0; k < 8; ++k) length += pitch * (k / 2 + 1);
  EXPECT_NEAR(acd::Area(w.obstacles[0]), length * options.wall_thickness, 1e-9);
}

TEST(GeneratorsTest, ByNameAppliesTheSetParametersOnly) {
  GeneratorParameters p;
  p.passage_width = 0.3;
  p.wall_thickness = 0.7;
  WallGapOptions gap;
  gap.passage_width = 0.3;
  gap.wall_thickness = 0.7;
  EXPECT_EQ(GenerateWorkspace2d("wall_gap", 4, p).obstacles[0].outer,
            MakeWallWithGap(4, gap).obstacles[0].outer);
  MazeOptions maze;
  maze.passage_width = 0.3;  // wall_thickness 0 keeps the default
  p.wall_thickness = 0.0;
  EXPECT_EQ(GenerateWorkspace2d("maze", 4, p).obstacles[0].outer,
            MakeMaze(4, maze).obstacles[0].outer);
}

TEST(GeneratorsTest, Errors) {
  EXPECT_THAT(
      ErrorOf([] { GenerateWorkspace2d("castle", 1); }),
      HasSubstr("GenerateWorkspace2d(): unknown generator 'castle' (expected one of: wall_gap, "
                "zigzag, bug_trap, two_rooms, spiral, maze)"));
  EXPECT_THAT(ErrorOf([] { GenerateWorkspace2d("maze", 1, {-1}); }),
              HasSubstr("passage_width must be >= 0"));
  EXPECT_THAT(ErrorOf([] {
                GenerateWorkspace2d("zigzag", 1, {0, 0.5});
              }),
              HasSubstr("GenerateWorkspace2d(): wall_thickness is not an option of generator "
                        "'zigzag'"));
  WallGapOptions gap;
  gap.passage_width = 8;
  EXPECT_THAT(ErrorOf([&] { MakeWallWithGap(1, gap); }),
              HasSubstr("MakeWallWithGap(): passage_width must be in (0, height / 2]"));
  ZigZagOptions zigzag;
  zigzag.passage_width = 6;
  EXPECT_THAT(ErrorOf([&] { MakeZigZagCorridor(1, zigzag); }),
              HasSubstr("MakeZigZagCorridor(): passage_width 6 is too wide for height 10"));
  MazeOptions maze;
  maze.columns = 0;
  EXPECT_THAT(ErrorOf([&] { MakeMaze(1, maze); }),
              HasSubstr("MakeMaze(): columns and rows must be in [1, 1000]"));
  BugTrapOptions trap;
  trap.trap_size = 20;
  EXPECT_THAT(ErrorOf([&] { MakeBugTrap(1, trap); }),
              HasSubstr("MakeBugTrap(): trap_size must be < min(width, height)"));
}

}  // namespace
}  // namespace acdplan::envs
