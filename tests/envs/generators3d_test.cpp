// 3D generators: closed solid obstacles inside the bounds, a passage that is really open
// (its centre is free and a segment through it misses every obstacle), exact volumes, seeds.

#include "envs/generators3d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "acd/mesh_measures.h"
#include "acd/prepare_mesh.h"
#include "acd/triangle_mesh.h"
#include "base/input_error.h"
#include "envs/load_workspace.h"
#include "envs/mesh_loader.h"
#include "envs/workspace_yaml.h"
#include "tests/data_paths.h"

namespace acdplan::envs {
namespace {

using Eigen::Vector3d;

/// Whether segment [p, q] meets triangle (a, b, c) (Moller-Trumbore; touching counts).
bool SegmentHitsTriangle(const Vector3d& p, const Vector3d& q, const Vector3d& a, const Vector3d& b,
                         const Vector3d& c) {
  const Vector3d d = q - p, e1 = b - a, e2 = c - a;
  const Vector3d h = d.cross(e2);
  const double det = e1.dot(h);
  if (std::abs(det) < 1e-14) return false;  // parallel: the layouts never graze a face
  const Vector3d s = p - a;
  const double u = s.dot(h) / det;
  if (u < -1e-12 || u > 1 + 1e-12) return false;
  const Vector3d r = s.cross(e1);
  const double v = d.dot(r) / det;
  if (v < -1e-12 || u + v > 1 + 1e-12) return false;
  const double t = e2.dot(r) / det;
  return t >= -1e-12 && t <= 1 + 1e-12;
}

bool SegmentHitsMesh(const Vector3d& p, const Vector3d& q, const acd::TriangleMesh& mesh) {
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    if (SegmentHitsTriangle(p, q, mesh.vertices.row(mesh.triangles(f, 0)),
                            mesh.vertices.row(mesh.triangles(f, 1)),
                            mesh.vertices.row(mesh.triangles(f, 2)))) {
      return true;
    }
  }
  return false;
}

/// Ray parity, the majority of three rays in directions no grid face or edge is parallel to
/// (a ray through a shared edge would count it twice).
bool InsideMesh(const Vector3d& p, const acd::TriangleMesh& mesh) {
  const Vector3d directions[3] = {Vector3d(0.5773, 0.6234, 0.5271),
                                  Vector3d(-0.4127, 0.7316, -0.5423),
                                  Vector3d(0.6911, -0.3297, 0.6431)};
  int votes = 0;
  for (const Vector3d& direction : directions) {
    const Vector3d far = p + 1e4 * direction;
    int crossings = 0;
    for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
      crossings += SegmentHitsTriangle(p, far, mesh.vertices.row(mesh.triangles(f, 0)),
                                       mesh.vertices.row(mesh.triangles(f, 1)),
                                       mesh.vertices.row(mesh.triangles(f, 2)));
    }
    votes += crossings % 2;
  }
  return votes >= 2;
}

std::vector<Eigen::AlignedBox3d> ObstacleBoxes(const Workspace3d& w) {
  std::vector<Eigen::AlignedBox3d> boxes;
  for (const acd::TriangleMesh& o : w.obstacles) boxes.push_back(acd::BoundingBox(o));
  return boxes;
}

/// Whether `p` is outside every obstacle, `boxes` their boxes (ObstacleBoxes()): the ray test
/// only for an obstacle whose box holds p (FreeSpaceIsConnected's grid is mostly outside them).
bool Free(const Workspace3d& w, const std::vector<Eigen::AlignedBox3d>& boxes, const Vector3d& p) {
  for (size_t i = 0; i < w.obstacles.size(); ++i) {
    if (boxes[i].contains(p) && InsideMesh(p, w.obstacles[i])) return false;
  }
  return true;
}

bool Free(const Workspace3d& w, const Vector3d& p) { return Free(w, ObstacleBoxes(w), p); }

bool SegmentFree(const Workspace3d& w, const Vector3d& p, const Vector3d& q) {
  for (const acd::TriangleMesh& o : w.obstacles) {
    if (SegmentHitsMesh(p, q, o)) return false;
  }
  return true;
}

/// The segment through `passage` along its axis, `margin` beyond both ends.
std::pair<Vector3d, Vector3d> Through(const Passage3d& passage, double margin) {
  Vector3d p = passage.box.center(), q = passage.box.center();
  p[passage.axis] = passage.box.min()[passage.axis] - margin;
  q[passage.axis] = passage.box.max()[passage.axis] + margin;
  return {p, q};
}

class Generator3dTest : public ::testing::TestWithParam<std::string> {};

TEST_P(Generator3dTest, ObstaclesAreSolidAndInsideTheBounds) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Workspace3d w = GenerateWorkspace3d(GetParam(), seed);
    ASSERT_FALSE(w.obstacles.empty());
    EXPECT_NE(w.description.find(GetParam() + ":"), std::string::npos) << w.description;
    for (size_t i = 0; i < w.obstacles.size(); ++i) {
      const acd::PreparedMesh prepared = acd::PrepareMesh(w.obstacles[i]);
      EXPECT_TRUE(prepared.solid()) << "obstacle " << i << ": " << prepared.defects.first;
      EXPECT_GT(acd::MeshVolume(w.obstacles[i]), 0.0);  // outward
      const Eigen::AlignedBox3d box = acd::BoundingBox(w.obstacles[i]);
      EXPECT_TRUE(w.bounds.contains(box)) << i;
      for (size_t j = 0; j < i; ++j) {  // disjoint: the slabs of cubicles
        EXPECT_TRUE(box.intersection(acd::BoundingBox(w.obstacles[j])).isEmpty()) << i << j;
      }
    }
  }
}

TEST_P(Generator3dTest, ThePassagesAreOpen) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    Passages3d passages;
    const Workspace3d w = GenerateWorkspace3d(GetParam(), seed, {}, &passages);
    ASSERT_FALSE(passages.empty());
    for (const Passage3d& passage : passages) {
      EXPECT_TRUE(w.bounds.contains(passage.box));
      EXPECT_TRUE(Free(w, passage.box.center()));
      // Through the passage and beyond (a tube leg ends in material: only along it).
      const auto [p, q] = Through(passage, GetParam() == "bent_tube" ? -1e-6 : 0.25);
      EXPECT_TRUE(SegmentFree(w, p, q));
      // The same segment moved sideways by 3/4 of the passage meets the material around it
      // (crosses its surface, or lies in it: a tube leg's neighbour is solid material).
      const int across = (passage.axis + 1) % 3;
      Vector3d side = Vector3d::Zero();
      side[across] = 0.75 * passage.box.sizes()[across];
      if (passage.box.max()[across] + side[across] > w.bounds.max()[across]) side = -side;
      EXPECT_FALSE(SegmentFree(w, p + side, q + side) && Free(w, p + side));
      EXPECT_FALSE(Free(w, passage.box.center() + side));
    }
  }
}

TEST_P(Generator3dTest, FreeSpaceIsConnected) {
  // Free sample points on a grid of spacing h (every wall is thicker than h, so no two free
  // points on opposite sides of a wall are neighbours; every passage is wider than 2h, so it
  // holds free points) form one 6-connected set.
  const Workspace3d w = GenerateWorkspace3d(GetParam(), 2);
  const double h = 0.25;
  Eigen::Vector3i n;
  for (int a = 0; a < 3; ++a) n[a] = static_cast<int>(std::floor(w.bounds.sizes()[a] / h));
  auto index = [&n](int i, int j, int k) { return (static_cast<size_t>(k) * n[1] + j) * n[0] + i; };
  std::vector<char> free(static_cast<size_t>(n.prod()), 0);
  const std::vector<Eigen::AlignedBox3d> boxes = ObstacleBoxes(w);
  size_t free_count = 0, first = 0;
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        const Vector3d p = w.bounds.min() + h * Vector3d(i + 0.5, j + 0.5, k + 0.5);
        if (Free(w, boxes, p)) {
          if (free_count++ == 0) first = index(i, j, k);
          free[index(i, j, k)] = 1;
        }
      }
    }
  }
  ASSERT_GT(free_count, 0u);
  std::vector<size_t> stack = {first};
  free[first] = 2;
  size_t reached = 1;
  while (!stack.empty()) {
    const size_t c = stack.back();
    stack.pop_back();
    const int i = static_cast<int>(c % n[0]), j = static_cast<int>(c / n[0] % n[1]),
              k = static_cast<int>(c / (static_cast<size_t>(n[0]) * n[1]));
    const int step[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const auto& d : step) {
      const int a = i + d[0], b = j + d[1], e = k + d[2];
      if (a < 0 || b < 0 || e < 0 || a >= n[0] || b >= n[1] || e >= n[2]) continue;
      const size_t next = index(a, b, e);
      if (free[next] == 1) {
        free[next] = 2;
        ++reached;
        stack.push_back(next);
      }
    }
  }
  EXPECT_EQ(reached, free_count);
}

TEST_P(Generator3dTest, SameSeedSameWorldOtherSeedOtherWorld) {
  const Workspace3d a = GenerateWorkspace3d(GetParam(), 7);
  const Workspace3d b = GenerateWorkspace3d(GetParam(), 7);
  const Workspace3d c = GenerateWorkspace3d(GetParam(), 8);
  ASSERT_EQ(a.obstacles.size(), b.obstacles.size());
  for (size_t i = 0; i < a.obstacles.size(); ++i) {
    EXPECT_EQ(a.obstacles[i].vertices, b.obstacles[i].vertices);
    EXPECT_EQ(a.obstacles[i].triangles, b.obstacles[i].triangles);
  }
  EXPECT_NE(a.obstacles.front().vertices, c.obstacles.front().vertices);
}

INSTANTIATE_TEST_SUITE_P(All, Generator3dTest, ::testing::ValuesIn(Generator3dNames()),
                         [](const auto& info) { return info.param; });

TEST(Generators3d, VolumesAreExact) {
  WindowWallOptions wall;
  wall.window_side = 1.5;
  const Workspace3d w = MakeWindowWall(3, wall);
  ASSERT_EQ(w.obstacles.size(), 1u);
  EXPECT_NEAR(acd::MeshVolume(w.obstacles[0]), 0.5 * 10 * 10 - 0.5 * 1.5 * 1.5, 1e-9);

  const Workspace3d trap = MakeBugTrap3d(3);
  // Cage 5^3 - 4.2^3, minus the mouth through the wall, plus the funnel's walls.
  const double funnel = 1.5 * ((0.8 + 0.8) * (0.8 + 0.8) - 0.8 * 0.8);
  EXPECT_NEAR(acd::MeshVolume(trap.obstacles[0]), 125 - 4.2 * 4.2 * 4.2 - 0.4 * 0.8 * 0.8 + funnel,
              1e-9);

  const Workspace3d rooms = MakeCubicles(3);
  ASSERT_EQ(rooms.obstacles.size(), 2u);
  for (const acd::TriangleMesh& slab : rooms.obstacles) {
    EXPECT_NEAR(acd::MeshVolume(slab), 0.3 * (100 - 1), 1e-9);
  }

  BentTubeOptions two;
  two.bends = 2;
  Passages3d legs;
  const Workspace3d tube = MakeBentTube(3, two, &legs);
  ASSERT_EQ(legs.size(), 3u);
  // The legs overlap in one tube cube at each bend.
  double free = -2 * 1.0;
  for (const Passage3d& leg : legs) free += leg.box.volume();
  EXPECT_NEAR(acd::MeshVolume(tube.obstacles[0]), 1000 - free, 1e-9);
}

TEST(Generators3d, ShippedWorldsMatchTheGenerators) {
  // envs/3d/<name>.yaml is the default instance with seed 1 (acdplan_generate_envs).
  for (const std::string& name : Generator3dNames()) {
    SCOPED_TRACE(name);
    const Workspace3d expected = GenerateWorkspace3d(name, 1);
    const std::string path = acdplan::test::SourceDir() + "/envs/3d/" + name + ".yaml";
    const Workspace3d shipped = LoadWorkspace3dYaml(path);
    EXPECT_EQ(shipped.description, expected.description);
    EXPECT_TRUE(shipped.bounds.isApprox(expected.bounds));
    ASSERT_EQ(shipped.obstacles.size(), expected.obstacles.size());
    for (size_t i = 0; i < shipped.obstacles.size(); ++i) {
      EXPECT_EQ(shipped.obstacles[i].triangles.rows(), expected.obstacles[i].triangles.rows());
      // assimp reads OBJ coordinates as floats.
      const Eigen::AlignedBox3d a = acd::BoundingBox(shipped.obstacles[i]);
      const Eigen::AlignedBox3d b = acd::BoundingBox(expected.obstacles[i]);
      EXPECT_LT((a.min() - b.min()).norm() + (a.max() - b.max()).norm(), 1e-5);
      EXPECT_NEAR(acd::MeshVolume(shipped.obstacles[i]), acd::MeshVolume(expected.obstacles[i]),
                  1e-6 * acd::MeshVolume(expected.obstacles[i]));
      EXPECT_TRUE(acd::PrepareMesh(shipped.obstacles[i]).solid());
    }
    EXPECT_EQ(LoadWorld(path).dimension, 3);
  }
}

TEST(Generators3d, RobotMeshesAreClosedSolids) {
  const std::string robots = acdplan::test::DataDir() + "/robots/";
  const acd::TriangleMesh rod = ReadMesh(robots + "rod.obj");
  EXPECT_TRUE(acd::PrepareMesh(rod).solid());
  EXPECT_NEAR(acd::MeshVolume(rod), 3 * 0.5 * 0.5, 1e-6);  // assimp reads floats
  EXPECT_TRUE(acd::BoundingBox(rod).center().isZero(1e-6));
  const acd::TriangleMesh l_shape = ReadMesh(robots + "l_shape.obj");
  EXPECT_TRUE(acd::PrepareMesh(l_shape).solid());
  EXPECT_NEAR(acd::MeshVolume(l_shape), (2 * 0.4 + 0.4 * 1.2) * 0.4, 1e-6);
}

TEST(Generators3d, ErrorsNameTheFunctionAndTheRule) {
  auto error_of = [](const std::function<void()>& f) -> std::string {
    try {
      f();
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  };
  EXPECT_EQ(error_of([] { GenerateWorkspace3d("tunnel", 1); }),
            "GenerateWorkspace3d(): unknown generator 'tunnel' (expected one of: window_wall, "
            "bug_trap3d, cubicles, bent_tube)");
  EXPECT_NE(error_of([] {
              GenerateWorkspace3d("bent_tube", 1, {0, 0.2});
            }).find("bent_tube has no wall_thickness"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              GenerateWorkspace3d("window_wall", 1, {-1, 0});
            }).find("passage_width must be a finite number >= 0"),
            std::string::npos);
  EXPECT_EQ(error_of([] {
              GenerateWorkspace3d("window_wall", 1, {20, 0});
            }),
            "GenerateWorkspace3d(): MakeWindowWall(): window_side must be in (0, min(depth, "
            "height))");
  EXPECT_NE(error_of([] {
              MakeCubicles(1, {10, 10, 1});
            }).find("floors must be >= 2"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              MakeBugTrap3d(1, {10, 5, 0.4, 4.0});
            }).find("trap_size > mouth_side"),
            std::string::npos);
}

}  // namespace
}  // namespace acdplan::envs
