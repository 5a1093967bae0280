#include "collision/internal/outer_polytope.h"

#include <gtest/gtest.h>

#include <vector>

#include "acd/convex_hull3d.h"
#include "acd/mesh_measures.h"
#include "base/random.h"

namespace acdplan::collision::internal {
namespace {

// The hull of points on an ellipsoid: hundreds of faces, none of them large.
acd::TriangleMesh EllipsoidHull(int points, std::uint64_t seed) {
  RandomEngine rng(seed);
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < points; ++i) {
    Eigen::Vector3d g(StandardNormal(rng), StandardNormal(rng), StandardNormal(rng));
    p.push_back(g.normalized().cwiseProduct(Eigen::Vector3d(3, 1, 0.5)) +
                Eigen::Vector3d(10, -4, 2));
  }
  return acd::ConvexHull3(p, 0.0);
}

TEST(OuterPolytope, HasFewFacesAndContainsTheHull) {
  const acd::TriangleMesh hull = EllipsoidHull(2000, 3);
  ASSERT_GT(acd::HullPlanes(hull).rows(), 1000);
  for (const int max_planes : {8, 58}) {
    SCOPED_TRACE(max_planes);
    const acd::TriangleMesh outer = OuterPolytope(hull, acd::HullPlanes(hull), max_planes);
    const Eigen::Matrix<double, Eigen::Dynamic, 4> planes = acd::HullPlanes(outer);
    EXPECT_LE(planes.rows(), max_planes + 6);
    for (Eigen::Index v = 0; v < hull.vertices.rows(); ++v) {
      const Eigen::Vector3d p = hull.vertices.row(v).transpose();
      EXPECT_LE((planes.leftCols<3>() * p - planes.col(3)).maxCoeff(), 0.0) << v;
    }
    // Close around it: the more planes, the closer.
    const double ratio = acd::MeshVolume(outer) / acd::MeshVolume(hull);
    EXPECT_GE(ratio, 1.0);
    EXPECT_LE(ratio, max_planes == 8 ? 2.0 : 1.25) << ratio;
    EXPECT_EQ(OuterPolytope(hull, acd::HullPlanes(hull), max_planes).vertices,
              outer.vertices);  // deterministic
  }
}

TEST(OuterPolytope, AHullWithFewFacesIsKept) {
  const acd::TriangleMesh cube = acd::Cube(2.0);
  const acd::TriangleMesh outer = OuterPolytope(cube, acd::HullPlanes(cube), 8);
  EXPECT_EQ(outer.vertices, cube.vertices);
  EXPECT_EQ(outer.triangles, cube.triangles);
}

}  // namespace
}  // namespace acdplan::collision::internal
