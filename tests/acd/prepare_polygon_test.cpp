#include "acd/prepare_polygon.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "base/input_error.h"
#include "tests/input_error_of.h"
#include "tests/polygon_fixtures.h"

namespace acdplan::acd {
namespace {

using acdplan::test::SquareRing;
using ::testing::AllOf;
using ::testing::HasSubstr;

// The message of the acdplan::InputError PreparePolygon() throws, or "" if it does not throw.
std::string PreparePolygonErrorOf(const Polygon2d& raw) {
  return acdplan::test::InputErrorOf([&] { PreparePolygon(raw, "test.poly: polygon 0"); });
}

TEST(PreparePolygonTest, KeepsCleanCounterClockwiseSquare) {
  const Polygon2d clean = PreparePolygon({SquareRing(0, 0, 1), {}}, "w");
  EXPECT_EQ(clean.outer, SquareRing(0, 0, 1));
  EXPECT_DOUBLE_EQ(Area(clean), 1.0);
}

TEST(PreparePolygonTest, ReorientsClockwiseOuterAndCounterClockwiseHole) {
  const Polygon2d raw{Reversed(SquareRing(0, 0, 4)), {SquareRing(1, 1, 1)}};
  const Polygon2d clean = PreparePolygon(raw, "w");
  EXPECT_GT(SignedArea(clean.outer), 0.0);
  ASSERT_EQ(clean.holes.size(), 1u);
  EXPECT_LT(SignedArea(clean.holes[0]), 0.0);
  EXPECT_DOUBLE_EQ(Area(clean), 15.0);
}

TEST(PreparePolygonTest, DropsDuplicatesClosingVertexCollinearAndSpikes) {
  // A square with a repeated vertex, a collinear midpoint, a zero-width spike (2,1)->(2,3)->
  // (2,1.5) on the right side, and the first vertex repeated at the end.
  const Ring2d raw = {{0, 0}, {1, 0},   {1, 0}, {2, 0}, {2, 1},
                      {2, 3}, {2, 1.5}, {2, 2}, {0, 2}, {0, 0}};
  const Polygon2d clean = PreparePolygon({raw, {}}, "w");
  EXPECT_EQ(clean.outer, Ring2d({{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
}

TEST(PreparePolygonTest, AcceptsLargeAndSmallScales) {
  for (const double scale : {1e6, 1e-6}) {
    const Polygon2d raw{
        {{1 * scale, 1 * scale},
         {5 * scale, 1 * scale},
         {5 * scale, 5 * scale},
         {3 * scale, 2 * scale},
         {1 * scale, 5 * scale}},
        {{{2 * scale, 1.5 * scale}, {2.5 * scale, 1.5 * scale}, {2.5 * scale, 2 * scale}}}};
    const Polygon2d clean = PreparePolygon(raw, "w");
    EXPECT_EQ(clean.outer.size(), 5u) << scale;
    EXPECT_EQ(clean.holes.size(), 1u) << scale;
    EXPECT_NEAR(Area(clean), (10.0 - 0.125) * scale * scale, 1e-9 * scale * scale) << scale;
  }
  // Far from the origin as well: the same square offset by 1e6.
  EXPECT_NO_THROW(PreparePolygon({SquareRing(1e6, 1e6, 1e-3), {}}, "w"));
}

TEST(PreparePolygonTest, RejectsNonFiniteCoordinate) {
  Polygon2d raw{SquareRing(0, 0, 1), {SquareRing(0.2, 0.2, 0.1)}};
  raw.holes[0][2].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(PreparePolygonErrorOf(raw),
              AllOf(HasSubstr("test.poly: polygon 0: hole 0: vertex 2"), HasSubstr("not finite")));
  raw.holes[0][2].y() = 0.25;
  raw.outer[1].x() = std::numeric_limits<double>::infinity();
  EXPECT_THAT(PreparePolygonErrorOf(raw),
              AllOf(HasSubstr("outer ring: vertex 1"), HasSubstr("not finite")));
}

// Found by fuzz/fuzz_decompose2d (fuzz/corpus/decompose2d/regression-overflowing-coordinate.wkt):
// a vertex at x = 5e185 made the products in every area and centroid overflow (a centroid of
// inf and NaN). Beyond 1e100 a coordinate is rejected with the vertex named; up to it, the
// polygon is prepared.
TEST(PreparePolygonTest, RejectsCoordinatesWhoseProductsOverflow) {
  Polygon2d raw{{{0, 0}, {1, 4}, {1, 2}, {5e185, 199}, {0, 4}}, {}};
  EXPECT_THAT(PreparePolygonErrorOf(raw),
              AllOf(HasSubstr("test.poly: polygon 0: outer ring: vertex 3"),
                    HasSubstr("is too far from the origin (|coordinate| > 1e100")));
  raw.outer[3] = {0.5, -1e101};
  EXPECT_THAT(PreparePolygonErrorOf(raw), HasSubstr("outer ring: vertex 3"));
  raw.outer[3] = {1e100, 199};
  EXPECT_NO_THROW(PreparePolygon(raw, "w"));  // Decompose2dTest decomposes it.
}

TEST(PreparePolygonTest, RejectsTooFewVertices) {
  EXPECT_THAT(PreparePolygonErrorOf({{{0, 0}, {1, 1}}, {}}),
              AllOf(HasSubstr("test.poly: polygon 0: outer ring"), HasSubstr("fewer than 3")));
  // Collinear points clean down to a segment.
  EXPECT_THAT(PreparePolygonErrorOf({{{0, 0}, {1, 1}, {2, 2}, {3, 3}}, {}}),
              AllOf(HasSubstr("outer ring"), HasSubstr("fewer than 3")));
  EXPECT_THAT(PreparePolygonErrorOf({SquareRing(0, 0, 4), {{{1, 1}, {1, 1}, {2, 2}}}}),
              AllOf(HasSubstr("hole 0"), HasSubstr("fewer than 3")));
}

TEST(PreparePolygonTest, RejectsSelfIntersectingOuterRingNamingEdgesAndPoint) {
  // A bow tie: edges (0,1) and (2,3) cross at (1.5, 1.5).
  EXPECT_THAT(PreparePolygonErrorOf({{{0, 0}, {2, 2}, {3, 0}, {0, 3}}, {}}),
              AllOf(HasSubstr("test.poly: polygon 0: outer ring is not simple"),
                    HasSubstr("edges (0,1) and (2,3) intersect at (1.5, 1.5)")));
}

// Found by fuzz/fuzz_decompose2d (fuzz/corpus/decompose2d/regression-bowtie-vertical-edge.wkt):
// the crossing (1, 0.8) of a vertical edge and a sloped one is not a double, and the sweep on
// Epick's rounded constructions missed it, so a bow-tie reached Decompose2d(). Every rotation
// and both orientations of the ring are rejected.
TEST(PreparePolygonTest, RejectsCrossingAtAPointThatIsNotADouble) {
  Ring2d ring = {{0, 0}, {1, 0}, {1, 2}, {5, 4}};
  for (int reversed = 0; reversed < 2; ++reversed) {
    for (int rotation = 0; rotation < 4; ++rotation) {
      EXPECT_THAT(PreparePolygonErrorOf({ring, {}}),
                  AllOf(HasSubstr("test.poly: polygon 0: outer ring is not "
                                  "simple: edges"),
                        HasSubstr("intersect at (1, 0.8)")))
          << "rotation " << rotation << ", reversed " << reversed;
      std::rotate(ring.begin(), ring.begin() + 1, ring.end());
    }
    ring = Reversed(ring);
  }
  // The WKT the fuzzer found: "5 4\v 0 4" is x y z m, then (0 0) twice closes the ring.
  EXPECT_EQ(PreparePolygonErrorOf({{{0, 0}, {1, 0}, {1, 2}, {5, 4}, {0, 0}, {0, 0}}, {}}),
            "test.poly: polygon 0: outer ring is not simple: edges (1,2) and (3,0) intersect at "
            "(1, 0.8)");
}

TEST(PreparePolygonTest, VertexIndicesAreThoseOfTheInput) {
  // The same crossing with a duplicate vertex: indices still refer to the input.
  EXPECT_THAT(PreparePolygonErrorOf({{{0, 0}, {0, 0}, {2, 2}, {3, 0}, {0, 3}}, {}}),
              HasSubstr("edges (0,2) and (3,4) intersect at (1.5, 1.5)"));
}

TEST(PreparePolygonTest, RejectsSelfIntersectingHole) {
  EXPECT_THAT(PreparePolygonErrorOf({SquareRing(0, 0, 10), {{{1, 1}, {3, 3}, {4, 1}, {1, 4}}}}),
              AllOf(HasSubstr("hole 0 is not simple"), HasSubstr("intersect at (2.5, 2.5)")));
}

TEST(PreparePolygonTest, RejectsHoleCrossingOuterRing) {
  EXPECT_THAT(PreparePolygonErrorOf({SquareRing(0, 0, 4), {SquareRing(3, 1, 2)}}),
              AllOf(HasSubstr("hole 0 touches or crosses the outer ring"),
                    HasSubstr("strictly inside"), HasSubstr("intersect at (4, 3)")));
}

TEST(PreparePolygonTest, RejectsHoleOutsideOuterRing) {
  EXPECT_THAT(
      PreparePolygonErrorOf({SquareRing(0, 0, 4), {SquareRing(1, 1, 1), SquareRing(10, 10, 1)}}),
      AllOf(HasSubstr("hole 1 is not inside the outer ring"), HasSubstr("is outside")));
  // A hole around the outer ring is not inside it either.
  EXPECT_THAT(PreparePolygonErrorOf({SquareRing(0, 0, 4), {SquareRing(-1, -1, 6)}}),
              HasSubstr("hole 0 is not inside the outer ring"));
}

TEST(PreparePolygonTest, RejectsOverlappingHoles) {
  EXPECT_THAT(
      PreparePolygonErrorOf({SquareRing(0, 0, 10), {SquareRing(1, 1, 3), SquareRing(2, 2, 3)}}),
      AllOf(HasSubstr("hole 0 and hole 1 touch or overlap"), HasSubstr("holes must be disjoint")));
}

// Rings touching at points (a hole on the outer ring, two holes at a vertex, a self-tangent
// ring) are valid: PreparePolygons() splits them (tests/acd/prepare_polygons_test.cpp), and
// PreparePolygon(), which must return one polygon, says so.
TEST(PreparePolygonTest, RejectsOverlappingHoleEdgesAndNamesTouchingAsSeveralPolygons) {
  // Sharing the edge x = 4 partly.
  EXPECT_THAT(
      PreparePolygonErrorOf({SquareRing(0, 0, 10), {SquareRing(1, 1, 3), SquareRing(4, 2, 3)}}),
      HasSubstr("hole 0 and hole 1 touch or overlap"));
  EXPECT_THAT(PreparePolygonErrorOf({SquareRing(0, 0, 4), {{{2, 0}, {3, 1}, {1, 1}}}}),
              HasSubstr("test.poly: polygon 0: rings touch at points, which makes the polygon 2 "
                        "polygons where one is required"));
}

TEST(PreparePolygonTest, RejectsNestedHoles) {
  EXPECT_THAT(
      PreparePolygonErrorOf({SquareRing(0, 0, 10), {SquareRing(1, 1, 6), SquareRing(2, 2, 1)}}),
      AllOf(HasSubstr("hole 1 lies inside hole 0"), HasSubstr("nested")));
}

TEST(PreparePolygonTest, NamesTheFirstNestedHoleAmongMany) {
  // Holes 0 - 29 in a row; hole 31 lies in hole 5, hole 32 in hole 30, which lies left of hole 5:
  // the first nested hole in hole order is named, whichever container comes first in space.
  Polygon2d raw{SquareRing(0, 0, 100), {}};
  for (int k = 0; k < 30; ++k) raw.holes.push_back(SquareRing(1 + 3 * k, 1, 2));
  raw.holes.push_back(SquareRing(10, 50, 10));
  raw.holes.push_back(SquareRing(16.5, 1.5, 1));
  raw.holes.push_back(SquareRing(12, 52, 2));
  EXPECT_THAT(PreparePolygonErrorOf(raw), HasSubstr("hole 31 lies inside hole 5 (holes must not"));
}

TEST(PreparePolygonTest, AcceptsManyDisjointHoles) {
  Polygon2d raw{SquareRing(0, 0, 100), {}};
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 10; ++j) raw.holes.push_back(SquareRing(1 + 10 * i, 1 + 10 * j, 5));
  }
  const Polygon2d clean = PreparePolygon(raw, "w");
  EXPECT_EQ(clean.holes.size(), 100u);
  EXPECT_DOUBLE_EQ(Area(clean), 10000.0 - 100 * 25.0);
}

}  // namespace
}  // namespace acdplan::acd
