// ConvexHull3 and HullPlanes: the half-spaces contain every point the hull was built from, also
// when nearly collinear points make sliver facets (the cut faces of the 3D ACD's pieces do).

#include "acd/convex_hull3d.h"

#include <gtest/gtest.h>

#include <vector>

#include "acd/mesh_measures.h"
#include "base/random.h"

namespace acdplan::acd {
namespace {

/// Largest n . p - d over the rows of `planes` and the `points`.
double WorstViolation(const Eigen::Matrix<double, Eigen::Dynamic, 4>& planes,
                      const std::vector<Eigen::Vector3d>& points) {
  double worst = -1e300;
  for (const Eigen::Vector3d& p : points) {
    for (Eigen::Index r = 0; r < planes.rows(); ++r) {
      worst = std::max(worst, planes.row(r).head<3>().dot(p) - planes(r, 3));
    }
  }
  return worst;
}

TEST(HullPlanes, ACubeHasSixPlanes) {
  const TriangleMesh cube = Cube(2);
  const Eigen::Matrix<double, Eigen::Dynamic, 4> planes = HullPlanes(cube);
  EXPECT_EQ(planes.rows(), 6);
  for (Eigen::Index r = 0; r < planes.rows(); ++r) EXPECT_NEAR(planes(r, 3), 1.0, 1e-15);
}

TEST(HullPlanes, ContainEveryPointDespiteSliverFacets) {
  // Points on a few long segments, each point off its segment by rounding-sized amounts: the
  // hull has facets with nearly collinear corners.
  RandomEngine rng(7);
  double worst = -1e300;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Eigen::Vector3d> points;
    for (int segment = 0; segment < 4; ++segment) {
      Eigen::Vector3d a, b;
      for (int k = 0; k < 3; ++k) a[k] = UniformReal(rng, -1.0, 1.0);
      for (int k = 0; k < 3; ++k) b[k] = UniformReal(rng, -1.0, 1.0);
      for (int i = 0; i < 12; ++i) {
        const double t = UniformReal(rng, 0.0, 1.0);
        Eigen::Vector3d noise;
        for (int k = 0; k < 3; ++k) noise[k] = UniformReal(rng, -1e-13, 1e-13);
        points.push_back(a + t * (b - a) + noise);
      }
    }
    const TriangleMesh hull = ConvexHull3(points, 0.0);
    ASSERT_GT(MeshVolume(hull), 0.0);
    worst = std::max(worst, WorstViolation(HullPlanes(hull), points));
  }
  EXPECT_LE(worst, 1e-14);
}

}  // namespace
}  // namespace acdplan::acd
