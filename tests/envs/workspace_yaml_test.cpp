#include "envs/workspace_yaml.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "test_util.h"

namespace acdplan::envs {
namespace {

using testing::ErrorOf;
using ::testing::HasSubstr;
using testing::TempDir;

TEST(Workspace2dYamlTest, InlinePolygonsHolesAndFiles) {
  TempDir dir;
  std::filesystem::create_directories(dir.Path("shapes"));
  dir.Write("shapes/rock.wkt", "POLYGON ((6 6, 8 6, 8 8, 6 8, 6 6))");
  const std::string path = dir.Write("world.yaml",
                                     "description: \"a test world\"\n"
                                     "bounds: [0, 0, 10, 10]\n"
                                     "obstacles:\n"
                                     "  - polygon: [[1, 1], [1, 4], [4, 4], [4, 1]]  # clockwise\n"
                                     "    holes: [[[2, 2], [3, 2], [3, 3], [2, 3]]]\n"
                                     "  - file: shapes/rock.wkt\n");
  const Workspace2d w = LoadWorkspace2dYaml(path);
  EXPECT_EQ(w.description, "a test world");
  EXPECT_EQ(w.bounds.max(), Eigen::Vector2d(10, 10));
  ASSERT_EQ(w.obstacles.size(), 2u);
  EXPECT_DOUBLE_EQ(acd::Area(w.obstacles[0]), 8.0);
  EXPECT_GT(acd::SignedArea(w.obstacles[0].outer), 0.0);  // Re-oriented.
  EXPECT_DOUBLE_EQ(acd::Area(w.obstacles[1]), 4.0);
}

TEST(Workspace2dYamlTest, InvalidObstaclesAreRejectedUnlessRepaired) {
  TempDir dir;
  dir.Write("tile.wkt", "POLYGON ((6 6, 9 9, 9 6, 6 9, 6 6))");  // a bow tie
  const std::string path = dir.Write("world.yaml",
                                     "bounds: [0, 0, 10, 10]\n"
                                     "obstacles:\n"
                                     "  - polygon: [[1, 1], [4, 4], [4, 1], [1, 3]]  # a bow tie\n"
                                     "  - file: tile.wkt\n");
  EXPECT_THAT(ErrorOf([&] { LoadWorkspace2dYaml(path); }),
              HasSubstr("world.yaml: obstacles[0]: outer ring is not simple"));
  std::vector<std::string> notes;
  acd::ReadPolygonsOptions repair;
  repair.repair = true;
  repair.notes = &notes;
  const Workspace2d w = LoadWorkspace2dYaml(path, repair);
  ASSERT_EQ(w.obstacles.size(), 4u);  // each bow tie: its two triangles
  for (const acd::Polygon2d& o : w.obstacles) {
    EXPECT_EQ(o.outer.size(), 3u);
    EXPECT_GT(acd::Area(o), 0.5);
  }
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_THAT(notes[0], HasSubstr("world.yaml: obstacles[0]: repaired: "));
  EXPECT_THAT(notes[1], HasSubstr("tile.wkt: polygon 0: repaired: "));
}

TEST(Workspace2dYamlTest, ObstaclesWhoseRingsTouchAtAPointAreValid) {
  TempDir dir;
  // A hole touching the outer ring at (1, 2): OGC-valid.
  const std::string path = dir.Write("world.yaml",
                                     "bounds: [0, 0, 10, 10]\n"
                                     "obstacles:\n"
                                     "  - polygon: [[1, 1], [5, 1], [5, 5], [1, 5]]\n"
                                     "    holes: [[[1, 2], [3, 2], [3, 4]]]\n");
  const Workspace2d w = LoadWorkspace2dYaml(path);
  double area = 0;
  for (const acd::Polygon2d& o : w.obstacles) area += acd::Area(o);
  EXPECT_DOUBLE_EQ(area, 16.0 - 2.0);
}

TEST(Workspace2dYamlTest, WriteThenLoadIsExact) {
  TempDir dir;
  Workspace2d w;
  w.bounds = Eigen::AlignedBox2d(Eigen::Vector2d(-0.1, 0.3), Eigen::Vector2d(10.7, 1e3));
  w.obstacles.push_back({{{0.1, 0.2}, {1.0 / 3, 0.5}, {0.2, 2.0 / 3}}, {}});
  w.obstacles.push_back({{{2, 2}, {8, 2}, {8, 8}, {2, 8}}, {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}}});
  w.description = "quotes \" and \\ survive";
  const std::string path = dir.Path("out.yaml");
  WriteWorkspace2dYaml(w, path);
  const Workspace2d back = LoadWorkspace2dYaml(path);
  EXPECT_EQ(back.description, w.description);
  EXPECT_EQ(back.bounds.min(), w.bounds.min());
  EXPECT_EQ(back.bounds.max(), w.bounds.max());
  ASSERT_EQ(back.obstacles.size(), 2u);
  EXPECT_EQ(back.obstacles[0].outer, w.obstacles[0].outer);
  EXPECT_EQ(back.obstacles[1].holes, w.obstacles[1].holes);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

TEST(Workspace2dYamlTest, Errors) {
  TempDir dir;
  auto error = [&](const std::string& text) {
    const std::string path = dir.Write("world.yaml", text);
    return ErrorOf([&] { LoadWorkspace2dYaml(path); });
  };
  const std::string b = "bounds: [0, 0, 10, 10]\n";
  EXPECT_THAT(error(b + "obstacle: []\n"),
              HasSubstr("world.yaml: obstacle: unknown key (expected one of: description, "
                        "bounds, obstacles)"));
  EXPECT_THAT(error("obstacles: []\n"), HasSubstr("world.yaml: bounds: missing required key"));
  EXPECT_THAT(
      error("bounds: [0, 0, 10]\n"),
      HasSubstr("world.yaml: bounds: expected [xmin, ymin, xmax, ymax] (4 finite numbers)"));
  EXPECT_THAT(error("bounds: [0, 0, -1, 10]\n"),
              HasSubstr("world.yaml: bounds: expected xmin < xmax and ymin < ymax"));
  EXPECT_THAT(error(b + "obstacles: {polygon: 1}\n"),
              HasSubstr("world.yaml: obstacles: expected a list"));
  const std::string square = "  - polygon: [[0, 0], [1, 0], [1, 1]]\n";
  EXPECT_THAT(
      error(b + "obstacles:\n" + square + square + "  - polygon: [1, 2, 3]\n"),
      HasSubstr(
          "/world.yaml: obstacles[2].polygon: expected a list of [x, y] pairs: element 0 is not "
          "a pair of finite numbers"));
  EXPECT_THAT(error(b + "obstacles:\n  - polygon: [[0, 0], [1, 0]]\n"),
              HasSubstr("world.yaml: obstacles[0].polygon: expected a list of [x, y] pairs (at "
                        "least 3)"));
  EXPECT_THAT(error(b + "obstacles:\n  - polygon: [[0, 0], [1, 0], [1, x]]\n"),
              HasSubstr("world.yaml: obstacles[0].polygon: expected a list of [x, y] pairs: "
                        "element 2"));
  EXPECT_THAT(error(b + "obstacles:\n" + square + "    colour: red\n"),
              HasSubstr("world.yaml: obstacles[0].colour: unknown key (expected one of: file, "
                        "polygon, holes)"));
  EXPECT_THAT(error(b + "obstacles:\n" + square + "    holes: [[0, 0]]\n"),
              HasSubstr("world.yaml: obstacles[0].holes[0]: expected a list of [x, y] pairs"));
  EXPECT_THAT(error(b + "obstacles:\n  - {file: a.wkt, polygon: [[0, 0], [1, 0], [1, 1]]}\n"),
              HasSubstr("world.yaml: obstacles[0]: expected exactly one of 'file' or 'polygon'"));
  EXPECT_THAT(error(b + "obstacles:\n  - 3\n"),
              HasSubstr("world.yaml: obstacles[0]: expected a mapping of keys"));
  EXPECT_THAT(error(b + "obstacles:\n  - file: nothere.wkt\n"),
              HasSubstr("nothere.wkt: cannot read the file: No such file or directory"));
  EXPECT_THAT(error(b + "obstacles:\n  - polygon: [[0, 0], [2, 2], [2, 0], [0, 1]]\n"),
              HasSubstr("world.yaml: obstacles[0]: outer ring is not simple"));
  EXPECT_THAT(error(b + "obstacles: [\n"), HasSubstr("world.yaml:3: YAML syntax error"));
  EXPECT_THAT(ErrorOf([&] { LoadWorkspace2dYaml(dir.Path("none.yaml")); }),
              HasSubstr("none.yaml: cannot read the file: No such file or directory"));
}

TEST(Workspace3dYamlTest, MeshesWithScaleAndTranslation) {
  TempDir dir;
  dir.Write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const Workspace3d w = LoadWorkspace3dYaml(
      dir.Write("world.yaml",
                "bounds: [0, 0, 0, 10, 10, 10]\nobstacles:\n"
                "  - mesh: tri.obj\n    scale: 2\n    translation: [1, 2, 3]\n"));
  ASSERT_EQ(w.obstacles.size(), 1u);
  EXPECT_EQ(BoundingBox(w.obstacles[0]).min(), Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(BoundingBox(w.obstacles[0]).max(), Eigen::Vector3d(3, 4, 3));
}

TEST(Workspace3dYamlTest, Errors) {
  TempDir dir;
  auto error = [&](const std::string& text) {
    const std::string path = dir.Write("world.yaml", text);
    return ErrorOf([&] { LoadWorkspace3dYaml(path); });
  };
  const std::string b = "bounds: [0, 0, 0, 1, 1, 1]\n";
  EXPECT_THAT(error("bounds: [0, 0, 1, 1]\n"),
              HasSubstr("world.yaml: bounds: expected [xmin, ymin, zmin, xmax, ymax, zmax]"));
  EXPECT_THAT(error(b + "obstacles:\n  - scale: 2\n"),
              HasSubstr("world.yaml: obstacles[0].mesh: missing required key"));
  EXPECT_THAT(error(b + "obstacles:\n  - {mesh: a.obj, scale: 0}\n"),
              HasSubstr("world.yaml: obstacles[0].scale: expected a number > 0"));
  EXPECT_THAT(error(b + "obstacles:\n  - {mesh: missing.obj}\n"),
              HasSubstr("missing.obj: cannot read the file: No such file or directory"));
  dir.Write("broken.ply", "ply\nformat nonsense\n");
  EXPECT_THAT(error(b + "obstacles:\n  - {mesh: broken.ply}\n"),
              HasSubstr("broken.ply:2: expected 'format <ascii|binary_little_endian|"
                        "binary_big_endian> 1.0'"));
}

}  // namespace
}  // namespace acdplan::envs
