#include "acd/check_decomposition.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "acd/decompose2d.h"
#include "acd/read_polygons.h"
#include "tests/acd/problem_lines.h"
#include "tests/data_paths.h"

namespace acdplan::acd {
namespace {

// Fills hull, centroid, concavity 0 and the stats of a hand-made decomposition, so each test
// only breaks the one rule it is about.
Component2d MakeComponent(const Ring2d& outer, int source = 0) {
  Component2d c;
  c.polygon.outer = outer;
  c.hull = outer;  // The fixtures are convex; a test breaks this on purpose.
  c.centroid = Centroid(c.polygon);
  c.concavity = 0.0;
  c.source = source;
  return c;
}

void FillStats(Decomposition2d* d) {
  d->stats.components = static_cast<int>(d->components.size());
  double areas = 0.0, hulls = 0.0, max_concavity = 0.0;
  for (const Component2d& c : d->components) {
    areas += Area(c.polygon);
    hulls += SignedArea(c.hull);
    max_concavity = std::max(max_concavity, c.concavity);
  }
  d->stats.max_concavity = max_concavity;
  d->stats.convexity = hulls > 0.0 ? areas / hulls : 1.0;
}

std::vector<Polygon2d> UnitSquare() { return {Polygon2d{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}}}; }

// The unit square cut along its diagonal (0,0)-(1,1), with the opening on the cut.
Decomposition2d TwoTriangles() {
  Decomposition2d d;
  d.components.push_back(MakeComponent({{0, 0}, {1, 0}, {1, 1}}));
  d.components.push_back(MakeComponent({{0, 0}, {1, 1}, {0, 1}}));
  d.openings.push_back({{0, 0}, {1, 1}, 0, 1});
  FillStats(&d);
  return d;
}

// True if some problem line contains every one of `words`.
bool HasProblem(const DecompositionCheck& check, const std::vector<std::string>& words) {
  for (const std::string& line : check.problems) {
    bool all = true;
    for (const std::string& word : words) all = all && line.find(word) != std::string::npos;
    if (all) return true;
  }
  return false;
}

TEST(CheckDecompositionTest, SquareSplitIntoTwoTrianglesIsOk) {
  const DecompositionCheck check = CheckDecomposition(UnitSquare(), TwoTriangles());
  EXPECT_TRUE(check.ok()) << acdplan::test::ProblemLines(check);
}

TEST(CheckDecompositionTest, SteinerPointOnASharedCutIsOk) {
  // Square split by x = 0.5; the right half is split again at y = 0.5, so the left half has an
  // edge that the right pieces meet at a T-junction (the left half has no vertex there).
  Decomposition2d d;
  d.components.push_back(MakeComponent({{0, 0}, {0.5, 0}, {0.5, 1}, {0, 1}}));
  d.components.push_back(MakeComponent({{0.5, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}}));
  d.components.push_back(MakeComponent({{0.5, 0.5}, {1, 0.5}, {1, 1}, {0.5, 1}}));
  FillStats(&d);
  const DecompositionCheck check = CheckDecomposition(UnitSquare(), d);
  EXPECT_TRUE(check.ok()) << acdplan::test::ProblemLines(check);
}

TEST(CheckDecompositionTest, ShiftedTriangleOverlaps) {
  Decomposition2d d = TwoTriangles();
  for (Point2d& p : d.components[1].polygon.outer) p.x() += 0.25;
  d.components[1].hull = d.components[1].polygon.outer;
  d.components[1].centroid = Centroid(d.components[1].polygon);
  FillStats(&d);
  const DecompositionCheck check = CheckDecomposition(UnitSquare(), d);
  EXPECT_TRUE(HasProblem(check, {"components 0 and 1 overlap"}))
      << acdplan::test::ProblemLines(check);
  EXPECT_TRUE(HasProblem(check, {"component 1:", "outside input polygon 0"}))
      << acdplan::test::ProblemLines(check);
}

TEST(CheckDecompositionTest, DuplicatedComponentOverlaps) {
  Decomposition2d d = TwoTriangles();
  d.components[1] = d.components[0];
  d.openings.clear();
  FillStats(&d);
  const DecompositionCheck check = CheckDecomposition(UnitSquare(), d);
  EXPECT_TRUE(HasProblem(check, {"components 0 and 1 overlap"}))
      << acdplan::test::ProblemLines(check);
}

TEST(CheckDecompositionTest, OverlapThroughVerticesOnlyIsFound) {
  // Overlap without any proper crossing, vertex inside the other or shared stretch: the
  // triangle's bottom edge is a chord of the rectangle between two of its boundary points.
  const std::vector<Polygon2d> input = {Polygon2d{{{0, -1}, {2, -1}, {2, 2}, {0, 2}}, {}}};
  Decomposition2d d;
  d.components.push_back(MakeComponent({{0, 0}, {2, 0}, {2, 2}}));
  d.components.push_back(MakeComponent({{1, -1}, {1, 0}, {1, 1}, {0, 1}, {0, -1}}));
  d.components.back().hull = {{1, -1}, {1, 1}, {0, 1}, {0, -1}};
  FillStats(&d);
  const DecompositionCheck check = CheckDecomposition(input, d);
  EXPECT_TRUE(HasProblem(check, {"components 0 and 1 overlap"}))
      << acdplan::test::ProblemLines(check);
}

TEST(CheckDecompositionTest, MissingPieceBreaksTheAreaSum) {
  Decomposition2d d = TwoTriangles();
  d.components.pop_back();
  d.openings.clear();
  FillStats(&d);
  const DecompositionCheck check = CheckDecomposition(UnitSquare(), d);
  EXPECT_TRUE(HasProblem(check, {"area of components 0.5 != input area 1 (polygon 0)"}))
      << acdplan::test::ProblemLines(check);
}

TEST(CheckDecompositionTest, ClockwiseComponent) {
  Decomposition2d d = TwoTriangles();
  d.components[1].polygon.outer = Reversed(d.components[1].polygon.outer);
  FillStats(&d);
  const DecompositionCheck check = CheckDecomposition(UnitSquare(), d);
  EXPECT_TRUE(HasProblem(check, {"component 1:", "clockwise"}))
      << acdplan::test::ProblemLines(check);
}

TEST(CheckDecompositionTest, TooFewVertices) {
  Decomposition2d d = TwoTriangles();
  d.components[1].polygon.outer.pop_back();
  FillStats(&d);
  const DecompositionCheck check = CheckDecomposition(UnitSquare(), d);
  EXPECT_TRUE(HasProblem(check, {"component 1:", "2 vertices", ">= 3"}))
      << acdplan::test::ProblemLines(check);
}

TEST(CheckDecompositionTest, BowTieIsNotSimple) {
  const std::vector<Polygon2d> input = UnitSquare();
  Decomposition2d d;
  d.components.push_back(MakeComponent({{0, 0}, {1, 1}, {1, 0}, {0, 1}}));
  d.components[0].hull = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  FillStats(&d);
  const DecompositionCheck check = CheckDecomposition(input, d);
  EXPECT_TRUE(
      HasProblem(check, {"component 0: not simple: edges (0,1) and (2,3) cross at (0.5, 0.5)"}))
      << acdplan::test::ProblemLines(check);
}

TEST(CheckDecompositionTest, SpikeIsNotSimple) {
  Decomposition2d d;
  d.components.push_back(MakeComponent({{0, 0}, {1, 0}, {1, 1}, {1, 0.5}, {1, 1}, {0, 1}}));
  const DecompositionCheck check = CheckDecomposition(UnitSquare(), d);
  EXPECT_TRUE(HasProblem(check, {"component 0: not simple"})) << acdplan::test::ProblemLines(check);
}

TEST(CheckDecompositionTest, ComponentOutsideTheInput) {
  Decomposition2d d = TwoTriangles();
  d.components.push_back(MakeComponent({{2, 0}, {3, 0}, {3, 1}}));
  FillStats(&d);
  const DecompositionCheck check = CheckDecomposition(UnitSquare(), d);
  EXPECT_TRUE(HasProblem(check, {"component 2:", "lies outside input polygon 0"}))
      << acdplan::test::ProblemLines(check);
  EXPECT_TRUE(HasProblem(check, {"area of components"})) << acdplan::test::ProblemLines(check);
}

TEST(CheckDecompositionTest, ComponentCoveringAnInputHole) {
  Polygon2d square{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 1}, {1, 3}, {3, 3}, {3, 1}}}};
  Decomposition2d d;
  d.components.push_back(MakeComponent(square.outer));
  FillStats(&d);
  const DecompositionCheck check = CheckDecomposition({square}, d);
  // Its deepest interior point is the hole's centre.
  EXPECT_TRUE(
      HasProblem(check, {"component 0: interior point (2, 2) lies outside input polygon 0"}))
      << acdplan::test::ProblemLines(check);
  EXPECT_TRUE(HasProblem(check, {"area of components 16 != input area 12"}))
      << acdplan::test::ProblemLines(check);

  // An off-centre hole: its boundary (or its inside sample) lies strictly inside the component.
  Polygon2d off_centre{square.outer, {{{0.5, 0.5}, {0.5, 1}, {1, 1}, {1, 0.5}}}};
  const DecompositionCheck covered = CheckDecomposition({off_centre}, d);
  EXPECT_TRUE(HasProblem(covered, {"component 0: covers a", "of input polygon 0"}))
      << acdplan::test::ProblemLines(covered);
}

TEST(CheckDecompositionTest, ComponentWithAHoleIsOkForLargeTau) {
  Polygon2d square{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 1}, {1, 3}, {3, 3}, {3, 1}}}};
  Decomposition2d d;
  d.tau = 100.0;
  d.components.push_back(MakeComponent(square.outer));
  d.components[0].polygon = square;
  d.components[0].centroid = Centroid(square);
  FillStats(&d);
  const DecompositionCheck check = CheckDecomposition({square}, d);
  EXPECT_TRUE(check.ok()) << acdplan::test::ProblemLines(check);

  d.tau = 0.0;
  const DecompositionCheck strict = CheckDecomposition({square}, d);
  EXPECT_TRUE(HasProblem(strict, {"component 0: not convex: 1 holes left"}))
      << acdplan::test::ProblemLines(strict);
}

TEST(CheckDecompositionTest, ConcaveComponentWithTauZeroIsNotConvex) {
  // An L-shape left whole.
  const Ring2d l_shape = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  Decomposition2d d;
  d.components.push_back(MakeComponent(l_shape));
  d.components[0].hull = {{0, 0}, {2, 0}, {2, 1}, {1, 2}, {0, 2}};
  FillStats(&d);
  const DecompositionCheck check = CheckDecomposition({Polygon2d{l_shape, {}}}, d);
  EXPECT_TRUE(HasProblem(check, {"component 0: concavity", "> tau 0"}))
      << acdplan::test::ProblemLines(check);
  EXPECT_TRUE(HasProblem(check, {"component 0: not convex: vertex 3 (1, 1) is a notch"}))
      << acdplan::test::ProblemLines(check);

  d.tau = 1.0;  // Its concavity is about 0.7 under every measure.
  EXPECT_TRUE(CheckDecomposition({Polygon2d{l_shape, {}}}, d).ok());

  d.tau = 0.0;
  d.min_convexity = 0.8;  // Area 3 / hull area 3.5 = 0.857.
  EXPECT_TRUE(CheckDecomposition({Polygon2d{l_shape, {}}}, d).ok());
  d.min_convexity = 0.9;
  EXPECT_TRUE(HasProblem(CheckDecomposition({Polygon2d{l_shape, {}}}, d),
                         {"component 0: convexity", "< min_convexity 0.9"}));
}

TEST(CheckDecompositionTest, WrongHullAndCentroid) {
  Decomposition2d d = TwoTriangles();
  d.components[0].hull = {{0, 0}, {1, 0}, {0.9, 0.9}};
  d.components[1].centroid = {0.5, 0.5};
  FillStats(&d);
  const DecompositionCheck check = CheckDecomposition(UnitSquare(), d);
  EXPECT_TRUE(HasProblem(check, {"component 0: vertex 2 (1, 1) lies outside its hull"}))
      << acdplan::test::ProblemLines(check);
  EXPECT_TRUE(HasProblem(check, {"component 1: centroid (0.5, 0.5) != Centroid(polygon)"}))
      << acdplan::test::ProblemLines(check);

  d = TwoTriangles();
  d.components[0].hull = {{0, 0}, {1, 1}, {1, 0}};  // Clockwise.
  const DecompositionCheck clockwise = CheckDecomposition(UnitSquare(), d);
  EXPECT_TRUE(HasProblem(clockwise, {"component 0: hull is not convex counter-clockwise"}))
      << acdplan::test::ProblemLines(clockwise);

  d = TwoTriangles();
  d.components[0].hull = {{0, 0}, {2, 0}, {1, 1}};  // Contains the triangle but is too big.
  FillStats(&d);
  const DecompositionCheck loose = CheckDecomposition(UnitSquare(), d);
  EXPECT_TRUE(HasProblem(loose, {"component 0: hull area 1 exceeds"}))
      << acdplan::test::ProblemLines(loose);
}

TEST(CheckDecompositionTest, LargeConvexComponentAndItsHull) {
  Ring2d circle;
  for (int i = 0; i < 2000; ++i) {
    const double angle = 2.0 * 3.14159265358979323846 * i / 2000;
    circle.push_back({100.0 + 50.0 * std::cos(angle), -20.0 + 50.0 * std::sin(angle)});
  }
  Decomposition2d d;
  d.components.push_back(MakeComponent(circle));
  FillStats(&d);
  const DecompositionCheck check = CheckDecomposition({Polygon2d{circle, {}}}, d);
  EXPECT_TRUE(check.ok()) << acdplan::test::ProblemLines(check);

  d.components[0].hull.erase(d.components[0].hull.begin() + 700);  // Vertex 700 now sticks out.
  const DecompositionCheck missing = CheckDecomposition({Polygon2d{circle, {}}}, d);
  EXPECT_TRUE(HasProblem(missing, {"component 0: vertex 700", "lies outside its hull"}))
      << acdplan::test::ProblemLines(missing);
}

TEST(CheckDecompositionTest, OpeningNotOnTheBoundary) {
  Decomposition2d d = TwoTriangles();
  d.openings[0].b = {0.5, 0.6};
  const DecompositionCheck check = CheckDecomposition(UnitSquare(), d);
  EXPECT_TRUE(HasProblem(
      check, {"opening 0: end point b (0.5, 0.6) is not on the boundary of component 0"}))
      << acdplan::test::ProblemLines(check);
  EXPECT_TRUE(HasProblem(check, {"opening 0: end point b", "component 1"}))
      << acdplan::test::ProblemLines(check);

  d = TwoTriangles();
  d.openings[0].component_b = 0;
  EXPECT_TRUE(
      HasProblem(CheckDecomposition(UnitSquare(), d), {"opening 0: both sides are component 0"}));
  d.openings[0].component_b = 7;
  EXPECT_TRUE(HasProblem(CheckDecomposition(UnitSquare(), d),
                         {"opening 0: component index 7 out of range (2 components)"}));
  d = TwoTriangles();
  d.openings[0].b = d.openings[0].a;
  EXPECT_TRUE(
      HasProblem(CheckDecomposition(UnitSquare(), d), {"opening 0: end points a and b are equal"}));
}

TEST(CheckDecompositionTest, WrongStats) {
  Decomposition2d d = TwoTriangles();
  d.stats.components = 3;
  d.stats.max_concavity = 0.5;
  d.stats.convexity = 0.9;
  const DecompositionCheck check = CheckDecomposition(UnitSquare(), d);
  EXPECT_TRUE(HasProblem(check, {"stats.components 3 != 2"})) << acdplan::test::ProblemLines(check);
  EXPECT_TRUE(HasProblem(check, {"stats.max_concavity 0.5 != largest component concavity 0"}))
      << acdplan::test::ProblemLines(check);
  EXPECT_TRUE(HasProblem(check, {"stats.convexity 0.9 !=", "Eqn. 4.4"}))
      << acdplan::test::ProblemLines(check);
}

TEST(CheckDecompositionTest, BadSourceIndex) {
  Decomposition2d d = TwoTriangles();
  d.components[1].source = 4;
  const DecompositionCheck check = CheckDecomposition(UnitSquare(), d);
  EXPECT_TRUE(HasProblem(check, {"component 1: source 4 is not an input index"}))
      << acdplan::test::ProblemLines(check);
}

TEST(CheckDecompositionTest, ProblemListIsCapped) {
  Decomposition2d d;
  for (int i = 0; i < 60; ++i) d.components.push_back(MakeComponent({{0, 0}, {1, 0}}));
  const DecompositionCheck check = CheckDecomposition(UnitSquare(), d);
  ASSERT_EQ(check.problems.size(), 51u);
  EXPECT_EQ(check.problems.back().rfind("... and ", 0), 0u) << check.problems.back();
}

TEST(CheckDecompositionTest, NazcaMonkeyConvexDecomposition) {
  const std::vector<Polygon2d> input =
      ReadPolygons(acdplan::test::DataDir() + "/polygons/acd2d/nazca/nazca_monkey.poly");
  ASSERT_FALSE(input.empty());
  Decomposition2d d = Decompose2d(input, Decompose2dOptions{});
  ASSERT_GT(d.components.size(), 1u);
  const DecompositionCheck check = CheckDecomposition(input, d);
  EXPECT_TRUE(check.ok()) << acdplan::test::ProblemLines(check);

  // Move one vertex of a component outward (away from its centroid) by 1% of the radius: the
  // component now overlaps a neighbour or leaves the input, and the areas no longer add up.
  Component2d& c = d.components[d.components.size() / 2];
  Point2d& v = c.polygon.outer[0];
  v += (v - c.centroid).normalized() * 0.01 * ReferenceRadius(input[0]);
  const DecompositionCheck broken = CheckDecomposition(input, d);
  EXPECT_FALSE(broken.ok());
  EXPECT_TRUE(HasProblem(broken, {"area of components"})) << acdplan::test::ProblemLines(broken);
}

}  // namespace
}  // namespace acdplan::acd
