// PreparePolygons(): the OGC-valid inputs whose rings touch at points are accepted, split into
// polygons with simple, disjoint rings, and decompose; what stays invalid keeps its message.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "acd/check_decomposition.h"
#include "acd/decompose2d.h"
#include "acd/prepare_polygon.h"
#include "base/input_error.h"
#include "base/random.h"
#include "base/stopwatch.h"
#include "tests/input_error_of.h"
#include "tests/polygon_fixtures.h"

namespace acdplan::acd {
namespace {

using acdplan::test::SquareRing;
using acdplan::test::TotalArea;
using ::testing::AllOf;
using ::testing::HasSubstr;

std::string PreparePolygonsErrorOf(const Polygon2d& raw) {
  return acdplan::test::InputErrorOf([&] { PreparePolygons(raw, "test.poly: polygon 0"); });
}

// How many groups the components of `d` form, joined by openings.
int OpeningGroups(const Decomposition2d& d) {
  const std::vector<std::vector<int>> graph = ComponentGraph(d);
  std::vector<char> seen(graph.size(), 0);
  int groups = 0;
  for (size_t start = 0; start < graph.size(); ++start) {
    if (seen[start]) continue;
    ++groups;
    std::vector<int> stack{static_cast<int>(start)};
    seen[start] = 1;
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      for (const int next : graph[static_cast<size_t>(c)]) {
        if (!seen[static_cast<size_t>(next)]) {
          seen[static_cast<size_t>(next)] = 1;
          stack.push_back(next);
        }
      }
    }
  }
  return groups;
}

// Prepares `raw`, checks that every piece is strictly valid (PreparePolygon() keeps it as it
// is), that the pieces keep the area, and that they decompose and pass CheckDecomposition();
// with `connected`, that the openings join all components (across the pieces' cuts too).
std::vector<Polygon2d> PrepareAndDecompose(const Polygon2d& raw, double expected_area,
                                           double tau_rel = 0.0, bool connected = true) {
  const std::vector<Polygon2d> pieces = PreparePolygons(raw, "w");
  EXPECT_NEAR(TotalArea(pieces), expected_area, 1e-9 * expected_area);
  for (const Polygon2d& piece : pieces) {
    const Polygon2d again = PreparePolygon(piece, "piece");
    EXPECT_EQ(again.outer.size(), piece.outer.size());
    EXPECT_EQ(again.holes.size(), piece.holes.size());
  }
  Decompose2dOptions options;
  options.tau = tau_rel * ReferenceRadius(raw);
  const Decomposition2d decomposition = Decompose2d(pieces, options);
  const DecompositionCheck check = CheckDecomposition(pieces, decomposition);
  EXPECT_TRUE(check.ok()) << (check.ok() ? "" : check.problems[0]);
  if (connected) {
    EXPECT_EQ(OpeningGroups(decomposition), 1);
  }
  return pieces;
}

TEST(PreparePolygonsTest, StrictlyValidPolygonStaysOne) {
  const Polygon2d raw{SquareRing(0, 0, 10), {SquareRing(1, 1, 2), SquareRing(5, 5, 2)}};
  const std::vector<Polygon2d> pieces = PreparePolygons(raw, "w");
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].holes.size(), 2u);
}

TEST(PreparePolygonsTest, AcceptsHoleTouchingOuterRingAtAPoint) {
  // The hole's vertex (2, 0) lies inside the outer ring's bottom edge.
  PrepareAndDecompose({SquareRing(0, 0, 4), {{{2, 0}, {3, 1}, {1, 1}}}}, 16.0 - 1.0);
  // A hole sharing a vertex with the outer ring.
  PrepareAndDecompose({SquareRing(0, 0, 4), {{{0, 0}, {2, 1}, {1, 2}}}}, 16.0 - 1.5);
  // The old single-polygon entry point says why it cannot return one polygon.
  try {
    PreparePolygon({SquareRing(0, 0, 4), {{{2, 0}, {3, 1}, {1, 1}}}}, "w");
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("w: rings touch at points"));
  }
}

TEST(PreparePolygonsTest, AcceptsTwoHolesTouchingAtAPoint) {
  const std::vector<Polygon2d> pieces = PrepareAndDecompose(
      {SquareRing(0, 0, 10), {SquareRing(1, 1, 3), SquareRing(4, 4, 3)}}, 100.0 - 18.0);
  EXPECT_GE(pieces.size(), 1u);
}

TEST(PreparePolygonsTest, AcceptsSelfTangentOuterRing) {
  // An inverted ring: the outer ring touches itself at (2, 0), enclosing the pocket
  // (2,0)-(3,2)-(1,2) that is outside the polygon.
  const Ring2d inverted = {{0, 0}, {2, 0}, {1, 2}, {3, 2}, {2, 0}, {4, 0}, {4, 4}, {0, 4}};
  PrepareAndDecompose({inverted, {}}, 16.0 - 2.0);
  // The same pocket written the other way round (clockwise outer ring).
  PrepareAndDecompose({Reversed(inverted), {}}, 16.0 - 2.0);
  // Two lobes meeting at a point: two polygons.
  const Ring2d figure_eight = {{2, 2}, {4, 0}, {4, 4}, {2, 2}, {0, 4}, {0, 0}};
  EXPECT_EQ(PrepareAndDecompose({figure_eight, {}}, 8.0, 0.0, false).size(), 2u);
  // A vertex touching a non-adjacent edge of its own ring: two triangles.
  const Ring2d touching = {{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}};
  EXPECT_EQ(PrepareAndDecompose({touching, {}}, 8.0, 0.0, false).size(), 2u);
}

// Two lobes meeting at a point, one of subnormal size: the whole ring's area is that of the
// large lobe, but the small lobe's, once split off, is below what a double holds (its exact
// area is 1.5e-620). It is refused by name; it had passed and failed the decomposition's check
// (fuzz_decompose2d, on a shapefile of subnormal coordinates, through --repair).
TEST(PreparePolygonsTest, RefusesAPartWhoseAreaUnderflows) {
  const Ring2d lobes = {
      {0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}, {-2e-310, -1e-310}, {-1e-310, -2e-310}};
  EXPECT_THAT(PreparePolygonsErrorOf({lobes, {}}),
              HasSubstr("test.poly: polygon 0: the part at (0, 0), split off where its rings "
                        "touch, has zero area in double precision"));
}

TEST(PreparePolygonsTest, AcceptsHoleTouchingAtTwoPointsThatSplitNothing) {
  // Hole 0 touches the outer ring at (0, 5) and hole 1 at (3, 5); hole 1 touches nothing else.
  const Polygon2d raw{SquareRing(0, 0, 10),
                      {{{0, 5}, {3, 5}, {1, 6}}, {{3, 5}, {5, 4}, {5, 6}}, SquareRing(7, 7, 1)}};
  PrepareAndDecompose(raw, 100.0 - 1.5 - 2.0 - 1.0, 0.01);
}

// A pinch is taken apart with a few cuts, wherever it is; the holes away from them stay holes.
// (Pieces grown from single triangles cannot close around a hole: before they were joined
// again, this polygon with 49 holes and one touching the outer ring became 35 without holes.)
TEST(PreparePolygonsTest, APinchCostsAFewPiecesNotOnePerHole) {
  Polygon2d grid{SquareRing(0, 0, 70), {}};
  for (int i = 0; i < 7; ++i) {
    for (int j = 0; j < 7; ++j) grid.holes.push_back(SquareRing(10 * i + 4, 10 * j + 4, 2));
  }
  const double area = 70.0 * 70.0 - 49 * 4.0;
  // A triangle hole touching the outer ring's bottom edge at (35, 0).
  Polygon2d touching_outer = grid;
  touching_outer.holes.push_back({{35, 0}, {37, 2}, {33, 2}});
  // Two triangle holes touching each other at (35, 1.5), apart from the outer ring.
  Polygon2d touching_holes = grid;
  touching_holes.holes.push_back({{35, 1.5}, {37, 0.5}, {37, 2.5}});
  touching_holes.holes.push_back({{35, 1.5}, {33, 2.5}, {33, 0.5}});
  for (const auto& [raw, hole_area] :
       {std::make_pair(touching_outer, 4.0), std::make_pair(touching_holes, 4.0)}) {
    const std::vector<Polygon2d> pieces = PrepareAndDecompose(raw, area - hole_area, 0.02);
    EXPECT_LE(pieces.size(), 3u);
    // The cut runs along triangulation edges, so it opens the few holes it passes (two here).
    size_t holes = 0;
    for (const Polygon2d& piece : pieces) holes += piece.holes.size();
    EXPECT_GE(holes, 45u);
  }
}

TEST(PreparePolygonsTest, RejectsWhatStaysInvalid) {
  // Crossing rings keep the strict messages.
  EXPECT_THAT(PreparePolygonsErrorOf({{{0, 0}, {2, 2}, {3, 0}, {0, 3}}, {}}),
              AllOf(HasSubstr("test.poly: polygon 0: outer ring is not simple"),
                    HasSubstr("edges (0,1) and (2,3) intersect at (1.5, 1.5)")));
  EXPECT_THAT(PreparePolygonsErrorOf({SquareRing(0, 0, 4), {SquareRing(3, 1, 2)}}),
              AllOf(HasSubstr("hole 0 touches or crosses the outer ring"),
                    HasSubstr("intersect at (4, 3)")));
  // Overlapping collinear edges (holes sharing part of the edge x = 4).
  EXPECT_THAT(
      PreparePolygonsErrorOf({SquareRing(0, 0, 10), {SquareRing(1, 1, 3), SquareRing(4, 2, 3)}}),
      AllOf(HasSubstr("hole 0 and hole 1 touch or overlap"), HasSubstr("overlap from")));
  // A hole outside, touching the outer ring at a vertex.
  EXPECT_THAT(PreparePolygonsErrorOf({SquareRing(0, 0, 4), {SquareRing(4, 4, 1)}}),
              HasSubstr("test.poly: polygon 0: hole 0 is not inside the outer ring: its vertex 3 "
                        "(4, 5) is outside"));
  // A hole inside another, touching it.
  EXPECT_THAT(PreparePolygonsErrorOf(
                  {SquareRing(0, 0, 10), {SquareRing(1, 1, 6), {{1, 1}, {2, 3}, {3, 2}}}}),
              HasSubstr("test.poly: polygon 0: hole 1 lies inside hole 0 (holes must not be "
                        "nested)"));
  // A hole touching the outer ring at two points cuts the interior in two.
  EXPECT_THAT(PreparePolygonsErrorOf({SquareRing(0, 0, 4), {{{0, 2}, {2, 1}, {4, 2}, {2, 3}}}}),
              HasSubstr("test.poly: polygon 0: hole 0 disconnects the interior"));
  // Two lobes that cross at their shared vertex (a bow tie through a vertex).
  EXPECT_THAT(PreparePolygonsErrorOf({{{2, 2}, {4, 0}, {4, 4}, {2, 2}, {0, 0}, {0, 5}}, {}}),
              HasSubstr("test.poly: polygon 0: outer ring crosses itself at the shared vertex "
                        "(2, 2)"));
}

// Scaling a touching case by powers of two gives the same pieces and components; rotating it
// by quarter turns keeps it valid and its area (which diagonals split the pinches, and so the
// counts, follow the triangulation of the cocircular squares, which rotation changes).
TEST(PreparePolygonsTest, MetamorphicRotateAndScale) {
  const Polygon2d base{SquareRing(0, 0, 10),
                       {{{0, 5}, {3, 5}, {1, 6}}, {{3, 5}, {5, 4}, {5, 6}}, SquareRing(7, 7, 1)}};
  auto count = [](const Polygon2d& raw) {
    const std::vector<Polygon2d> pieces = PreparePolygons(raw, "w");
    const Decomposition2d d = Decompose2d(pieces, {});
    EXPECT_TRUE(CheckDecomposition(pieces, d).ok());
    const double outer = Area(Polygon2d{raw.outer, {}});  // Holes: 4.5 of 100.
    EXPECT_NEAR(TotalArea(pieces), outer * 0.955, 1e-9 * outer);
    return std::make_pair(pieces.size(), d.components.size());
  };
  const auto expected = count(base);
  for (const double angle : {0.0, 0.5 * M_PI, M_PI, 1.5 * M_PI}) {
    for (const double scale : {1.0, 0.125, 1024.0}) {
      Polygon2d moved = base;
      auto map = [&](Point2d& p) {
        const double c = std::round(std::cos(angle)), s = std::round(std::sin(angle));
        p = scale * Point2d(c * p.x() - s * p.y(), s * p.x() + c * p.y());
      };
      for (Point2d& p : moved.outer) map(p);
      for (Ring2d& hole : moved.holes) {
        for (Point2d& p : hole) map(p);
      }
      const auto counts = count(moved);
      if (angle == 0.0) {
        EXPECT_EQ(counts, expected) << scale;
      }
    }
  }
}

// A generated map tile: a 10^4-vertex outer ring and 10^3 holes on a grid, every fifth hole
// touching its right neighbour and every hole of the bottom row touching the outer ring.
Polygon2d LargeTouchingCase() {
  constexpr int kGrid = 32;  // 1024 holes.
  constexpr double kCell = 10.0;
  const double size = kGrid * kCell;
  RandomEngine random(7);
  Polygon2d raw;
  // Outer ring: a square whose top side is a saw tooth of ~10^4 vertices.
  raw.outer = {{0, 0}, {size, 0}};
  const int teeth = 9000;
  for (int i = 0; i <= teeth; ++i) {
    const double x = size - size * i / teeth;
    raw.outer.emplace_back(x, size + 2.0 + (i % 2 == 0 ? 0.0 : UniformReal(random, 0.0, 2.0)));
  }
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      const double x = i * kCell, y = j * kCell;
      // A diamond from (x, y+5) to (x+10, y+5): it touches the diamond to its right at
      // (x+10, y+5) when `touch`, else it stops 1 short of it.
      const bool touch_left = i > 0 && ((i - 1) * kGrid + j) % 5 == 0;
      const bool touch = (i * kGrid + j) % 5 == 0 && i + 1 < kGrid;
      const double right = touch ? x + kCell : x + kCell - 1.0;
      const double left = touch_left ? x : x + 1.0;
      // Bottom row holes touch the outer ring unless they touch a neighbour (that would close a
      // chain of rings around part of the interior).
      const double bottom = j == 0 && !touch && !touch_left ? 0.0 : y + 1.0;
      const double mid = left + (right - left) * 0.4;
      raw.holes.push_back({{left, y + 5}, {mid, bottom}, {right, y + 5}, {mid, y + 8}});
    }
  }
  return raw;
}

TEST(PreparePolygonsTest, LargeTouchingCaseDecomposes) {
  const Polygon2d raw = LargeTouchingCase();
  EXPECT_GE(VertexCount(raw), 13000);
  const Stopwatch stopwatch;
  const std::vector<Polygon2d> pieces = PreparePolygons(raw, "large");
  const double prepare_ms = stopwatch.Milliseconds();
  Decompose2dOptions options;
  options.tau = 0.01 * ReferenceRadius(raw);
  const Decomposition2d decomposition = Decompose2d(pieces, options);
  const double decompose_ms = stopwatch.Milliseconds() - prepare_ms;
  std::printf(
      "large touching case: %d vertices, %zu holes -> %zu polygons, %zu components; "
      "prepare %.1f ms, decompose %.1f ms\n",
      VertexCount(raw), raw.holes.size(), pieces.size(), decomposition.components.size(),
      prepare_ms, decompose_ms);
  const DecompositionCheck check = CheckDecomposition(pieces, decomposition);
  EXPECT_TRUE(check.ok()) << (check.ok() ? "" : check.problems[0]);
  EXPECT_EQ(OpeningGroups(decomposition), 1);
}

}  // namespace
}  // namespace acdplan::acd
