#include "acd/internal/solid_concavity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "acd/convex_hull3d.h"
#include "acd/internal/canonical_hull.h"
#include "acd/internal/in_plane_tolerance.h"
#include "acd/mesh_measures.h"
#include "base/random.h"
#include "solid_test_meshes.h"

namespace acdplan::acd::internal {
namespace {

// The L-block's notch corner (1, 1) lies 1/sqrt(2) below the hull's slanted facet x + y = 3.
TEST(MeasureSolidConcavity, TheLBlockIsAsDeepAsItsNotchCorner) {
  const SolidConcavity c = MeasureSolidConcavity(test::LBlock(), 0.1);
  EXPECT_NEAR(c.value, std::sqrt(0.5), 1e-9);
  EXPECT_GE(c.witness_vertex, 0);
  EXPECT_NEAR(c.witness.x(), 1.0, 1e-12);
  EXPECT_NEAR(c.witness.y(), 1.0, 1e-12);
}

// A needle (the L-profile 1e-4 across, 1 long) has a hull volume below kInPlaneTolerance x its
// size cubed, as a flat plate has, but it is not flat: its notch is 7e-5 deep, far above the
// in-plane tolerance of 1.4e-6. Judged flat by its hull volume, it was measured 0 and failed
// CheckDecomposition3d's re-measure (ob_chair_gothic, tau_rel 0.05, a sliver of a cut).
TEST(MeasureSolidConcavity, ANeedleIsNotFlat) {
  const double s = 1e-4;
  const TriangleMesh needle =
      test::Extrude({{0, 0}, {2 * s, 0}, {2 * s, s}, {s, s}, {s, 2 * s}, {0, 2 * s}}, 1.0);
  EXPECT_NEAR(MeasureSolidConcavity(needle, 1e-5).value, std::sqrt(0.5) * s, 1e-9);
}

// A plate within the in-plane tolerance of one plane is flat, whatever its outline.
TEST(MeasureSolidConcavity, APlateThinnerThanTheToleranceIsFlat) {
  const TriangleMesh plate = test::Extrude({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 1e-8);
  EXPECT_EQ(MeasureSolidConcavity(plate, 0.1).value, 0.0);
}

// A closed block over [0, g]^2 whose top is the g x g grid at the heights `z` ((g+1)^2 of them,
// row by row), its bottom at z = 0 fanned from its centre.
TriangleMesh HeightfieldBlock(int g, const std::vector<double>& z) {
  std::vector<Eigen::Vector3d> v;
  std::vector<Eigen::Vector3i> f;
  auto top = [g](int i, int j) { return i * (g + 1) + j; };
  for (int i = 0; i <= g; ++i) {
    for (int j = 0; j <= g; ++j) v.emplace_back(j, i, z[static_cast<size_t>(top(i, j))]);
  }
  for (int i = 0; i < g; ++i) {
    for (int j = 0; j < g; ++j) {
      f.emplace_back(top(i, j), top(i, j + 1), top(i + 1, j + 1));
      f.emplace_back(top(i, j), top(i + 1, j + 1), top(i + 1, j));
    }
  }
  // The top's rim counter-clockwise seen from above, and the bottom's copy of it.
  std::vector<int> rim;
  for (int j = 0; j < g; ++j) rim.push_back(top(0, j));
  for (int i = 0; i < g; ++i) rim.push_back(top(i, g));
  for (int j = g; j > 0; --j) rim.push_back(top(g, j));
  for (int i = g; i > 0; --i) rim.push_back(top(i, 0));
  const int base = static_cast<int>(v.size());
  for (int t : rim)
    v.emplace_back(v[static_cast<size_t>(t)].x(), v[static_cast<size_t>(t)].y(), 0.0);
  const int centre = static_cast<int>(v.size());
  v.emplace_back(g / 2.0, g / 2.0, 0.0);
  const int n = static_cast<int>(rim.size());
  for (int k = 0; k < n; ++k) {
    const int l = (k + 1) % n;
    f.emplace_back(rim[static_cast<size_t>(k)], base + k, base + l);
    f.emplace_back(rim[static_cast<size_t>(k)], base + l, rim[static_cast<size_t>(l)]);
    f.emplace_back(centre, base + l, base + k);
  }
  return MakeTriangleMesh(v, f);
}

// The depth of the deepest vertex below the boundary of the exact hull of the mesh's vertices.
double DeepestVertex(const TriangleMesh& mesh) {
  std::vector<Eigen::Vector3d> points;
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i) points.push_back(mesh.vertices.row(i));
  const Eigen::Matrix<double, Eigen::Dynamic, 4> planes = HullPlanes(ConvexHull3(points, 0.0));
  double deepest = 0;
  for (const Eigen::Vector3d& p : points) {
    double depth = std::numeric_limits<double>::infinity();
    for (Eigen::Index r = 0; r < planes.rows(); ++r) {
      depth = std::min(depth, planes(r, 3) - planes.row(r).head<3>().dot(p));
    }
    deepest = std::max(deepest, depth);
  }
  return deepest;
}

// A top of near-coplanar facets (heights within a few in-plane tolerances of 1) with one vertex
// pressed in: the hull's planes regroup those facets, and a plane refitted through its group's
// own vertices could cut into the hull and take a vertex several tolerances deep as in it, or
// measure it from too low (fuzz_decompose3d: a component of concavity 0 with a vertex 1.4e-5
// below its hull). The measure is never more than the in-plane tolerance below the deepest
// vertex's true depth. Trials 0-299 and those a search of 5,000 found measured too low.
TEST(MeasureSolidConcavity, NearlyCoplanarHullFacetsHideNoDepth) {
  const int g = 4;
  std::vector<std::uint64_t> trials = {128, 576, 2181, 2815, 3631, 4023, 4582};
  for (std::uint64_t t = 0; t < 300; ++t) trials.push_back(t);
  int deep = 0;
  for (std::uint64_t trial : trials) {
    RandomEngine rng(DeriveSeed(7, trial));
    const double tol = kInPlaneTolerance * std::sqrt(2.0 * g * g + 1.0);
    std::vector<double> z(static_cast<size_t>((g + 1) * (g + 1)));
    for (double& h : z) h = 1.0 + UniformReal(rng, -3 * tol, 3 * tol);
    const int i = 1 + static_cast<int>(UniformIndex(rng, g - 1));
    const int j = 1 + static_cast<int>(UniformIndex(rng, g - 1));
    z[static_cast<size_t>(i * (g + 1) + j)] -= UniformReal(rng, 2 * tol, 10 * tol);
    const TriangleMesh block = HeightfieldBlock(g, z);
    const double truth = DeepestVertex(block);
    const double scale = BoundingBox(block).diagonal().norm();
    deep += truth > 2 * kInPlaneTolerance * scale;
    EXPECT_GE(MeasureSolidConcavity(block, 0.1).value, truth - kInPlaneTolerance * scale)
        << "trial " << trial;
  }
  EXPECT_GT(deep, 100);  // most pressed vertices lie clearly below the tolerance
}

// Found by fuzz/fuzz_decompose3d (fuzz/corpus/decompose3d/regression-hull-keeps-three-planes.bin;
// repaired, then kept by the solid ACD as one component of concavity 0; CheckDecomposition3d
// re-measured 0.756): a solid whose hull has 5 vertices and keeps only 3 of its regrouped planes
// (MakeCanonicalHull drops a plane a hull vertex lies clearly outside of). Fewer than four planes
// were taken for a flat hull, measured 0.
TEST(MeasureSolidConcavity, AHullThatKeepsFewerThanFourPlanesIsNotTakenForFlat) {
  const std::vector<Eigen::Vector3d> v = {
      {4, 4, 0},
      {0, -21.75, -21.5},
      {0, -0.25, -0.25},
      {-32, 0, 0},
      {4, 0, 0},
      {-13.017863161442534, -12.901921132457026, -12.753623188405797},
      {-12.340807174887891, -12.340807174887891, -12.340807174887891},
      {-12.274906780106086, -12.382175305918805, -12.382175305918805},
      {-0.25001754859722702, -0.24999979354591495, -0.24997708359656229},
      {-0.24806201550387597, -0.24806201550387597, -0.24806201550387597},
      {0, 0, 0},
      {0.23529411764705882, 0, 0}};
  const std::vector<Eigen::Vector3i> f = {
      {3, 5, 8}, {3, 6, 5},   {3, 8, 9},  {3, 9, 10}, {3, 10, 0},  {3, 0, 6}, {5, 6, 7},
      {5, 7, 1}, {5, 1, 8},   {6, 0, 7},  {7, 0, 1},  {8, 1, 2},   {8, 2, 9}, {9, 2, 10},
      {1, 0, 2}, {2, 11, 10}, {2, 4, 11}, {2, 0, 4},  {10, 11, 0}, {11, 4, 0}};
  const TriangleMesh mesh = MakeTriangleMesh(v, f);
  ASSERT_GT(MeshVolume(mesh), 400.0);
  ASSERT_LT(MakeCanonicalHull(v).planes.rows(), 4);
  EXPECT_GT(MeasureSolidConcavity(mesh, 0.45).value, 0.7);
}

}  // namespace
}  // namespace acdplan::acd::internal
