#include "acd/polygon2d.h"

#include <gtest/gtest.h>

#include <cmath>

namespace acdplan::acd {
namespace {

Polygon2d SquareWithHole() {
  Polygon2d p;
  p.outer = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  p.holes = {{{1, 1}, {1, 2}, {2, 2}, {2, 1}}};  // clockwise
  return p;
}

TEST(Polygon2dTest, SignedAreaFollowsOrientation) {
  const Ring2d ccw = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  EXPECT_DOUBLE_EQ(SignedArea(ccw), 2.0);
  EXPECT_DOUBLE_EQ(SignedArea(Reversed(ccw)), -2.0);
}

// Found by fuzz/fuzz_decompose2d (fuzz/corpus/decompose2d/regression-zero-area-component.wkt):
// the shoelace terms of this quadrilateral are near 3e59 and cancel to 10, so the double sum
// was 0 (and CheckDecomposition() called the component degenerate). The exact sum decides.
TEST(Polygon2dTest, SignedAreaIsExactWhereTheTermsCancel) {
  const Ring2d wedge = {{5e58, 10}, {0, 4}, {0, 0}, {1, 4}};
  EXPECT_EQ(SignedArea(wedge), 5.0);
  EXPECT_EQ(SignedArea(Reversed(wedge)), -5.0);
  // A 2 x 2 square with a spike 5.56e21 long on a base of 1 whose apex is 1 to the side: the
  // spike's area is 0.5, the double terms near 1e22 err by 1e6.
  const Ring2d spike = {{0, 0}, {2, 0}, {2, 1}, {3, 5.56e21}, {2, 2}, {0, 2}};
  EXPECT_EQ(SignedArea(spike), 4.5);
  // Off the line through the other two by one unit in the last place of 2.
  const Ring2d sliver = {{0, 0}, {1e30, 1}, {2e30, std::nextafter(2.0, 3.0)}};
  EXPECT_GT(SignedArea(sliver), 0.0);
  EXPECT_EQ(SignedArea(Ring2d{{0, 0}, {1e30, 1}, {2e30, 2}}), 0.0);
}

TEST(Polygon2dTest, AreaSubtractsHoles) { EXPECT_DOUBLE_EQ(Area(SquareWithHole()), 15.0); }

TEST(Polygon2dTest, CentroidAccountsForHoles) {
  const Point2d c = Centroid(SquareWithHole());
  // (16 * (2,2) - 1 * (1.5,1.5)) / 15
  EXPECT_NEAR(c.x(), (32.0 - 1.5) / 15.0, 1e-12);
  EXPECT_NEAR(c.y(), (32.0 - 1.5) / 15.0, 1e-12);
}

TEST(Polygon2dTest, CentroidIsStableFarFromTheOrigin) {
  Polygon2d p;
  for (const Point2d& v : Ring2d{{0, 0}, {1, 0}, {1, 1}, {0, 1}})
    p.outer.push_back(v + Point2d(1e8, -1e8));
  const Point2d c = Centroid(p);
  EXPECT_NEAR(c.x(), 1e8 + 0.5, 1e-6);
  EXPECT_NEAR(c.y(), -1e8 + 0.5, 1e-6);
}

TEST(Polygon2dTest, ReferenceRadiusIsMaxDistanceFromVertexMean) {
  Polygon2d p;
  p.outer = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_DOUBLE_EQ(ReferenceRadius(p), std::sqrt(2.0));
  EXPECT_EQ(VertexCount(SquareWithHole()), 8);
}

}  // namespace
}  // namespace acdplan::acd
