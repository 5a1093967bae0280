#include "envs/robot.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "test_util.h"

namespace acdplan::envs {
namespace {

using testing::ErrorOf;
using ::testing::HasSubstr;

TEST(RobotTest, ShapesAndBoundingRadius) {
  EXPECT_EQ(Robot::Point().shape, RobotShape::kPoint);
  EXPECT_EQ(Robot::Point().BoundingRadius(), 0.0);
  EXPECT_EQ(Robot::Disc(0.5).BoundingRadius(), 0.5);
  // Clockwise input is re-oriented.
  const Robot box = Robot::Polygon({{{-1, -1}, {-1, 1}, {2, 1}, {2, -1}}, {}});
  EXPECT_EQ(box.shape, RobotShape::kPolygon);
  EXPECT_GT(acd::SignedArea(box.polygon.outer), 0.0);
  EXPECT_DOUBLE_EQ(box.BoundingRadius(), std::sqrt(5.0));
  acd::TriangleMesh tri;
  tri.vertices.resize(3, 3);
  tri.vertices << 0, 0, 0, 3, 0, 0, 0, 4, 0;
  tri.triangles.resize(1, 3);
  tri.triangles << 0, 1, 2;
  EXPECT_DOUBLE_EQ(Robot::Mesh(tri).BoundingRadius(), 4.0);
  EXPECT_EQ(ToString(RobotShape::kMesh), "mesh");
}

TEST(RobotTest, Transformed) {
  const acd::Polygon2d square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}};
  const Eigen::Isometry2d pose = Eigen::Translation2d(5, 0) * Eigen::Rotation2Dd(M_PI / 2);
  const acd::Polygon2d moved = Transformed(square, pose);
  EXPECT_TRUE(moved.outer[1].isApprox(Eigen::Vector2d(5, 1)));
  acd::TriangleMesh tri;
  tri.vertices.resize(1, 3);
  tri.vertices << 1, 0, 0;
  const Eigen::Isometry3d pose3(Eigen::Translation3d(0, 0, 2));
  EXPECT_TRUE(Transformed(tri, pose3).vertices.row(0).isApprox(Eigen::RowVector3d(1, 0, 2)));
}

TEST(RobotTest, Errors) {
  EXPECT_THAT(ErrorOf([] { Robot::Disc(0); }),
              HasSubstr("Robot::Disc(): radius must be finite and > 0"));
  EXPECT_THAT(ErrorOf([] { Robot::Disc(NAN); }), HasSubstr("Robot::Disc()"));
  EXPECT_THAT(ErrorOf([] {
                Robot::Polygon({{{0, 0}, {2, 2}, {2, 0}, {0, 1}}, {}});
              }),
              HasSubstr("Robot::Polygon(): outer ring is not simple"));
  EXPECT_THAT(ErrorOf([] { Robot::Mesh(acd::TriangleMesh{}); }),
              HasSubstr("Robot::Mesh(): mesh has no triangles"));
}

}  // namespace
}  // namespace acdplan::envs
