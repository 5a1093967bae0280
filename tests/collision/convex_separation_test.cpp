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

// A uniform rotation (a normalised 4D Gaussian) and a translation in [-reach, reach]^3.
Eigen::Isometry3d RandomPose(RandomEngine& rng, double reach) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (int k = 0; k < 3; ++k) pose.translation()[k] = UniformReal(rng, -reach, reach);
  Eigen::Vector4d q;
  for (int k = 0; k < 4; ++k) q[k] = StandardNormal(rng);
  pose.linear() = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
  return pose;
}

// Distance between two convex polytopes' vertex sets is not their distance, but a point of one
// inside the other (by the planes) proves overlap, and a separating plane proves the opposite:
// on random pairs, compare with a brute-force check on a dense sample of each polytope.
TEST(ConvexSeparation, NeverSeparatesOverlappingCubes) {
  const ConvexPolytope cube = PolytopeOf(acd::Cube(1.0));
  RandomEngine rng(11);
  int separated = 0, overlapping = 0;
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Isometry3d pose = RandomPose(rng, 1.8);
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

// Whether `t` meets the cube [-0.5, 0.5]^3, by clipping it with the cube's six half-spaces
// (Sutherland-Hodgman): an independent reference for TouchesTriangle().
bool TriangleMeetsUnitCube(const Triangle3& t) {
  std::vector<Eigen::Vector3d> polygon(t.begin(), t.end());
  for (int k = 0; k < 3; ++k) {
    for (const double sign : {1.0, -1.0}) {
      std::vector<Eigen::Vector3d> clipped;
      for (size_t i = 0; i < polygon.size(); ++i) {
        const Eigen::Vector3d& a = polygon[i];
        const Eigen::Vector3d& b = polygon[(i + 1) % polygon.size()];
        const double da = sign * a[k] - 0.5, db = sign * b[k] - 0.5;  // <= 0: inside
        if (da <= 0) clipped.push_back(a);
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
          clipped.push_back(a + (b - a) * (da / (da - db)));
        }
      }
      polygon = clipped;
      if (polygon.empty()) return false;
    }
  }
  return true;
}

TEST(TouchesTriangle, AgreesWithClippingOnRandomTrianglesAndPoses) {
  const acd::TriangleMesh mesh = acd::Cube(1.0);
  const ConvexPolytope cube = PolytopeOf(mesh);
  const std::vector<Eigen::Vector3d> edges = EdgeDirections(mesh.vertices, mesh.triangles);
  RandomEngine rng(23);
  int touching = 0, apart = 0, apart_by_an_edge_axis_only = 0;
  for (int i = 0; i < 20000; ++i) {
    // A random triangle in the cube's frame, and the same pair moved by a random pose.
    Triangle3 t;
    const Eigen::Vector3d center(UniformReal(rng, -1, 1), UniformReal(rng, -1, 1),
                                 UniformReal(rng, -1, 1));
    const double size = UniformReal(rng, 0.05, 1.5);
    for (Eigen::Vector3d& corner : t) {
      corner = center + size * Eigen::Vector3d(UniformReal(rng, -1, 1), UniformReal(rng, -1, 1),
                                               UniformReal(rng, -1, 1));
    }
    const Eigen::Isometry3d pose = RandomPose(rng, 5);
    ConvexPolytope moved;
    cube.Transformed(pose, &moved);
    std::vector<Eigen::Vector3d> moved_edges;
    for (const Eigen::Vector3d& e : edges) moved_edges.push_back(pose.linear() * e);
    Triangle3 moved_t;
    for (size_t k = 0; k < 3; ++k) moved_t[k] = pose * t[k];

    const bool expected = TriangleMeetsUnitCube(t);
    EXPECT_EQ(TouchesTriangle(moved, moved_edges, moved_t), expected) << i;
    EXPECT_EQ(TouchesTriangle(cube, edges, t), expected) << i;
    touching += expected;
    apart += !expected;
    // Disjoint, yet no face axis of either separates: only an edge-edge axis can.
    if (!expected && TouchesTriangle(cube, {}, t)) ++apart_by_an_edge_axis_only;
  }
  EXPECT_GT(touching, 2000);
  EXPECT_GT(apart, 2000);
  EXPECT_GT(apart_by_an_edge_axis_only, 20);
}

TEST(TouchesTriangle, ContactsAtAPointAndTrianglesInsideCount) {
  const acd::TriangleMesh mesh = acd::Cube(1.0);
  const ConvexPolytope cube = PolytopeOf(mesh);
  const std::vector<Eigen::Vector3d> edges = EdgeDirections(mesh.vertices, mesh.triangles);
  // A corner on the face x = 0.5, the rest outside.
  EXPECT_TRUE(TouchesTriangle(cube, edges, {{{0.5, 0, 0}, {1, 0.2, 0}, {1, -0.2, 0.1}}}));
  EXPECT_FALSE(TouchesTriangle(cube, edges, {{{0.5 + 1e-9, 0, 0}, {1, 0.2, 0}, {1, -0.2, 0.1}}}));
  // Wholly inside: the polytope is solid.
  EXPECT_TRUE(TouchesTriangle(cube, edges, {{{0.1, 0, 0}, {0, 0.1, 0}, {0, 0, 0.1}}}));
  // A degenerate triangle (a segment) through the cube, and one beside it.
  EXPECT_TRUE(TouchesTriangle(cube, edges, {{{-1, 0, 0}, {1, 0, 0}, {0, 0, 0}}}));
  EXPECT_FALSE(TouchesTriangle(cube, edges, {{{-1, 0.7, 0}, {1, 0.7, 0}, {0, 0.7, 0}}}));
}

TEST(EdgeDirections, EachEdgeOfACubeOnce) {
  const acd::TriangleMesh mesh = acd::Cube(1.0);
  // 12 edges and 6 face diagonals (two triangles a face).
  EXPECT_EQ(EdgeDirections(mesh.vertices, mesh.triangles).size(), 18u);
}

}  // namespace
}  // namespace acdplan::collision::internal
