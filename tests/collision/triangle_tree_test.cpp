#include "collision/internal/triangle_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "base/random.h"

namespace acdplan::collision::internal {
namespace {

Eigen::AlignedBox3d BoxOf(const Triangle3& t) {
  Eigen::AlignedBox3d box(t[0]);
  return box.extend(t[1]).extend(t[2]);
}

// Random triangles of very different sizes (a few span the whole scene): every query visits
// exactly the triangles whose boxes meet its box, once each.
TEST(TriangleTree, VisitsExactlyTheTrianglesWhoseBoxesMeetTheQuery) {
  RandomEngine rng(5);
  auto uniform = [&rng](double lo, double hi) {
    return Eigen::Vector3d(UniformReal(rng, lo, hi), UniformReal(rng, lo, hi),
                           UniformReal(rng, lo, hi));
  };
  std::vector<Triangle3> triangles;
  for (int i = 0; i < 3000; ++i) {
    const double size = i % 500 == 0 ? 10.0 : UniformReal(rng, 0.001, 0.2);
    const Eigen::Vector3d center = uniform(-5, 5);
    triangles.push_back({center + size * uniform(-1, 1), center + size * uniform(-1, 1),
                         center + size * uniform(-1, 1)});
  }
  const TriangleTree tree(triangles);
  ASSERT_EQ(tree.size(), triangles.size());
  int nonempty = 0;
  for (int query = 0; query < 300; ++query) {
    const Eigen::Vector3d corner = uniform(-6, 6);
    const Eigen::AlignedBox3d box(corner, corner + uniform(0, 1.5));
    std::vector<double> expected, visited;  // a triangle named by its first coordinate
    for (const Triangle3& t : triangles) {
      if (BoxOf(t).intersects(box)) expected.push_back(t[0].x());
    }
    EXPECT_FALSE(tree.AnyNear(box, [&visited](const Triangle3& t) {
      visited.push_back(t[0].x());
      return false;
    }));
    std::sort(expected.begin(), expected.end());
    std::sort(visited.begin(), visited.end());
    EXPECT_EQ(visited, expected) << query;
    nonempty += !expected.empty();
    // A test that accepts one of them stops there.
    if (!expected.empty()) {
      int calls = 0;
      EXPECT_TRUE(tree.AnyNear(box, [&](const Triangle3& t) {
        ++calls;
        return t[0].x() == expected.front();
      }));
      EXPECT_LE(calls, static_cast<int>(expected.size()));
    }
  }
  EXPECT_GT(nonempty, 100);
}

TEST(TriangleTree, EmptyTreeFindsNothing) {
  const TriangleTree tree;
  EXPECT_FALSE(tree.AnyNear(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()),
                            [](const Triangle3&) { return true; }));
}

}  // namespace
}  // namespace acdplan::collision::internal
