#include "envs/load_workspace.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_util.h"
#include "tests/data_paths.h"

namespace acdplan::envs {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;

TEST(LoadWorkspace2dTest, DispatchesByExtensionAndContent) {
  TempDir dir;
  const Workspace2d yaml =
      LoadWorkspace2d(dir.Write("w.YAML", "bounds: [0, 0, 4, 4]\nobstacles: []\n"));
  EXPECT_EQ(yaml.bounds.max(), Eigen::Vector2d(4, 4));

  dir.Write("m.pgm", "P2 2 1 255\n0 255\n");
  const Workspace2d ros =
      LoadWorkspace2d(dir.Write("m.yml", "image: m.pgm\nresolution: 2\norigin: [0, 0, 0]\n"));
  EXPECT_EQ(ros.bounds.max(), Eigen::Vector2d(4, 2));
  EXPECT_EQ(ros.obstacles.size(), 1u);

  const Workspace2d grid =
      LoadWorkspace2d(dir.Write("g.map", "type octile\nheight 1\nwidth 2\nmap\n@.\n"));
  EXPECT_EQ(grid.obstacles.size(), 1u);

  const Workspace2d wkt =
      LoadWorkspace2d(dir.Write("p.wkt", "POLYGON ((0 0, 10 0, 10 5, 0 5, 0 0))"));
  EXPECT_EQ(wkt.bounds.min(), Eigen::Vector2d(-1, -1));
  EXPECT_EQ(wkt.bounds.max(), Eigen::Vector2d(11, 6));

  EXPECT_THAT(testing::ErrorOf([&] { LoadWorkspace2d("world.svg"); }),
              HasSubstr("world.svg: unknown world file extension '.svg'"));
  // LoadWorld() takes meshes too, and says so.
  EXPECT_THAT(
      testing::ErrorOf([&] { LoadWorld("world.svg"); }),
      HasSubstr("world.svg: unknown world file extension '.svg' (expected .yaml, .yml, "
                ".map, .poly, .wkt, .geojson, .json, .shp, .gpkg, .kml or .kmz, or a mesh: .obj,"));
}

TEST(LoadWorkspace2dTest, LoadsEveryBuiltInWorld) {
  for (const auto& entry :
       std::filesystem::directory_iterator(acdplan::test::SourceDir() + "/envs/2d")) {
    if (entry.path().extension() != ".yaml") continue;
    const Workspace2d w = LoadWorkspace2d(entry.path().string());
    EXPECT_FALSE(w.obstacles.empty()) << entry.path();
    EXPECT_FALSE(w.description.empty()) << entry.path();
  }
}

}  // namespace
}  // namespace acdplan::envs
