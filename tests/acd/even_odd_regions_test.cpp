#include "acd/internal/even_odd_regions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "base/random.h"

namespace acdplan::acd::internal {
namespace {

Ring2d Square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

// The triangles of a fan around `centre` over the counter-clockwise ring `ring`.
std::vector<Ring2d> Fan(const Ring2d& ring, const Point2d& centre) {
  std::vector<Ring2d> triangles;
  for (size_t i = 0; i < ring.size(); ++i) {
    triangles.push_back({centre, ring[i], ring[(i + 1) % ring.size()]});
  }
  return triangles;
}

// The frame between the squares [0, 3]^2 and [1, 2]^2 as 8 counter-clockwise triangles.
std::vector<Ring2d> Frame() {
  const Ring2d outer = Square(0, 0, 3), inner = Square(1, 1, 1);
  std::vector<Ring2d> triangles;
  for (size_t i = 0; i < 4; ++i) {
    const size_t j = (i + 1) % 4;
    triangles.push_back({outer[i], outer[j], inner[j]});
    triangles.push_back({outer[i], inner[j], inner[i]});
  }
  return triangles;
}

TEST(EvenOddRegionsTest, TwoTriangulationsOfASquareShareTheSquare) {
  const Ring2d square = Square(0, 0, 2);
  // One side: the two triangles of one diagonal. The other: a fan around the centre whose
  // vertices on the edges' midpoints are T-junctions against the first side.
  const std::vector<Ring2d> diagonal = {{square[0], square[1], square[2]},
                                        {square[0], square[2], square[3]}};
  const Ring2d octagon = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  const std::vector<Polygon2d> regions = EvenOddRegions({diagonal, Fan(octagon, {1, 1})});
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_TRUE(regions[0].holes.empty());
  // The midpoints lie between collinear edges: dropped; the ring starts at its lowest vertex.
  EXPECT_EQ(regions[0].outer, square);
}

TEST(EvenOddRegionsTest, AFrameAgainstAFullSquareIsASquareWithAClockwiseHole) {
  const Ring2d square = Square(0, 0, 3);
  const std::vector<Polygon2d> regions = EvenOddRegions(
      {Frame(), {{square[0], square[1], square[2]}, {square[0], square[2], square[3]}}});
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].outer, square);
  ASSERT_EQ(regions[0].holes.size(), 1u);
  EXPECT_LT(SignedArea(regions[0].holes[0]), 0.0);
  EXPECT_DOUBLE_EQ(Area(regions[0]), 8.0);
  EXPECT_EQ(regions[0].holes[0].front(), Point2d(1, 1));  // Its lowest vertex.
}

TEST(EvenOddRegionsTest, TheIntersectionOfTheLayersRegions) {
  // [0, 2]^2 and [1, 3]^2 share [1, 2]^2; a third layer [1.5, 4]^2 leaves [1.5, 2]^2.
  std::vector<Polygon2d> regions = EvenOddRegions({{Square(0, 0, 2)}, {Square(1, 1, 2)}});
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].outer, Square(1, 1, 1));
  regions = EvenOddRegions({{Square(0, 0, 2)}, {Square(1, 1, 2)}, {Square(1.5, 1.5, 2.5)}});
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].outer, Square(1.5, 1.5, 0.5));
  // Disjoint layers share nothing.
  EXPECT_TRUE(EvenOddRegions({{Square(0, 0, 1)}, {Square(2, 0, 1)}}).empty());
}

TEST(EvenOddRegionsTest, OneLayerIsTheEvenOddRule) {
  // A bow tie: its two triangles, ordered by their lowest vertex.
  std::vector<Polygon2d> regions = EvenOddRegions({{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}}});
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[0].outer, Ring2d({{0, 0}, {1, 1}, {0, 2}}));
  EXPECT_EQ(regions[1].outer, Ring2d({{1, 1}, {2, 0}, {2, 2}}));
  // A ring listed twice (once each way round) encloses nothing.
  EXPECT_TRUE(EvenOddRegions({{Square(0, 0, 1), Reversed(Square(0, 0, 1))}}).empty());
  // Two squares sharing an edge: one rectangle, the shared edge gone.
  regions = EvenOddRegions({{Square(0, 0, 1), Square(1, 0, 1)}});
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].outer, Ring2d({{0, 0}, {2, 0}, {2, 1}, {0, 1}}));
  // Overlapping squares: the symmetric difference, two L-shapes touching at two points.
  regions = EvenOddRegions({{Square(0, 0, 2), Square(1, 1, 2)}});
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_DOUBLE_EQ(Area(regions[0]) + Area(regions[1]), 6.0);
  for (const Polygon2d& region : regions) EXPECT_EQ(region.outer.size(), 6u);
}

TEST(EvenOddRegionsTest, PointContactsSeparateLoopsAndParts) {
  // Two squares meeting at a corner: two polygons.
  std::vector<Polygon2d> regions = EvenOddRegions({{Square(0, 0, 1), Square(1, 1, 1)}});
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_EQ(regions[0].outer, Square(0, 0, 1));
  EXPECT_EQ(regions[1].outer, Square(1, 1, 1));
  // A hole touching the outer ring at its lowest vertex (OGC-valid): one polygon, one hole.
  const Ring2d hole = {{0, 0}, {1, 2}, {2, 1}};
  regions = EvenOddRegions({{Square(0, 0, 4), hole}});
  ASSERT_EQ(regions.size(), 1u);
  EXPECT_EQ(regions[0].outer, Square(0, 0, 4));
  ASSERT_EQ(regions[0].holes.size(), 1u);
  EXPECT_EQ(regions[0].holes[0], hole);  // Clockwise, from its lowest vertex.
  EXPECT_DOUBLE_EQ(Area(regions[0]), 16.0 - 1.5);
}

TEST(EvenOddRegionsTest, TheResultDependsOnTheGeometryAlone) {
  std::vector<Ring2d> frame = Frame();
  const std::vector<Ring2d> square = {Square(0, 0, 3)};
  const std::vector<Polygon2d> expected = EvenOddRegions({frame, square});
  RandomEngine rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    // Triangles in another order, each started at another corner (still counter-clockwise).
    for (size_t i = frame.size(); i > 1; --i) {
      std::swap(frame[i - 1], frame[UniformIndex(rng, i)]);
    }
    for (Ring2d& triangle : frame) {
      std::rotate(triangle.begin(),
                  triangle.begin() + static_cast<std::ptrdiff_t>(UniformIndex(rng, 3)),
                  triangle.end());
    }
    const std::vector<Polygon2d> regions = EvenOddRegions({frame, square});
    ASSERT_EQ(regions.size(), expected.size());
    for (size_t k = 0; k < regions.size(); ++k) {
      EXPECT_EQ(regions[k].outer, expected[k].outer);
      EXPECT_EQ(regions[k].holes, expected[k].holes);
    }
  }
}

TEST(EvenOddRegionsTest, DegenerateInput) {
  EXPECT_TRUE(EvenOddRegions({}).empty());
  EXPECT_TRUE(EvenOddRegions({{}}).empty());
  // Zero-length edges are skipped; a ring of one repeated point encloses nothing.
  EXPECT_TRUE(EvenOddRegions({{{{1, 1}, {1, 1}, {1, 1}}}}).empty());
  EXPECT_THROW(EvenOddRegions(std::vector<std::vector<Ring2d>>(33)), std::invalid_argument);
}

}  // namespace
}  // namespace acdplan::acd::internal
