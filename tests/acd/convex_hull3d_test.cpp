// ConvexHull3 and HullPlanes: the half-spaces contain every point the hull was built from, also
// when nearly collinear points make sliver facets (the cut faces of the 3D ACD's pieces do); the
// hull mesh is the same bytes for the same set of points, and closed without degenerate faces.

#include "acd/convex_hull3d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "acd/mesh_measures.h"
#include "base/random.h"
#include "solid_test_meshes.h"

namespace acdplan::acd {
namespace {

/// Largest n . p - d over the rows of `planes` and the `points`.
double WorstViolation(const Eigen::Matrix<double, Eigen::Dynamic, 4>& planes,
                      const std::vector<Eigen::Vector3d>& points) {
  double worst = -1e300;
  for (const Eigen::Vector3d& p : points) {
    for (Eigen::Index r = 0; r < planes.rows(); ++r) {
      worst = std::max(worst, planes.row(r).head<3>().dot(p) - planes(r, 3));
    }
  }
  return worst;
}

TEST(HullPlanes, ACubeHasSixPlanes) {
  const TriangleMesh cube = Cube(2);
  const Eigen::Matrix<double, Eigen::Dynamic, 4> planes = HullPlanes(cube);
  EXPECT_EQ(planes.rows(), 6);
  for (Eigen::Index r = 0; r < planes.rows(); ++r) EXPECT_NEAR(planes(r, 3), 1.0, 1e-15);
}

TEST(HullPlanes, ContainEveryPointDespiteSliverFacets) {
  // Points on a few long segments, each point off its segment by rounding-sized amounts: the
  // hull has facets with nearly collinear corners.
  RandomEngine rng(7);
  double worst = -1e300;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Eigen::Vector3d> points;
    for (int segment = 0; segment < 4; ++segment) {
      Eigen::Vector3d a, b;
      for (int k = 0; k < 3; ++k) a[k] = UniformReal(rng, -1.0, 1.0);
      for (int k = 0; k < 3; ++k) b[k] = UniformReal(rng, -1.0, 1.0);
      for (int i = 0; i < 12; ++i) {
        const double t = UniformReal(rng, 0.0, 1.0);
        Eigen::Vector3d noise;
        for (int k = 0; k < 3; ++k) noise[k] = UniformReal(rng, -1e-13, 1e-13);
        points.push_back(a + t * (b - a) + noise);
      }
    }
    const TriangleMesh hull = ConvexHull3(points, 0.0);
    ASSERT_GT(MeshVolume(hull), 0.0);
    worst = std::max(worst, WorstViolation(HullPlanes(hull), points));
  }
  EXPECT_LE(worst, 1e-14);
}

// Heap blocks of varied sizes kept alive across a run, so that the run's allocations (CGAL's
// hull is a linked structure) land at other addresses.
std::vector<std::unique_ptr<char[]>> Garbage(RandomEngine& rng) {
  std::vector<std::unique_ptr<char[]>> blocks;
  const int count = 20 + static_cast<int>(UniformIndex(rng, 200));
  for (int i = 0; i < count; ++i) {
    const size_t size = 8 + UniformIndex(rng, 4000);
    blocks.emplace_back(new char[size]);
    std::memset(blocks.back().get(), 0x5a, size);
  }
  return blocks;
}

// The box [0, a] x [0, b] x [0, c] as points: an (n + 1) x (n + 1) grid on each face (so its
// edges carry collinear points and its faces coplanar ones) and a few points inside.
std::vector<Eigen::Vector3d> GriddedBox(const Eigen::Vector3d& size, int n) {
  std::vector<Eigen::Vector3d> points;
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
          Eigen::Vector3d p;
          p[axis] = side * size[axis];
          p[(axis + 1) % 3] = size[(axis + 1) % 3] * i / n;
          p[(axis + 2) % 3] = size[(axis + 2) % 3] * j / n;
          points.push_back(p);
        }
      }
    }
  }
  for (int i = 1; i < 4; ++i) points.push_back(size * i / 4);
  return points;
}

// The prism over a hexagon (z from 0 to 2) as points: its 12 corners, 3 points inside each edge,
// 3 x 3 points inside each side face and points on the caps (all exactly representable, so
// exactly collinear and coplanar where they should be).
std::vector<Eigen::Vector3d> GriddedHexagonalPrism() {
  const std::vector<Eigen::Vector3d> hexagon = {{2, 0, 0},  {1, 2, 0},   {-1, 2, 0},
                                                {-2, 0, 0}, {-1, -2, 0}, {1, -2, 0}};
  std::vector<Eigen::Vector3d> points;
  const Eigen::Vector3d up(0, 0, 2);
  for (size_t k = 0; k < hexagon.size(); ++k) {
    const Eigen::Vector3d& a = hexagon[k];
    const Eigen::Vector3d& b = hexagon[(k + 1) % hexagon.size()];
    for (int i = 0; i <= 4; ++i) {
      for (int j = 0; j <= 4; ++j) points.push_back(a + (b - a) * i / 4 + up * j / 4);
      points.push_back((a + (b - a) * i / 4) / 2);       // on the bottom cap
      points.push_back((a + (b - a) * i / 4) / 2 + up);  // on the top cap
    }
  }
  return points;
}

// "" if each edge of `mesh` is used once in each direction (closed, manifold along edges,
// consistently oriented), else the first offending edge.
std::string ClosedManifoldProblem(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> uses;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    for (int k = 0; k < 3; ++k) ++uses[{mesh.triangles(f, k), mesh.triangles(f, (k + 1) % 3)}];
  }
  for (const auto& [edge, count] : uses) {
    const auto back = uses.find({edge.second, edge.first});
    if (count != 1 || back == uses.end() || back->second != 1) {
      return "edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second);
    }
  }
  return "";
}

// Twice the area of each triangle, the smallest.
double SmallestDoubleArea(const TriangleMesh& mesh) {
  double smallest = 1e300;
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(f, 0));
    const Eigen::Vector3d b = mesh.vertices.row(mesh.triangles(f, 1));
    const Eigen::Vector3d c = mesh.vertices.row(mesh.triangles(f, 2));
    smallest = std::min(smallest, (b - a).cross(c - a).norm());
  }
  return smallest;
}

TEST(ConvexHull3, TrianglesDependOnThePointSetAlone) {
  // CGAL's convex_hull_3 draws the diagonals of a facet with >= 4 corners in an order that
  // follows the input order and heap addresses; the mesh must not.
  RandomEngine rng(11);
  std::vector<std::vector<Eigen::Vector3d>> shapes = {
      GriddedBox({1, 2, 3}, 6),
      GriddedHexagonalPrism(),
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}}};  // flat
  std::vector<Eigen::Vector3d> cloud;  // random, with a coplanar patch and duplicates
  for (int i = 0; i < 200; ++i) {
    Eigen::Vector3d p(UniformReal(rng, -1, 1), UniformReal(rng, -1, 1), UniformReal(rng, -1, 1));
    if (i % 3 == 0) p.z() = 1;
    cloud.push_back(p);
    if (i % 7 == 0) cloud.push_back(p);
  }
  shapes.push_back(cloud);
  for (size_t s = 0; s < shapes.size(); ++s) {
    std::vector<Eigen::Vector3d> points = shapes[s];
    const std::string expected = test::Bytes(ConvexHull3(points, 0.0));
    for (int run = 1; run <= 6; ++run) {
      for (size_t i = points.size(); i > 1; --i)
        std::swap(points[i - 1], points[UniformIndex(rng, i)]);
      const auto garbage = Garbage(rng);
      EXPECT_TRUE(test::Bytes(ConvexHull3(points, 0.0)) == expected)
          << "shape " << s << " run " << run;
    }
  }
}

TEST(ConvexHull3, GriddedBoxIsItsCornersAndTwelveTriangles) {
  const Eigen::Vector3d size(1, 2, 3);
  const TriangleMesh hull = ConvexHull3(GriddedBox(size, 6), 0.0);
  ASSERT_EQ(hull.vertices.rows(), 8);  // No grid point inside a face or an edge is kept.
  for (Eigen::Index v = 0; v < 8; ++v) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(hull.vertices(v, k) == 0 || hull.vertices(v, k) == size[k])
          << hull.vertices.row(v);
    }
  }
  EXPECT_EQ(hull.triangles.rows(), 12);
  EXPECT_EQ(ClosedManifoldProblem(hull), "");
  EXPECT_NEAR(MeshVolume(hull), 6.0, 1e-14);
  EXPECT_GT(SmallestDoubleArea(hull), 0.0);
}

TEST(ConvexHull3, GriddedPrismHasNoDegenerateTriangle) {
  // Collinear points along every edge: a fan over all of a facet's boundary points would make
  // zero-area triangles; only the 12 corners are vertices.
  const TriangleMesh hull = ConvexHull3(GriddedHexagonalPrism(), 0.0);
  EXPECT_EQ(hull.vertices.rows(), 12);
  EXPECT_EQ(hull.triangles.rows(), 2 * 4 + 6 * 2);
  EXPECT_EQ(ClosedManifoldProblem(hull), "");
  EXPECT_GT(SmallestDoubleArea(hull), 1.0);
  EXPECT_NEAR(MeshVolume(hull), 12.0 * 2, 1e-13);  // hexagon area 12, height 2
}

TEST(ConvexHull3, RandomSetsGiveClosedHullsOverTheirOwnPoints) {
  RandomEngine rng(5);
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<Eigen::Vector3d> points;
    const int n = 4 + static_cast<int>(UniformIndex(rng, 60));
    for (int i = 0; i < n; ++i) {
      Eigen::Vector3d p(UniformReal(rng, -1, 1), UniformReal(rng, -1, 1), UniformReal(rng, -1, 1));
      // Snapped to a few coordinate values, so facets with many coplanar corners and edges with
      // collinear points are common.
      if (trial % 2 == 0) p = (p * 2).array().round().matrix() / 2;
      points.push_back(p);
    }
    const TriangleMesh hull = ConvexHull3(points, 0.0);
    if (hull.triangles.rows() == 0) continue;
    const double volume = MeshVolume(hull);
    if (!(volume > 0)) continue;  // a flat set: one-sided
    EXPECT_EQ(ClosedManifoldProblem(hull), "") << "trial " << trial;
    EXPECT_EQ(hull.vertices.rows() - hull.triangles.rows() * 3 / 2 + hull.triangles.rows(), 2)
        << "trial " << trial << ": Euler characteristic of a sphere";
    EXPECT_GT(SmallestDoubleArea(hull), 0.0) << "trial " << trial;
    for (Eigen::Index v = 0; v < hull.vertices.rows(); ++v) {
      const Eigen::Vector3d p = hull.vertices.row(v);
      EXPECT_NE(std::find(points.begin(), points.end(), p), points.end()) << "trial " << trial;
    }
    EXPECT_LE(WorstViolation(HullPlanes(hull), points), 1e-14) << "trial " << trial;
  }
}

TEST(ConvexHull3, FlatAndCollinearSets) {
  // A flat set: one side, counter-clockwise about +z whatever the input order.
  std::vector<Eigen::Vector3d> square = {{0, 0, 0}, {1, 0, 0}, {0.5, 0, 0},
                                         {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}};
  for (int turn = 0; turn < 2; ++turn) {
    const TriangleMesh hull = ConvexHull3(square, 0.0);
    ASSERT_EQ(hull.vertices.rows(), 4);
    ASSERT_EQ(hull.triangles.rows(), 2);
    for (Eigen::Index f = 0; f < 2; ++f) {
      const Eigen::Vector3d a = hull.vertices.row(hull.triangles(f, 0));
      const Eigen::Vector3d b = hull.vertices.row(hull.triangles(f, 1));
      const Eigen::Vector3d c = hull.vertices.row(hull.triangles(f, 2));
      EXPECT_GT((b - a).cross(c - a).z(), 0.0);
    }
    std::reverse(square.begin(), square.end());
  }
  // A segment: its two ends, no triangle.
  const TriangleMesh segment =
      ConvexHull3({{0.5, 0.5, 0.5}, {0, 0, 0}, {1, 1, 1}, {0.25, 0.25, 0.25}}, 0.0);
  ASSERT_EQ(segment.vertices.rows(), 2);
  EXPECT_EQ(segment.triangles.rows(), 0);
  EXPECT_EQ(Eigen::Vector3d(segment.vertices.row(0)), Eigen::Vector3d(0, 0, 0));
  EXPECT_EQ(Eigen::Vector3d(segment.vertices.row(1)), Eigen::Vector3d(1, 1, 1));
}

}  // namespace
}  // namespace acdplan::acd
