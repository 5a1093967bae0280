#include "acd/repair_polygon.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
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

// The even-odd rule counts every ring edge: a hole listed twice would cancel itself and fill
// its area in. Each hole is taken once, whichever vertex it starts at and whichever way it runs.
TEST(RepairPolygonTest, AHoleListedTwiceIsTakenOnce) {
  Ring2d reversed = SquareRing(1, 1, 1);
  std::reverse(reversed.begin(), reversed.end());
  std::rotate(reversed.begin(), reversed.begin() + 1, reversed.end());
  const RepairedPolygon r = RepairPolygon(
      {SquareRing(0, 0, 4), {SquareRing(1, 1, 1), SquareRing(2.5, 2.5, 1), reversed}}, "w");
  EXPECT_THAT(r.changes, ElementsAre("w: repaired: hole 2 repeats hole 0: dropped"));
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(r.polygons[0].holes.size(), 2u);
  EXPECT_DOUBLE_EQ(Area(r.polygons[0]), 14.0);
  // Listed three times, and with a hole that crosses another: the even-odd rule then runs on
  // the holes taken once.
  const RepairedPolygon crossing = RepairPolygon(
      {SquareRing(0, 0, 4),
       {SquareRing(1, 1, 1), SquareRing(1, 1, 1), SquareRing(1.5, 1.5, 1), SquareRing(1, 1, 1)}},
      "w");
  ASSERT_EQ(crossing.changes.size(), 3u);
  EXPECT_EQ(crossing.changes[0], "w: repaired: hole 1 repeats hole 0: dropped");
  EXPECT_EQ(crossing.changes[1], "w: repaired: hole 3 repeats hole 0: dropped");
  EXPECT_THAT(crossing.changes[2], HasSubstr("area 14.5"));  // 16 - 1 - 1 + 2 x 0.25.
  EXPECT_NEAR(TotalArea(crossing.polygons), 14.5, 1e-12);
  ExpectDecomposes(crossing.polygons);
}

// A ring that runs around its vertices twice would cancel itself out under the even-odd rule;
// it is taken once (three times: the same).
TEST(RepairPolygonTest, ARingThatRunsAroundTwiceIsTakenOnce) {
  Ring2d twice = SquareRing(0, 0, 4);
  const Ring2d once = twice;
  twice.insert(twice.end(), once.begin(), once.end());
  twice.insert(twice.begin() + 2, once[1]);  // A repeated vertex does not hide the period.
  const Ring2d hole = SquareRing(1, 1, 1);
  Ring2d hole_thrice;
  for (int k = 0; k < 3; ++k) hole_thrice.insert(hole_thrice.end(), hole.begin(), hole.end());
  const RepairedPolygon r = RepairPolygon({twice, {hole_thrice}}, "w");
  EXPECT_THAT(r.changes,
              ElementsAre("w: repaired: outer ring runs around its first 4 distinct vertices 2 "
                          "times: taken once",
                          "w: repaired: hole 0 runs around its first 4 distinct vertices 3 "
                          "times: taken once"));
  ASSERT_EQ(r.polygons.size(), 1u);
  EXPECT_EQ(r.polygons[0].holes.size(), 1u);
  EXPECT_DOUBLE_EQ(Area(r.polygons[0]), 15.0);
}

// Where ring edges overlap, the even-odd rule counts each: a spike out and back encloses
// nothing, and a hole that shares part of an edge with the outer ring is cut out. (GEOS 3.11's
// make-valid, which merges overlapping edges first, keeps both areas: 16 and 16 here.) These
// held before the repeated rings were taken once; they guard that the step changed only those.
TEST(RepairPolygonTest, OverlappingEdgesCountOncePerRing) {
  const RepairedPolygon spike =
      RepairPolygon({{{0, 0}, {4, 0}, {4, 2}, {6, 2}, {2, 2}, {4, 2}, {4, 4}, {0, 4}}, {}}, "w");
  EXPECT_NEAR(TotalArea(spike.polygons), 16.0, 1e-12);
  ExpectDecomposes(spike.polygons);
  const RepairedPolygon shared = RepairPolygon({SquareRing(0, 0, 4), {SquareRing(0, 1, 2)}}, "w");
  EXPECT_THAT(shared.changes, ElementsAre(HasSubstr("area 12")));
  EXPECT_NEAR(TotalArea(shared.polygons), 12.0, 1e-12);
  ExpectDecomposes(shared.polygons);
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
