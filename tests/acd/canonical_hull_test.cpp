#include "acd/internal/canonical_hull.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "acd/convex_hull3d.h"
#include "acd/mesh_measures.h"
#include "base/random.h"

namespace acdplan::acd::internal {
namespace {

// Largest distance of a point outside one of the hull's planes (0: every point inside all).
double Excess(const CanonicalHull& hull, const std::vector<Eigen::Vector3d>& points) {
  double worst = 0;
  for (Eigen::Index r = 0; r < hull.planes.rows(); ++r) {
    for (const Eigen::Vector3d& p : points) {
      worst = std::max(worst, hull.planes.row(r).head<3>().dot(p) - hull.planes(r, 3));
    }
  }
  return worst;
}

// Six corners of a piece of hose.obj (tau_rel 0.02): four nearly collinear points make hull
// facets that are slivers. The grouping by a sliver triangle's own computed normal made a plane
// with a point 1.4 units outside it; a face 0.56 deep then measured 0 (CheckDecomposition3d:
// "concavity 0.00036 is below its re-measured lower bound 0.558").
TEST(CanonicalHullTest, EveryPlaneSupportsTheHullOfNearlyCollinearPoints) {
  const std::vector<Eigen::Vector3d> points = {
      {7.6823504463777867, 26.759969132712421, -21.531285110316908},
      {8.4703042840237082, 26.759969121074761, -21.204905167211102},
      {9.6132630704644431, 26.759969104193871, -20.731477910602646},
      {9.7085419215683171, 26.759969102786652, -20.692012266148936},
      {-9.9182033382153136, 28.835266485050656, -20.360074070418072},
      {1.4481589035329017, 34.574517110149351, -20.360074070418072}};
  const CanonicalHull hull = MakeCanonicalHull(points);
  ASSERT_GE(hull.planes.rows(), 4);
  EXPECT_LE(Excess(hull, points), 1e-9);
  // Each plane is a facet: at least three points lie in it.
  for (Eigen::Index r = 0; r < hull.planes.rows(); ++r) {
    int in_plane = 0;
    for (const Eigen::Vector3d& p : points) {
      in_plane += std::abs(hull.planes.row(r).head<3>().dot(p) - hull.planes(r, 3)) <= 1e-8;
    }
    EXPECT_GE(in_plane, 3) << "plane " << r;
  }
  EXPECT_GT(MeshVolume(hull.mesh), 0);
}

// The same points in another order give the same planes, byte for byte.
TEST(CanonicalHullTest, ThePlanesDoNotDependOnThePointOrder) {
  std::vector<Eigen::Vector3d> points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const CanonicalHull a = MakeCanonicalHull(points);
  std::reverse(points.begin(), points.end());
  const CanonicalHull b = MakeCanonicalHull(points);
  ASSERT_EQ(a.planes.rows(), 6);
  ASSERT_EQ(b.planes.rows(), 6);
  EXPECT_EQ(a.planes, b.planes);
  EXPECT_LE(Excess(a, points), 0.0);
}

// Two grids of points, a flat one and one whose heights lie within a few in-plane tolerances of
// a plane: the near-coplanar facets are regrouped, and each group's refitted plane is still a
// supporting plane of the hull (through its own vertices, it cut up to 8 tolerances into it).
TEST(CanonicalHullTest, RegroupedPlanesOfNearlyCoplanarFacetsSupportTheHull) {
  const int g = 4;
  const double tol = kInPlaneTolerance * std::sqrt(2.0 * g * g + 1.0);
  int regrouped = 0;
  for (std::uint64_t trial = 0; trial < 200; ++trial) {
    RandomEngine rng(DeriveSeed(3, trial));
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i <= g; ++i) {
      for (int j = 0; j <= g; ++j) {
        points.emplace_back(j, i, 0.0);
        points.emplace_back(j, i, 1.0 + UniformReal(rng, -3 * tol, 3 * tol));
      }
    }
    const CanonicalHull hull = MakeCanonicalHull(points);
    ASSERT_GE(hull.planes.rows(), 5) << "trial " << trial;
    regrouped += hull.planes.rows() < HullPlanes(hull.mesh).rows();
    EXPECT_LE(Excess(hull, points), 1e-12) << "trial " << trial;
  }
  EXPECT_GT(regrouped, 100);
}

}  // namespace
}  // namespace acdplan::acd::internal
