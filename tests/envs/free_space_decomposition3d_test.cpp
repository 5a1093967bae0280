#include "envs/free_space_decomposition3d.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "base/input_error.h"
#include "tests/envs/test_worlds3d.h"
#include "tests/scratch_dir.h"

namespace acdplan::envs {
namespace {

// A cache folder (not yet created) inside a fresh scratch folder of the test.
class CacheDir {
 public:
  std::string path() const { return path_.string(); }
  std::vector<std::filesystem::path> Files() const {
    std::vector<std::filesystem::path> files;
    if (!std::filesystem::exists(path_)) return files;
    for (const auto& entry : std::filesystem::directory_iterator(path_)) files.push_back(entry);
    return files;
  }

 private:
  test::ScratchDir scratch_{"acdplan_free3d"};
  std::filesystem::path path_ = scratch_.path() / "cache";
};

FreeSpaceDecomposition3dOptions Options(const CacheDir& cache, bool use_cache = true) {
  FreeSpaceDecomposition3dOptions options;
  options.tau = 0.2;
  options.use_cache = use_cache;
  options.cache_dir = cache.path();
  return options;
}

TEST(NarrowestWidth, RectangleAndTriangle) {
  const Eigen::Vector3d n = Eigen::Vector3d::UnitX();
  EXPECT_NEAR(NarrowestWidth({{0, 0, 0}, {0, 3, 0}, {0, 3, 1}, {0, 0, 1}}, n), 1.0, 1e-12);
  // Tilted plane: a 2 x 0.5 rectangle in the plane x + y = 0.
  const Eigen::Vector3d u = Eigen::Vector3d(1, -1, 0).normalized(), w(0, 0, 1);
  EXPECT_NEAR(NarrowestWidth({0 * u, 2 * u, 2 * u + 0.5 * w, 0.5 * w},
                             Eigen::Vector3d(1, 1, 0).normalized()),
              0.5, 1e-12);
  // Equilateral triangle of side 2: width = its height sqrt(3).
  EXPECT_NEAR(NarrowestWidth({{0, 0, 0}, {0, 2, 0}, {0, 1, std::sqrt(3.0)}}, n), std::sqrt(3.0),
              1e-12);
  EXPECT_EQ(NarrowestWidth({{0, 0, 0}, {0, 1, 0}}, n), 0.0);
}

TEST(DecomposeFreeSpace3d, WindowWallOpeningHasTheWindowsWidth) {
  const CacheDir cache;
  const double side = 1.0;
  const FreeSpaceDecomposition3d d =
      DecomposeFreeSpace3d(testing::WindowWall(side), Options(cache));
  ASSERT_GE(d.components.size(), 2u);
  ASSERT_FALSE(d.openings.empty());
  EXPECT_NEAR(d.free_volume, 1000.0 - 99.0, 1e-9);
  double volume = 0;
  for (const FreeComponent3d& c : d.components) volume += c.volume;
  EXPECT_NEAR(volume, d.free_volume, 1e-6 * d.free_volume);
  // The narrowest opening is in the window (the wall slab x in [4.5, 5.5]), across x, about
  // the window's side wide.
  const FreeOpening3d* narrowest = &d.openings[0];
  for (const FreeOpening3d& o : d.openings) {
    if (o.width < narrowest->width) narrowest = &o;
  }
  EXPECT_NEAR(narrowest->width, side, 1e-6);
  EXPECT_NEAR(narrowest->area, side * side, 1e-6);
  EXPECT_GE(narrowest->centroid.x(), 4.5 - 1e-9);
  EXPECT_LE(narrowest->centroid.x(), 5.5 + 1e-9);
  EXPECT_NEAR(narrowest->centroid.y(), 5.0, 1e-6);
  EXPECT_NEAR(narrowest->centroid.z(), 5.0, 1e-6);
  EXPECT_NEAR(std::abs(narrowest->normal.x()), 1.0, 1e-9);
  // Every opening joins two components that the graph calls adjacent; every centroid locates.
  const auto graph = ComponentGraph(d);
  for (const FreeOpening3d& o : d.openings) {
    EXPECT_LT(o.component_a, o.component_b);
    EXPECT_TRUE(std::binary_search(graph[o.component_a].begin(), graph[o.component_a].end(),
                                   o.component_b));
  }
  EXPECT_EQ(d.Locate(Eigen::Vector3d(5, 5, 5)) >= 0, true);
  EXPECT_EQ(d.Locate(Eigen::Vector3d(5, 1, 1)), -1);  // Inside the wall.
  EXPECT_EQ(d.Locate(Eigen::Vector3d(20, 5, 5)), -1);
}

TEST(DecomposeFreeSpace3d, CacheHitReturnsTheIdenticalDecomposition) {
  const CacheDir cache;
  const Workspace3d world = testing::WindowWall(1.0);
  const FreeSpaceDecomposition3d first = DecomposeFreeSpace3d(world, Options(cache));
  EXPECT_FALSE(first.from_cache);
  ASSERT_EQ(cache.Files().size(), 1u);  // Written atomically: no temporary file left.
  const FreeSpaceDecomposition3d second = DecomposeFreeSpace3d(world, Options(cache));
  EXPECT_TRUE(second.from_cache);
  EXPECT_EQ(second.key, first.key);
  EXPECT_EQ(second.free_volume, first.free_volume);
  EXPECT_EQ(second.compute_ms, first.compute_ms);  // The original cost, not the read's.
  ASSERT_EQ(second.components.size(), first.components.size());
  for (size_t i = 0; i < first.components.size(); ++i) {
    EXPECT_EQ(second.components[i].centroid, first.components[i].centroid);
    EXPECT_EQ(second.components[i].volume, first.components[i].volume);
    EXPECT_EQ(second.components[i].hull.vertices, first.components[i].hull.vertices);
    EXPECT_EQ(second.components[i].hull.triangles, first.components[i].hull.triangles);
    EXPECT_EQ(second.components[i].planes, first.components[i].planes);
  }
  ASSERT_EQ(second.openings.size(), first.openings.size());
  for (size_t i = 0; i < first.openings.size(); ++i) {
    EXPECT_EQ(second.openings[i].polygon, first.openings[i].polygon);
    EXPECT_EQ(second.openings[i].centroid, first.openings[i].centroid);
    EXPECT_EQ(second.openings[i].normal, first.openings[i].normal);
    EXPECT_EQ(second.openings[i].width, first.openings[i].width);
    EXPECT_EQ(second.openings[i].area, first.openings[i].area);
    EXPECT_EQ(second.openings[i].component_a, first.openings[i].component_a);
    EXPECT_EQ(second.openings[i].component_b, first.openings[i].component_b);
  }
  // Another tau or another world is another entry.
  FreeSpaceDecomposition3dOptions other = Options(cache);
  other.tau = 0.3;
  EXPECT_FALSE(DecomposeFreeSpace3d(world, other).from_cache);
  EXPECT_NE(DecomposeFreeSpace3d(testing::WindowWall(1.5), Options(cache)).key, first.key);
}

TEST(DecomposeFreeSpace3d, CorruptOrStaleEntryIsRecomputed) {
  const CacheDir cache;
  const Workspace3d world = testing::WindowWall(1.0);
  const FreeSpaceDecomposition3d first = DecomposeFreeSpace3d(world, Options(cache));
  ASSERT_EQ(cache.Files().size(), 1u);
  const std::filesystem::path file = cache.Files()[0];
  std::ofstream(file, std::ios::trunc)
      << "acdplan.free_space_decomposition3d/3\nkey " << first.key << "\nbounds 0 0";
  ::testing::internal::CaptureStderr();
  const FreeSpaceDecomposition3d again = DecomposeFreeSpace3d(world, Options(cache));
  const std::string warning = ::testing::internal::GetCapturedStderr();
  EXPECT_FALSE(again.from_cache);
  EXPECT_NE(warning.find("unusable cache entry (truncated)"), std::string::npos) << warning;
  EXPECT_EQ(again.components.size(), first.components.size());
  // A stale entry: another key inside the file.
  std::ofstream(file, std::ios::trunc) << "acdplan.free_space_decomposition3d/3\nkey 0123\n";
  ::testing::internal::CaptureStderr();
  EXPECT_FALSE(DecomposeFreeSpace3d(world, Options(cache)).from_cache);
  EXPECT_NE(::testing::internal::GetCapturedStderr().find("is not its name's"), std::string::npos);
  // Rewritten: the next call hits.
  EXPECT_TRUE(DecomposeFreeSpace3d(world, Options(cache)).from_cache);
}

TEST(DecomposeFreeSpace3d, WithoutCacheWritesNothing) {
  const CacheDir cache;
  const FreeSpaceDecomposition3d d =
      DecomposeFreeSpace3d(testing::WindowWall(1.0), Options(cache, false));
  EXPECT_FALSE(d.from_cache);
  EXPECT_TRUE(cache.Files().empty());
  FreeSpaceDecomposition3dOptions bad;
  bad.tau = -1;
  EXPECT_THROW(DecomposeFreeSpace3d(testing::WindowWall(1.0), bad), InputError);
}

TEST(DecomposeFreeSpace3d, PiecesOfOneCutFaceAreOneOpening) {
  const CacheDir cache;
  FreeSpaceDecomposition3dOptions options = Options(cache, false);
  options.tau = 0.35;  // Small: the solid ACD cuts the world into slabs and splits cut faces.
  const FreeSpaceDecomposition3d d = DecomposeFreeSpace3d(testing::WindowWall(0.4), options);
  ASSERT_GE(d.openings.size(), 2u);
  double area = 0;
  for (size_t i = 0; i < d.openings.size(); ++i) {
    const FreeOpening3d& a = d.openings[i];
    area += a.area;
    EXPECT_GT(a.width, 0);
    // A convex polygon of width w has area >= w^2 / sqrt(3) (the equilateral triangle); the
    // merged pieces may cover less than their hull: a loose bound.
    EXPECT_LE(a.width * a.width, 3 * std::sqrt(3.0) * a.area) << i;
    for (size_t j = i + 1; j < d.openings.size(); ++j) {
      const FreeOpening3d& b = d.openings[j];
      const bool same_plane = a.normal.dot(b.normal) > 1 - 1e-9 &&
                              std::abs(a.normal.dot(a.centroid - b.centroid)) < 1e-9;
      EXPECT_FALSE(a.component_a == b.component_a && a.component_b == b.component_b && same_plane)
          << "openings " << i << " and " << j;
    }
  }
  EXPECT_GT(area, 0);
}

}  // namespace
}  // namespace acdplan::envs
