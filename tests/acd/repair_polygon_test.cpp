#include "acd/repair_polygon.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "acd/check_decomposition.h"
#include "acd/decompose2d.h"
#include "acd/prepare_polygon.h"
#include "base/input_error.h"
#include "tests/polygon_fixtures.h"

namespace acdplan::acd {
namespace {

using acdplan::test::SquareRing;
using acdplan::test::TotalArea;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

void ExpectDecomposes(const std::vector<Polygon2d>& polygons) {
  const Decomposition2d d = Decompose2d(polygons, {});
  const DecompositionCheck check = CheckDecomposition(polygons, d);
  EXPECT_TRUE(check.ok()) << (check.ok() ? "" : check.problems[0]);
}

TEST(RepairPolygonTest, ValidPolygonIsUnchanged) {
  const RepairedPolygon r = RepairPolygon({SquareRing(0, 0, 4), {SquareRing(1, 1, 1)}}, "w");
  EXPECT_TRUE(r.changes.empty());
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_DOUBLE_EQ(Area(r.polygons[0]), 15.0);
}

TEST(RepairPolygonTest, BowTieBecomesTwoTriangles) {
  const RepairedPolygon r =
      RepairPolygon({{{0, 0}, {2, 2}, {3, 0}, {0, 3}}, {}}, "t.wkt: polygon 0");
  ASSERT_EQ(r.polygons.size(), 2u);
  EXPECT_EQ(r.polygons[0].outer.size(), 3u);
  EXPECT_EQ(r.polygons[1].outer.size(), 3u);
  // Triangles (0,0)-(1.5,1.5)-(0,3) and (1.5,1.5)-(2,2)-(3,0)... areas 2.25 and 0.75.
  EXPECT_NEAR(TotalArea(r.polygons), 2.25 + 0.75, 1e-12);
  EXPECT_THAT(r.changes,
              ElementsAre("t.wkt: polygon 0: repaired: outer ring is not simple: edges (0,1) and "
                          "(2,3) intersect at (1.5, 1.5): rebuilt by the even-odd rule into 2 "
                          "polygon(s) with 0 hole(s), area 3"));
  ExpectDecomposes(r.polygons);
}

TEST(RepairPolygonTest, TwoVertexHoleIsDropped) {
  const RepairedPolygon r = RepairPolygon(
      {SquareRing(0, 0, 4), {{{1, 1}, {2, 2}}, SquareRing(1, 2, 1)}}, "t.wkt: polygon 3");
  EXPECT_THAT(r.changes,
              ElementsAre("t.wkt: polygon 3: repaired: hole 0 has 2 distinct vertices: dropped"));
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(r.polygons[0].holes.size(), 1u);
  EXPECT_DOUBLE_EQ(Area(r.polygons[0]), 15.0);
}

// After a hole is dropped, the rule the rest breaks names its rings as the input numbers them.
TEST(RepairPolygonTest, ChangesNameHolesByTheirInputIndex) {
  const RepairedPolygon r = RepairPolygon(
      {SquareRing(0, 0, 4), {{{1, 1}, {2, 2}}, SquareRing(0.5, 0.5, 1), SquareRing(3, 1, 2)}},
      "t.wkt: polygon 1");
  ASSERT_EQ(r.changes.size(), 2u);
  EXPECT_EQ(r.changes[0], "t.wkt: polygon 1: repaired: hole 0 has 2 distinct vertices: dropped");
  EXPECT_THAT(r.changes[1],
              HasSubstr("t.wkt: polygon 1: repaired: hole 2 touches or crosses the outer ring"));
  EXPECT_THAT(r.changes[1], HasSubstr("into 2 polygon(s) with 1 hole(s)"));
}

TEST(RepairPolygonTest, HoleCrossingOuterRingGivesTheEvenOddResult) {
  // Inside both: excluded; inside the hole only: included (the symmetric difference).
  const RepairedPolygon r = RepairPolygon({SquareRing(0, 0, 4), {SquareRing(3, 1, 2)}}, "w");
  ASSERT_EQ(r.changes.size(), 1u);
  EXPECT_THAT(r.changes[0], HasSubstr("w: repaired: hole 0 touches or crosses the outer ring"));
  EXPECT_THAT(r.changes[0], HasSubstr("rebuilt by the even-odd rule into 2 polygon(s) with 0 "
                                      "hole(s), area 16"));
  ASSERT_EQ(r.polygons.size(), 2u);
  EXPECT_DOUBLE_EQ(Area(r.polygons[0]), 14.0);  // The square with the notch [3,4]x[1,3].
  EXPECT_DOUBLE_EQ(Area(r.polygons[1]), 2.0);   // [4,5]x[1,3].
  ExpectDecomposes(r.polygons);
}

TEST(RepairPolygonTest, DegenerateOuterRingLeavesNothing) {
  const RepairedPolygon r = RepairPolygon({{{0, 0}, {1, 1}, {2, 2}}, {}}, "w");
  EXPECT_TRUE(r.polygons.empty());
  EXPECT_THAT(r.changes, ElementsAre("w: repaired: outer ring has 3 distinct vertices, all "
                                     "collinear: dropped",
                                     "w: repaired: nothing remains without the outer ring"));
}

TEST(RepairPolygonTest, NonFiniteCoordinateIsStillAnError) {
  Polygon2d raw{SquareRing(0, 0, 1), {}};
  raw.outer[1].x() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(RepairPolygon(raw, "w"), InputError);
}

// fuzz/corpus/decompose2d/regression-repair-far-coordinate.wkt: a ring crossing itself with a
// vertex at 5e184 went into the exact arrangement, whose interval filters overflow there
// (undefined behaviour inside CGAL under UBSan; "repair failed: rounding ..." in Release).
// PreparePolygons()' range rule, which no repair can mend, is the answer, as for a non-finite
// coordinate.
TEST(RepairPolygonTest, CoordinateBeyondTheRangeIsStillAnError) {
  const Polygon2d raw{{{0, 0}, {1, 4}, {1, 2}, {5e184, 199}, {0, 4}}, {}};
  try {
    RepairPolygon(raw, "w");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("w: outer ring: vertex 3"));
    EXPECT_THAT(error.what(), HasSubstr("is too far from the origin"));
  }
  // A bow tie reaching out to the limit is repaired into its two triangles; beyond it, refused.
  auto bow_tie = [](double x) { return Polygon2d{{{0, 0}, {x, 1}, {x, 0}, {0, 1}}, {}}; };
  const RepairedPolygon r = RepairPolygon(bow_tie(kMaxCoordinate), "w");
  EXPECT_EQ(r.changes.size(), 1u);
  EXPECT_EQ(r.polygons.size(), 2u);
  EXPECT_THROW(RepairPolygon(bow_tie(2 * kMaxCoordinate), "w"), InputError);
}

}  // namespace
}  // namespace acdplan::acd
