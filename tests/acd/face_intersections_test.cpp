#include "acd/internal/face_intersections.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "solid_test_meshes.h"

namespace acdplan::acd::internal {
namespace {

std::vector<int> FacesFrom(int begin, int end) {
  std::vector<int> faces(static_cast<size_t>(end - begin));
  std::iota(faces.begin(), faces.end(), begin);
  return faces;
}

TEST(FaceIntersections, FacesThatShareAnEdgeOrAVertexDoNotCount) {
  const TriangleMesh box = test::Box({0, 0, 0}, {1, 1, 1});
  EXPECT_TRUE(IntersectingFacePairs(box).empty());
  EXPECT_FALSE(AnyFaceIntersects(box, FacesFrom(0, 12)));
}

TEST(FaceIntersections, CrossingAndTouchingShellsArePairs) {
  const TriangleMesh a = test::Box({0, 0, 0}, {1, 1, 1});
  // b crosses a; c only touches a's face x = 1 (no shared vertex index, so a common point
  // counts); d is apart from both.
  const TriangleMesh b = test::Box({0.5, 0.25, 0.25}, {1.5, 0.75, 0.75});
  const TriangleMesh c = test::Box({1, 0, 0}, {2, 1, 1});
  const TriangleMesh d = test::Box({5, 5, 5}, {6, 6, 6});
  const TriangleMesh ab = test::Concatenate(a, b);
  const std::vector<std::pair<int, int>> pairs = IntersectingFacePairs(ab);
  ASSERT_FALSE(pairs.empty());
  for (const auto& [f, g] : pairs) {
    EXPECT_LT(f, 12);  // one face of a, one of b
    EXPECT_GE(g, 12);
  }
  EXPECT_TRUE(std::is_sorted(pairs.begin(), pairs.end()));
  EXPECT_FALSE(IntersectingFacePairs(test::Concatenate(a, c)).empty());

  // Only pairs with a listed face are tested: with d's faces listed, a and b's crossing is not
  // seen; with b's, it is.
  const TriangleMesh abd = test::Concatenate(ab, d);
  EXPECT_FALSE(AnyFaceIntersects(abd, FacesFrom(24, 36)));
  EXPECT_TRUE(AnyFaceIntersects(abd, FacesFrom(12, 24)));
  EXPECT_TRUE(AnyFaceIntersects(abd, {pairs.front().first}));
  EXPECT_FALSE(AnyFaceIntersects(abd, {}));
  // Two listed faces that cross each other.
  EXPECT_TRUE(AnyFaceIntersects(ab, {pairs.front().first, pairs.front().second}));
}

}  // namespace
}  // namespace acdplan::acd::internal
