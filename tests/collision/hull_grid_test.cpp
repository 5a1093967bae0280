#include "collision/internal/hull_grid.h"

#include <gtest/gtest.h>

#include <vector>

#include "acd/convex_hull3d.h"
#include "base/random.h"
#include "tests/asan_build.h"

namespace acdplan::collision::internal {
namespace {

using Planes = Eigen::Matrix<double, Eigen::Dynamic, 4>;

// Seeded random convex hulls (of 4-12 points in a cube of half-side 0.05-0.5, 1-2 for a single
// hull) in [0, 4]^3, the second one flat, with their planes and boxes; z scaled by `z_scale`.
struct RandomHulls {
  std::vector<Planes> planes;
  std::vector<Eigen::AlignedBox3d> boxes;
  std::vector<acd::TriangleMesh> meshes;
};

RandomHulls MakeHulls(int count, std::uint64_t seed, double z_scale = 1) {
  RandomEngine rng(seed);
  RandomHulls out;
  for (int h = 0; h < count; ++h) {
    Eigen::Vector3d centre;
    for (int k = 0; k < 3; ++k) centre[k] = UniformReal(rng, 0.0, 4.0);
    const double radius = count == 1 ? UniformReal(rng, 1.0, 2.0) : UniformReal(rng, 0.05, 0.5);
    const int n = 4 + static_cast<int>(UniformReal(rng, 0.0, 8.99));
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < n; ++i) {
      Eigen::Vector3d p;
      for (int k = 0; k < 3; ++k) p[k] = centre[k] + UniformReal(rng, -radius, radius);
      if (h == 1) p.z() = 1.0;  // flat: thickened by ConvexHull3
      p.z() *= z_scale;
      points.push_back(p);
    }
    const acd::TriangleMesh hull = acd::ConvexHull3(points, 1e-3);
    out.planes.push_back(acd::HullPlanes(hull));
    Eigen::AlignedBox3d box;
    for (Eigen::Index i = 0; i < hull.vertices.rows(); ++i) {
      box.extend(Eigen::Vector3d(hull.vertices.row(i).transpose()));
    }
    out.boxes.push_back(box);
    out.meshes.push_back(hull);
  }
  return out;
}

bool PlainContains(const Planes& planes, const Eigen::Vector3d& p, double slack) {
  for (Eigen::Index r = 0; r < planes.rows(); ++r) {
    if (planes.row(r).head<3>().dot(p) > planes(r, 3) + slack) return false;
  }
  return true;
}

// The hulls that contain `p` by the plain test, in increasing order (as HullGrid::Candidates).
std::vector<int> PlainHullsContaining(const RandomHulls& hulls, const Eigen::Vector3d& p,
                                      double slack) {
  std::vector<int> out;
  for (size_t h = 0; h < hulls.planes.size(); ++h) {
    if (PlainContains(hulls.planes[h], p, slack)) out.push_back(static_cast<int>(h));
  }
  return out;
}

// Random points per scene: under ASan (10-20x slower) a tenth, the same cells and subcells met.
constexpr int kPoints = ACDPLAN_ASAN_BUILD ? 20000 : 200000;

TEST(HullGrid, AnswersAsThePlainTestOnEveryHull) {
  const double slack = 1e-12;
  // Hulls in a cube, in a slab 50 times thinner (flattened cells), and in a cube gridded as if
  // they were prisms along z (three layers of cells in z): the layout never changes an answer.
  struct Scene {
    double z_scale;
    bool prisms_in_z;
  };
  for (const Scene scene : {Scene{1, false}, Scene{0.02, false}, Scene{1, true}})
    for (int count : {1, 7, 120}) {
      SCOPED_TRACE(count);
      SCOPED_TRACE(scene.z_scale);
      SCOPED_TRACE(scene.prisms_in_z);
      const RandomHulls hulls =
          MakeHulls(count, 31 + static_cast<std::uint64_t>(count), scene.z_scale);
      const HullGrid grid(hulls.planes, hulls.boxes, slack, scene.prisms_in_z);
      EXPECT_EQ(grid.size(), count);
      RandomEngine rng(5);
      int inside = 0;
      for (int i = 0; i < kPoints; ++i) {
        Eigen::Vector3d p;
        for (int k = 0; k < 3; ++k) p[k] = UniformReal(rng, -0.5, 4.5);
        p.z() *= scene.z_scale;
        const std::vector<int> expected = PlainHullsContaining(hulls, p, slack);
        std::vector<int> found;
        grid.Candidates(p, &found);
        ASSERT_EQ(found, expected) << p.transpose();
        ASSERT_EQ(grid.AnyContains(p), !expected.empty()) << p.transpose();
        inside += !expected.empty();
      }
      EXPECT_GT(inside, kPoints / 2000);  // the test sees points inside as well as outside
    }
}

TEST(HullGrid, AnswersAsThePlainTestNearHullSurfaces) {
  // Points on the hulls' faces and just off them (along the face normal, both ways): where the
  // cells and their subcells are mixed. A point on a face is inside (the slack keeps it).
  const double slack = 1e-12;
  for (int count : {1, 7, 120}) {
    SCOPED_TRACE(count);
    const RandomHulls hulls = MakeHulls(count, 71 + static_cast<std::uint64_t>(count));
    const HullGrid grid(hulls.planes, hulls.boxes, slack);
    RandomEngine rng(9);
    int inside = 0, outside = 0;
    for (int i = 0; i < kPoints / 2; ++i) {
      const acd::TriangleMesh& mesh =
          hulls.meshes[static_cast<size_t>(UniformReal(rng, 0.0, count - 1e-9))];
      const Eigen::Index f =
          static_cast<Eigen::Index>(UniformReal(rng, 0.0, mesh.triangles.rows() - 1e-9));
      const Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(f, 0)).transpose();
      const Eigen::Vector3d b = mesh.vertices.row(mesh.triangles(f, 1)).transpose();
      const Eigen::Vector3d c = mesh.vertices.row(mesh.triangles(f, 2)).transpose();
      double u = UniformReal(rng, 0.0, 1.0), v = UniformReal(rng, 0.0, 1.0);
      if (u + v > 1) {
        u = 1 - u;
        v = 1 - v;
      }
      Eigen::Vector3d p = a + u * (b - a) + v * (c - a);
      const bool on_face = i % 4 == 0;
      if (!on_face) p += UniformReal(rng, -0.02, 0.02) * (b - a).cross(c - a).normalized();
      const std::vector<int> expected = PlainHullsContaining(hulls, p, slack);
      std::vector<int> found;
      grid.Candidates(p, &found);
      ASSERT_EQ(found, expected) << p.transpose();
      ASSERT_EQ(grid.AnyContains(p), !expected.empty()) << p.transpose();
      if (on_face) {
        ASSERT_TRUE(grid.AnyContains(p)) << p.transpose();
      }
      ++(expected.empty() ? outside : inside);
    }
    EXPECT_GT(inside, kPoints / 20);  // a tenth of the points either way
    EXPECT_GT(outside, kPoints / 20);
  }
}

TEST(HullGrid, PointsOnAHullsBoundaryAndCornersAreInside) {
  // The unit cube's hull: its corners and face centres are inside (the slack keeps them).
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i) corners.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const acd::TriangleMesh cube = acd::ConvexHull3(corners, 0);
  Eigen::AlignedBox3d box(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
  const HullGrid grid({acd::HullPlanes(cube)}, {box}, 1e-12);
  for (const Eigen::Vector3d& c : corners) EXPECT_TRUE(grid.AnyContains(c)) << c.transpose();
  EXPECT_TRUE(grid.AnyContains(Eigen::Vector3d(0.5, 0.5, 1)));
  EXPECT_TRUE(grid.AnyContains(Eigen::Vector3d(0.5, 0.5, 0.5)));
  EXPECT_FALSE(grid.AnyContains(Eigen::Vector3d(0.5, 0.5, 1 + 1e-9)));
  EXPECT_FALSE(grid.AnyContains(Eigen::Vector3d(-1e-9, 0.5, 0.5)));
}

TEST(HullGrid, CellsAreCubicExceptOnAThinAxis) {
  const auto cells = [](const Eigen::Vector3d& extent, const Eigen::Vector3i& fixed) {
    return HullGrid::CellsPerAxis(extent, fixed);
  };
  const auto about_target = [](const Eigen::Vector3i& c) {
    const double n = static_cast<double>(c.x()) * c.y() * c.z();
    return n >= HullGrid::kTargetCells && n <= 1.1 * HullGrid::kTargetCells;
  };
  const Eigen::Vector3i none = Eigen::Vector3i::Zero();
  const Eigen::Vector3i cube = cells({2, 2, 2}, none);
  EXPECT_EQ(cube, Eigen::Vector3i(41, 41, 41));
  EXPECT_EQ(HullGrid::CellsPerAxis({2, 2, 2}, none, HullGrid::kFineCells),
            Eigen::Vector3i(64, 64, 64));  // 64^3 = 2^18
  // A slab: kMinCellsPerAxis across it, the rest cubic.
  const Eigen::Vector3i slab = cells({10, 10, 0.1}, none);
  EXPECT_EQ(slab.z(), HullGrid::kMinCellsPerAxis);
  EXPECT_EQ(slab.x(), slab.y());
  EXPECT_TRUE(about_target(slab)) << slab.transpose();
  // A rod: two thin axes.
  const Eigen::Vector3i rod = cells({0.1, 10, 0.1}, none);
  EXPECT_EQ(rod, Eigen::Vector3i(16, 256, 16));
  // A fixed axis, and an axis without extent.
  const Eigen::Vector3i prisms = cells({5, 5, 1}, Eigen::Vector3i(0, 0, 3));
  EXPECT_EQ(prisms.z(), 3);
  EXPECT_TRUE(about_target(prisms)) << prisms.transpose();
  EXPECT_EQ(cells({5, 5, 0}, none).z(), 1);
}

TEST(HullGrid, EmptyGridContainsNothing) {
  const HullGrid grid({}, {}, 0);
  EXPECT_FALSE(grid.AnyContains(Eigen::Vector3d::Zero()));
  std::vector<int> found;
  grid.Candidates(Eigen::Vector3d::Zero(), &found);
  EXPECT_TRUE(found.empty());
}

}  // namespace
}  // namespace acdplan::collision::internal
