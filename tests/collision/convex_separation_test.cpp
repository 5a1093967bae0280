#include "collision/internal/convex_separation.h"

#include <gtest/gtest.h>

#include <vector>

#include "acd/convex_hull3d.h"
#include "acd/triangle_mesh.h"
#include "base/random.h"

namespace acdplan::collision::internal {
namespace {

ConvexPolytope PolytopeOf(const acd::TriangleMesh& hull) {
  ConvexPolytope p;
  for (Eigen::Index i = 0; i < hull.vertices.rows(); ++i) {
    p.vertices.push_back(hull.vertices.row(i).transpose());
  }
  const auto planes = acd::HullPlanes(hull);
  for (Eigen::Index r = 0; r < planes.rows(); ++r) p.planes.push_back(planes.row(r));
  return p;
}

// Distance between two convex polytopes' vertex sets is not their distance, but a point of one
// inside the other (by the planes) proves overlap, and a separating plane proves the opposite:
// on random pairs, compare with a brute-force check on a dense sample of each polytope.
TEST(ConvexSeparation, NeverSeparatesOverlappingCubes) {
  const ConvexPolytope cube = PolytopeOf(acd::Cube(1.0));
  RandomEngine rng(11);
  int separated = 0, overlapping = 0;
  for (int i = 0; i < 20000; ++i) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    for (int k = 0; k < 3; ++k) pose.translation()[k] = UniformReal(rng, -1.8, 1.8);
    Eigen::Vector4d q;
    for (int k = 0; k < 4; ++k) q[k] = StandardNormal(rng);
    pose.linear() = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
    ConvexPolytope moved;
    cube.Transformed(pose, &moved);
    // A sample of the moved cube (grid points of its volume) inside the fixed one: overlap.
    bool overlap = false;
    for (int a = 0; a <= 8 && !overlap; ++a) {
      for (int b = 0; b <= 8 && !overlap; ++b) {
        for (int c = 0; c <= 8 && !overlap; ++c) {
          const Eigen::Vector3d p =
              pose * (Eigen::Vector3d(a, b, c) / 8.0 - Eigen::Vector3d::Constant(0.5));
          overlap = (p.array().abs() <= 0.5).all();
        }
      }
    }
    const bool apart = SeparatedByAFacePlane(moved, cube, 1e-12);
    if (overlap) {
      ++overlapping;
      EXPECT_FALSE(apart) << pose.matrix();
    }
    separated += apart;
  }
  EXPECT_GT(separated, 1000);
  EXPECT_GT(overlapping, 1000);
}

TEST(ConvexSeparation, TouchingFacesAreNotSeparated) {
  const ConvexPolytope cube = PolytopeOf(acd::Cube(1.0));
  ConvexPolytope moved;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() << 1.0, 0.3, 0.0;  // shares the face x = 0.5
  cube.Transformed(pose, &moved);
  EXPECT_FALSE(SeparatedByAFacePlane(moved, cube, 1e-12));
  EXPECT_FALSE(AVertexInside(moved, cube, 1e-12));  // on the face is not inside
  pose.translation() << 1.0 + 1e-9, 0.3, 0.0;
  cube.Transformed(pose, &moved);
  EXPECT_TRUE(SeparatedByAFacePlane(moved, cube, 1e-12));
}

TEST(ConvexSeparation, ACornerInsideIsFound) {
  const ConvexPolytope cube = PolytopeOf(acd::Cube(1.0));
  ConvexPolytope moved;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  pose.translation() << 0.9, 0.9, 0.9;  // the corner near (0.4, 0.4, 0.4) is inside
  cube.Transformed(pose, &moved);
  EXPECT_TRUE(AVertexInside(moved, cube, 1e-12));
  EXPECT_FALSE(SeparatedByAFacePlane(moved, cube, 1e-12));
}

}  // namespace
}  // namespace acdplan::collision::internal
