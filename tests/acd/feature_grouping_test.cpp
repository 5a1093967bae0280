#include "acd/internal/feature_grouping.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "acd/internal/solid_concavity.h"
#include "solid_test_meshes.h"

namespace acdplan::acd::internal {
namespace {

using test::Box;
using test::Concatenate;
using test::LBlock;
using test::Torus;
using test::UBlock;

double Side(const Plane3d& plane, const Eigen::Vector3d& p) {
  return plane.normal.dot(p) - plane.offset;
}

Eigen::Vector3d At(const TriangleMesh& mesh, int v) { return mesh.vertices.row(v); }

TEST(DouglasPeucker, KeepsTheCriticalPointsOfATent) {
  // A tent with a ramp of collinear points and a bump below delta.
  const std::vector<Eigen::Vector2d> chain = {{0, 0}, {1, 1},    {2, 2}, {3, 1},
                                              {4, 0}, {5, 0.05}, {6, 0}};
  EXPECT_EQ(DouglasPeucker(chain, 0.1), (std::vector<int>{0, 2, 4, 6}));
  // The bump is kept once delta is below its height, and the tent's peak whatever delta is.
  EXPECT_EQ(DouglasPeucker(chain, 0.01), (std::vector<int>{0, 2, 4, 5, 6}));
  EXPECT_EQ(DouglasPeucker(chain, 10.0), (std::vector<int>{0, 6}));
}

TEST(DouglasPeucker, SplitsAtTheFarthestPointFirst) {
  // Algorithm 7 worked by hand: the farthest point from the line of the ends is (4, 1.02),
  // then (2, 0) on the left stretch, then (3, 1) and (5, 1); (1, 0.05) is within delta.
  const std::vector<Eigen::Vector2d> chain = {{0, 0},    {1, 0.05}, {2, 0}, {3, 1},
                                              {4, 1.02}, {5, 1},    {6, 0}};
  EXPECT_EQ(DouglasPeucker(chain, 0.1), (std::vector<int>{0, 2, 3, 4, 5, 6}));
  EXPECT_EQ(DouglasPeucker({{0, 0}, {1, 1}}, 0.1), (std::vector<int>{0, 1}));
  // A closed chain (ends equal): distances are measured from the end point.
  EXPECT_EQ(DouglasPeucker({{0, 0}, {1, 0.5}, {0, 0}}, 0.1), (std::vector<int>{0, 1, 2}));
}

TEST(FeatureGrouping, KnotsOfTheUBlockSlotAreItsFloorCorners) {
  // The slot of the U, [1,2] x [1,2] x [0,1], is one pocket under the bridge y = 2; its border
  // is one loop, at concavity 0 on the posts' rims (y = 2) and 1 along the floor (y = 1).
  const TriangleMesh u = UBlock();
  const SolidConcavity c = MeasureSolidConcavity(u, 0.05);
  ASSERT_NEAR(c.value, 1.0, 1e-9);
  ASSERT_GE(c.witness_pocket, 0);
  const std::vector<std::vector<int>> loops = PocketBorderLoops(u, c.face_pocket, c.witness_pocket);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 8u);
  std::vector<int> knots = FindKnots(u, loops[0], c.vertex_concavity, 0.005);
  ASSERT_EQ(knots.size(), 4u);
  std::vector<std::vector<double>> at;
  for (int v : knots) at.push_back({At(u, v).x(), At(u, v).y(), At(u, v).z()});
  std::sort(at.begin(), at.end());
  EXPECT_EQ(at, (std::vector<std::vector<double>>{{1, 1, 0}, {1, 1, 1}, {2, 1, 0}, {2, 1, 1}}));
}

TEST(FeatureGrouping, KnotsNeedAPeakAboveDelta) {
  // A loop whose concavity is a single low bump: no knot at delta above it.
  const TriangleMesh u = UBlock();
  const SolidConcavity c = MeasureSolidConcavity(u, 0.05);
  const auto loops = PocketBorderLoops(u, c.face_pocket, c.witness_pocket);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_TRUE(FindKnots(u, loops[0], c.vertex_concavity, 1.5).empty());
}

TEST(FeatureGrouping, GlobalCutOfTheLBlockSeparatesItsArms) {
  const TriangleMesh l = LBlock();
  const SolidConcavity c = MeasureSolidConcavity(l, 0.05);
  const GlobalCut cut = FindGlobalCut(l, c, 0.05);
  ASSERT_TRUE(cut.found);
  EXPECT_FALSE(cut.cup);  // the witness is a corner of the reflex edge: a knot
  EXPECT_GT(cut.weight, 0);
  // The root pocket cut is the reflex edge (1, 1, z).
  ASSERT_EQ(cut.root_cut_length, 2);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(At(l, cut.cycle[static_cast<size_t>(i)]).x(), 1.0, 1e-12);
    EXPECT_NEAR(At(l, cut.cycle[static_cast<size_t>(i)]).y(), 1.0, 1e-12);
  }
  // The plane runs along the reflex edge and puts the two arms on different sides.
  EXPECT_LT(std::abs(Side(cut.plane, {1, 1, 0.5})), 0.2);
  EXPECT_LT(Side(cut.plane, {1.5, 0.5, 0.5}) * Side(cut.plane, {0.5, 1.5, 0.5}), 0);
}

TEST(FeatureGrouping, GlobalCutOfTheUBlockCutsAtTheSlotFloor) {
  const TriangleMesh u = UBlock();
  const SolidConcavity c = MeasureSolidConcavity(u, 0.05);
  const GlobalCut cut = FindGlobalCut(u, c, 0.05);
  ASSERT_TRUE(cut.found);
  // The cut passes the witness (on the slot's floor edge, y = 1, x in [1, 2]) and separates a
  // post from the base's far end.
  EXPECT_LT(std::abs(Side(cut.plane, c.witness)), 0.2);
  EXPECT_NEAR(c.witness.y(), 1.0, 1e-12);
  const bool left = Side(cut.plane, {0.5, 1.5, 0.5}) * Side(cut.plane, {2.5, 0.5, 0.5}) < 0;
  const bool right = Side(cut.plane, {2.5, 1.5, 0.5}) * Side(cut.plane, {0.5, 0.5, 0.5}) < 0;
  EXPECT_TRUE(left || right);
}

TEST(FeatureGrouping, GlobalCutOfATorusCutsTheTube) {
  // The hole's pocket lies under the two caps; its deepest vertices ring the inner equator.
  // The lightest cycle runs from a rim through the hole and around the tube (a meridian), so
  // its plane holds the axis and cuts the ring open.
  const TriangleMesh torus = Torus(2.0, 1.0, 24, 12);
  const SolidConcavity c = MeasureSolidConcavity(torus, 0.2);
  const GlobalCut cut = FindGlobalCut(torus, c, 0.2);
  ASSERT_TRUE(cut.found);
  // The rims lie in the caps (concavity 0): no knot, the witness is not one (Fig. 42's cup),
  // and the cut is forced through it from the rims' start and far points.
  EXPECT_TRUE(cut.cup);
  EXPECT_EQ(cut.knots.size(), 4u);
  ASSERT_GE(cut.root_cut_length, 3);
  EXPECT_LT(std::abs(cut.plane.normal.z()), 0.2);
  EXPECT_LT(std::abs(cut.plane.offset), 0.3);
}

TEST(FeatureGrouping, ConvexAndCavityPiecesHaveNoGlobalCut) {
  const TriangleMesh cube = Box({0, 0, 0}, {1, 1, 1});
  EXPECT_FALSE(FindGlobalCut(cube, MeasureSolidConcavity(cube, 0.05), 0.05).found);
  // A box with a cavity: the witness's pocket is the inner shell, which has no border.
  const TriangleMesh box = Concatenate(Box({0, 0, 0}, {4, 4, 4}), Box({1, 1, 1}, {3, 3, 3}, true));
  const SolidConcavity c = MeasureSolidConcavity(box, 0.1);
  ASSERT_GT(c.value, 0.5);
  EXPECT_FALSE(FindGlobalCut(box, c, 0.1).found);
}

TEST(FeatureGrouping, LighterCutsComeFirst) {
  const TriangleMesh torus = Torus(2.0, 1.0, 24, 12);
  const SolidConcavity c = MeasureSolidConcavity(torus, 0.2);
  FeatureGroupingOptions options;
  options.max_cuts = 3;
  const std::vector<GlobalCut> cuts = FindGlobalCuts(torus, c, 0.2, options);
  ASSERT_GE(cuts.size(), 2u);
  EXPECT_LE(cuts.size(), 3u);
  const GlobalCut best = FindGlobalCut(torus, c, 0.2);
  EXPECT_EQ(cuts[0].cycle, best.cycle);
  for (size_t i = 1; i < cuts.size(); ++i) {
    EXPECT_LE(cuts[i - 1].weight, cuts[i].weight);
    EXPECT_FALSE(cuts[i].plane.normal == cuts[i - 1].plane.normal &&
                 cuts[i].plane.offset == cuts[i - 1].plane.offset);
  }
}

TEST(FeatureGrouping, SameInputSameCut) {
  const TriangleMesh torus = Torus(2.0, 1.0, 16, 8);
  const SolidConcavity c = MeasureSolidConcavity(torus, 0.3);
  const GlobalCut a = FindGlobalCut(torus, c, 0.3), b = FindGlobalCut(torus, c, 0.3);
  EXPECT_EQ(a.cycle, b.cycle);
  EXPECT_EQ(a.knots, b.knots);
  EXPECT_EQ(a.plane.normal, b.plane.normal);
  EXPECT_EQ(a.plane.offset, b.plane.offset);
}

}  // namespace
}  // namespace acdplan::acd::internal
